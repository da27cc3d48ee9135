package org.tensim.io.mesh;

import java.io.IOException;
import java.nio.file.Path;

/**
 * The whitespace-separated tokens of a text mesh file, across lines, each with its line number, for formats whose
 * numbers may wrap (legacy VTK); errors name the file and the line of the last token read (package-private).
 */
final class TextTokens implements AutoCloseable {
    private final TextLines lines;
    private String[] tokens = new String[0];
    private int at;
    private int tokenLine;

    TextTokens(Path file) throws IOException {
        this.lines = new TextLines(file);
    }

    /** The next token, or null at the end of the file. */
    String next() throws IOException {
        while (at >= tokens.length) {
            String s = lines.next();
            if (s == null) {
                return null;
            }
            String t = s.trim();
            tokens = t.isEmpty() ? new String[0] : t.split("\\s+");
            at = 0;
        }
        tokenLine = lines.line();
        return tokens[at++];
    }

    /** The next token; at the end of the file an error saying that {@code what} was expected. */
    String need(String what) throws IOException, MeshFormatException {
        String s = next();
        if (s == null) {
            throw lines.error("end of file; expected " + what);
        }
        return s;
    }

    /** The rest of the current line as one string (header lines), or null at the end of the file. */
    String restOfLine() throws IOException {
        if (at < tokens.length) {
            String r = String.join(" ", java.util.Arrays.copyOfRange(tokens, at, tokens.length));
            at = tokens.length;
            return r;
        }
        String s = lines.next();
        tokenLine = lines.line();
        return s;
    }

    /** Line of the last token read. */
    int line() {
        return tokenLine;
    }

    MeshFormatException error(String problem) {
        return MeshFormatException.atLine(lines.file(), tokenLine, problem);
    }

    double number(String what) throws IOException, MeshFormatException {
        String t = need(what);
        double d;
        try {
            d = Double.parseDouble(t);
        } catch (NumberFormatException e) {
            throw error("'" + t + "' is not a number; expected " + what);
        }
        if (!Double.isFinite(d)) {
            throw error(what + " is " + t + "; expected a finite number");
        }
        return d;
    }

    int integer(String what) throws IOException, MeshFormatException {
        String t = need(what);
        try {
            return Integer.parseInt(t);
        } catch (NumberFormatException e) {
            throw error("'" + t + "' is not a whole number; expected " + what);
        }
    }

    @Override
    public void close() throws IOException {
        lines.close();
    }
}

package org.tensim.io.mesh;

import java.io.BufferedReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Line-by-line reading of a text mesh file with the current line number, and
 * number parsing whose errors name the file, the line and what was expected
 * (package-private, shared by the OBJ, OFF and ASCII STL readers).
 */
final class TextLines implements AutoCloseable {
    private final Path file;
    private final BufferedReader in;
    private int line;

    TextLines(Path file) throws IOException {
        this.file = file;
        this.in = Files.newBufferedReader(file, StandardCharsets.ISO_8859_1);
    }

    /** The next line, or null at the end of the file. */
    String next() throws IOException {
        String s = in.readLine();
        if (s != null) {
            line++;
        }
        return s;
    }

    int line() {
        return line;
    }

    Path file() {
        return file;
    }

    MeshFormatException error(String problem) {
        return MeshFormatException.atLine(file, line, problem);
    }

    /** Parses a finite decimal number; {@code what} says what the token should be. */
    double number(String token, String what) throws MeshFormatException {
        double d;
        try {
            d = Double.parseDouble(token);
        } catch (NumberFormatException e) {
            throw error("'" + token + "' is not a number; expected " + what);
        }
        if (!Double.isFinite(d)) {
            throw error(what + " is " + token + "; expected a finite number");
        }
        return d;
    }

    /** Parses a whole number. */
    int integer(String token, String what) throws MeshFormatException {
        try {
            return Integer.parseInt(token);
        } catch (NumberFormatException e) {
            throw error("'" + token + "' is not a whole number; expected " + what);
        }
    }

    @Override
    public void close() throws IOException {
        in.close();
    }
}

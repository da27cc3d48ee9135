package org.tensim.io;

import java.io.BufferedWriter;
import java.io.Closeable;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * Writes a CSV file row by row (comma-separated, '.' decimal point, header
 * first). Rows are flushed every {@code flushEvery} rows and on close, so that a
 * run that stops early leaves a readable file with every complete row so far.
 */
public final class CsvWriter implements Closeable {
    private final Path path;
    private final BufferedWriter out;
    private final int columns;
    private final int flushEvery;
    private final StringBuilder line = new StringBuilder(256);
    private long rows;

    /**
     * Creates the file (and its parent folders) and writes the header.
     *
     * @param flushEvery rows between flushes (>= 1)
     */
    public CsvWriter(Path path, List<String> header, int flushEvery) throws IOException {
        this.path = path;
        if (path.toAbsolutePath().getParent() != null) {
            Files.createDirectories(path.toAbsolutePath().getParent());
        }
        this.out = Files.newBufferedWriter(path, StandardCharsets.UTF_8);
        this.columns = header.size();
        this.flushEvery = Math.max(1, flushEvery);
        out.write(String.join(",", header));
        out.write('\n');
        out.flush();
    }

    public Path path() {
        return path;
    }

    /** Rows written so far (header excluded). */
    public long rows() {
        return rows;
    }

    /** Writes one row; its length must match the header's. */
    public void row(double... values) throws IOException {
        if (values.length != columns) {
            throw new IllegalArgumentException("CSV row for " + path + " has " + values.length
                    + " values, expected " + columns + " (one per header column)");
        }
        line.setLength(0);
        for (int i = 0; i < values.length; i++) {
            if (i > 0) {
                line.append(',');
            }
            line.append(values[i]);
        }
        line.append('\n');
        out.write(line.toString());
        if (++rows % flushEvery == 0) {
            out.flush();
        }
    }

    /**
     * Writes one row of already formatted cells (names, numbers); its length must
     * match the header's. Cells must not contain commas or line breaks.
     */
    public void rowText(String... cells) throws IOException {
        if (cells.length != columns) {
            throw new IllegalArgumentException("CSV row for " + path + " has " + cells.length
                    + " values, expected " + columns + " (one per header column)");
        }
        for (String c : cells) {
            if (c.indexOf(',') >= 0 || c.indexOf('\n') >= 0) {
                throw new IllegalArgumentException("CSV cell for " + path + " contains a comma or line break: '"
                        + c + "'");
            }
        }
        out.write(String.join(",", cells));
        out.write('\n');
        if (++rows % flushEvery == 0) {
            out.flush();
        }
    }

    @Override
    public void close() throws IOException {
        out.close();
    }
}

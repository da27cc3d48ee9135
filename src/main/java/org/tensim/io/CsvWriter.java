package org.tensim.io;

import java.io.Closeable;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;

/**
 * Writes a CSV file row by row (comma-separated, '.' decimal point, header
 * first). Rows are kept in memory and handed to the file system whole, every
 * {@code flushEvery} rows and on close: each write ends at the end of a row, so a
 * run stopped at any moment (even killed) leaves a file that ends on a complete
 * row. The file is created through {@link OutputFiles#create} (no symbolic link
 * followed, mode 0644). Thread-safe: a signal handler may {@link #close} it while
 * the run writes, and then gets the last whole row.
 */
public final class CsvWriter implements Closeable {
    private final Path path;
    private final FileChannel out;
    private final int columns;
    private final int flushEvery;
    private final StringBuilder pending = new StringBuilder(1 << 16);
    private long rows;
    private boolean closed;

    /**
     * Creates the file (and its parent folders) and writes the header.
     *
     * @param flushEvery rows between writes to the file (>= 1)
     */
    public CsvWriter(Path path, List<String> header, int flushEvery) throws IOException {
        this.path = path;
        this.out = OutputFiles.create(path);
        this.columns = header.size();
        this.flushEvery = Math.max(1, flushEvery);
        pending.append(String.join(",", header)).append('\n');
        flush();
    }

    public Path path() {
        return path;
    }

    /** Rows written so far (header excluded). */
    public synchronized long rows() {
        return rows;
    }

    /** Writes one row; its length must match the header's. */
    public synchronized void row(double... values) throws IOException {
        if (values.length != columns) {
            throw new IllegalArgumentException("CSV row for " + path + " has " + values.length
                    + " values, expected " + columns + " (one per header column)");
        }
        ensureOpen();
        for (int i = 0; i < values.length; i++) {
            if (i > 0) {
                pending.append(',');
            }
            pending.append(values[i]);
        }
        endRow();
    }

    /**
     * Writes one row of already formatted cells (names, numbers); its length must
     * match the header's. Cells must not contain commas or line breaks.
     */
    public synchronized void rowText(String... cells) throws IOException {
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
        ensureOpen();
        pending.append(String.join(",", cells));
        endRow();
    }

    private void endRow() throws IOException {
        pending.append('\n');
        if (++rows % flushEvery == 0) {
            flush();
        }
    }

    private void ensureOpen() throws IOException {
        if (closed) {
            throw new IOException("CSV file " + path + " is closed (the run was interrupted)");
        }
    }

    /** Hands every complete row kept so far to the file system. */
    public synchronized void flush() throws IOException {
        if (pending.length() == 0 || closed) {
            return;
        }
        ByteBuffer b = ByteBuffer.wrap(pending.toString().getBytes(StandardCharsets.UTF_8));
        pending.setLength(0);
        try {
            while (b.hasRemaining()) {
                out.write(b);
            }
        } catch (IOException e) {
            throw OutputFiles.describe("write", path, e);
        }
    }

    /** Writes the rows kept and closes the file; closing twice does nothing. */
    @Override
    public synchronized void close() throws IOException {
        if (closed) {
            return;
        }
        try {
            flush();
        } finally {
            closed = true;
            out.close();
        }
    }
}

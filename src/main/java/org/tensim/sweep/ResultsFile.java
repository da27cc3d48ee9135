package org.tensim.sweep;

import com.fasterxml.jackson.databind.MappingIterator;
import com.fasterxml.jackson.dataformat.csv.CsvGenerator;
import com.fasterxml.jackson.dataformat.csv.CsvMapper;
import com.fasterxml.jackson.dataformat.csv.CsvParser;
import com.fasterxml.jackson.dataformat.csv.CsvSchema;
import java.io.Closeable;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The sweep's results CSV: one row per finished point, appended as points finish.
 * Columns: {@code point}, the swept parameters, {@code status}, {@code message},
 * {@code wall_s}, {@code cpu_s}, then the outputs. Numbers are written with {@link Double#toString},
 * which reads back to the same bits; a field the run did not produce is left empty.
 *
 * <p>Durability: each row is written with one {@code write} call and forced to the disk
 * before the next point is recorded, so a killed sweep loses no finished point. A row
 * cut short by a power loss (no final line break) is dropped when the file is opened
 * again, and that point runs again.
 */
public final class ResultsFile implements Closeable {
    private static final CsvMapper CSV = new CsvMapper();
    private final Path path;
    private final List<String> header;
    private final List<String> parameters;
    private final List<String> outputs;
    private final FileChannel channel;
    private final Map<Integer, PointResult> done = new LinkedHashMap<>();

    /**
     * Opens (or creates) the file; an existing file must have the same header, and its rows are
     * read back as finished points.
     *
     * @throws IllegalArgumentException when the existing file was written by another spec
     */
    public ResultsFile(Path path, List<String> parameters, List<String> outputs) throws IOException {
        this.path = path;
        this.parameters = List.copyOf(parameters);
        this.outputs = List.copyOf(outputs);
        List<String> h = new ArrayList<>();
        h.add("point");
        h.addAll(parameters);
        h.addAll(List.of("status", "message", "wall_s", "cpu_s"));
        h.addAll(outputs);
        this.header = List.copyOf(h);
        boolean fresh = !Files.exists(path) || Files.size(path) == 0;
        if (!fresh) {
            readExisting();
        }
        channel = FileChannel.open(path, StandardOpenOption.CREATE, StandardOpenOption.WRITE,
                StandardOpenOption.APPEND);
        if (fresh) {
            append(header);
        }
    }

    public Path path() {
        return path;
    }

    /** Points already finished (read from an existing file, then those appended), by id. */
    public Map<Integer, PointResult> done() {
        return done;
    }

    /** Appends one result as a whole row and forces it to the disk. */
    public void write(PointResult r) throws IOException {
        List<String> cells = new ArrayList<>(header.size());
        cells.add(Integer.toString(r.id()));
        for (double v : r.values()) {
            cells.add(Double.toString(v));
        }
        cells.add(r.status());
        cells.add(r.message().replace('\n', ' ').replace('\r', ' '));
        cells.add(Double.toString(r.wallS()));
        cells.add(Double.toString(r.cpuS()));
        for (String o : outputs) {
            double v = r.field(o);
            cells.add(Double.isNaN(v) ? "" : Double.toString(v));
        }
        append(cells);
        done.put(r.id(), r);
    }

    private void append(List<String> cells) throws IOException {
        String line = CSV.writer(CsvSchema.emptySchema()).with(CsvGenerator.Feature.STRICT_CHECK_FOR_QUOTING)
                .writeValueAsString(cells);
        ByteBuffer b = ByteBuffer.wrap(line.getBytes(StandardCharsets.UTF_8));
        while (b.hasRemaining()) {
            channel.write(b);
        }
        channel.force(false);
    }

    private void readExisting() throws IOException {
        byte[] bytes = Files.readAllBytes(path);
        int end = bytes.length;
        while (end > 0 && bytes[end - 1] != '\n') {
            end--; // a row cut short: drop it
        }
        if (end < bytes.length) {
            try (FileChannel c = FileChannel.open(path, StandardOpenOption.WRITE)) {
                c.truncate(end);
            }
        }
        String text = new String(bytes, 0, end, StandardCharsets.UTF_8);
        List<List<String>> rows = new ArrayList<>();
        try (MappingIterator<String[]> it = CSV.readerFor(String[].class).with(CsvParser.Feature.WRAP_AS_ARRAY)
                .readValues(text)) {
            while (it.hasNext()) {
                rows.add(List.of(it.next()));
            }
        }
        if (rows.isEmpty() || !rows.get(0).equals(header)) {
            throw new IllegalArgumentException(path + " exists with another header (another spec wrote it): found "
                    + (rows.isEmpty() ? "nothing" : rows.get(0)) + ", expected " + header
                    + "; give another --out or remove the file");
        }
        for (int i = 1; i < rows.size(); i++) {
            List<String> c = rows.get(i);
            String where = path + " line " + (i + 1);
            if (c.size() != header.size()) {
                throw new IllegalArgumentException(where + ": " + c.size() + " cells, expected " + header.size());
            }
            try {
                int id = Integer.parseInt(c.get(0));
                double[] values = new double[parameters.size()];
                for (int p = 0; p < values.length; p++) {
                    values[p] = Double.parseDouble(c.get(1 + p));
                }
                int k = 1 + values.length;
                Map<String, Double> fields = new LinkedHashMap<>();
                for (int o = 0; o < outputs.size(); o++) {
                    String cell = c.get(k + 4 + o);
                    if (!cell.isEmpty()) {
                        fields.put(outputs.get(o), Double.parseDouble(cell));
                    }
                }
                done.put(id, new PointResult(id, values, c.get(k), c.get(k + 1), fields,
                        Double.parseDouble(c.get(k + 2)), Double.parseDouble(c.get(k + 3))));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(where + ": not a number (" + e.getMessage() + ")", e);
            }
        }
    }

    @Override
    public void close() throws IOException {
        channel.close();
    }
}

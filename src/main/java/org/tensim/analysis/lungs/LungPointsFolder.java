package org.tensim.analysis.lungs;

import com.fasterxml.jackson.databind.MappingIterator;
import com.fasterxml.jackson.dataformat.csv.CsvMapper;
import com.fasterxml.jackson.dataformat.csv.CsvParser;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.io.CsvWriter;
import org.tensim.io.Json;
import org.tensim.io.RunFolder;
import org.tensim.io.landmarks.LandmarkFormatException;
import org.tensim.io.mesh.VtkSeriesWriter;

/**
 * A {@link ModelMotion} in a run folder (docs/lungs.md, "tensim validate-4dct"):
 * <ul>
 * <li>{@value #CSV}: header {@code t_s,point,lung,x_mm,y_mm,z_mm}, one row per point per sampled instant, the
 * instants in time order and at each the points 0, 1, ... in order;</li>
 * <li>the folder's {@code summary.json} key {@value #KEY}: {@code {end_exhale_s, end_inhale_s, period_s,
 * superior: [x, y, z]}} and, when the run gives it, {@code law}: the breathing law's value at each instant;</li>
 * <li>{@value #VTK}/: the points at each instant as a legacy VTK series with its {@code .pvd} (ParaView), the
 * displacement from end-exhale as point vectors, the lung as a label (0 right, 1 left).</li>
 * </ul>
 * A malformed row is refused with the file, the line and what was expected.
 */
public final class LungPointsFolder {
    /** The points' trajectories. */
    public static final String CSV = "lung-points.csv";
    /** The VTK points series. */
    public static final String VTK = "lung-points";
    /** The summary's key. */
    public static final String KEY = "lung_points";
    /** The CSV's header. */
    public static final List<String> HEADER = List.of("t_s", "point", "lung", "x_mm", "y_mm", "z_mm");

    private LungPointsFolder() {
    }

    /**
     * Writes {@value #CSV} and the {@value #VTK}/ series into {@code run} and returns the summary's {@value #KEY}
     * value, for the caller to put into its {@link RunFolder#finish} fields.
     */
    public static Map<String, Object> write(RunFolder run, ModelMotion m) throws IOException {
        CsvWriter w = run.csv(CSV, HEADER, 1000);
        int n = m.points();
        for (int k = 0; k < m.timesS().length; k++) {
            double[] x = m.positionsM()[k];
            String t = Double.toString(m.timesS()[k]);
            for (int i = 0; i < n; i++) {
                w.rowText(t, Integer.toString(i), m.lung()[i], Double.toString(x[3 * i] * 1e3),
                        Double.toString(x[3 * i + 1] * 1e3), Double.toString(x[3 * i + 2] * 1e3));
            }
        }
        w.close();
        int[] labels = new int[n];
        for (int i = 0; i < n; i++) {
            labels[i] = ModelMotion.LUNGS.indexOf(m.lung()[i]);
        }
        VtkSeriesWriter vtk = VtkSeriesWriter.points(run.file(VTK), VTK, labels, "lung_right0_left1");
        double[] exhale = m.positionsAt(m.endExhaleS());
        for (int k = 0; k < m.timesS().length; k++) {
            vtk.frame(m.timesS()[k], m.positionsM()[k], exhale);
        }
        Map<String, Object> key = new LinkedHashMap<>();
        key.put("end_exhale_s", m.endExhaleS());
        key.put("end_inhale_s", m.endInhaleS());
        key.put("period_s", m.periodS());
        key.put("superior", m.superior());
        if (m.law() != null) {
            key.put("law", m.law());
        }
        return key;
    }

    /**
     * Reads the motion of run folder {@code dir}.
     *
     * @throws IllegalArgumentException when the folder has no {@value #CSV} or its summary no {@value #KEY}
     * @throws LandmarkFormatException  naming the file and line of a malformed row or summary value
     */
    public static ModelMotion read(Path dir) throws IOException, LandmarkFormatException {
        Path csv = dir.resolve(CSV);
        Path summary = dir.resolve(RunFolder.SUMMARY);
        if (!Files.isRegularFile(csv)) {
            throw new IllegalArgumentException(dir + " has no " + CSV + ": expected the folder of a run of the lungs"
                    + " that writes its points' trajectories there (docs/lungs.md)");
        }
        if (!Files.isRegularFile(summary)) {
            throw new IllegalArgumentException(dir + " has no " + RunFolder.SUMMARY + " (the run did not finish):"
                    + " expected its " + KEY + " with end_exhale_s, end_inhale_s, period_s and superior");
        }
        Map<String, Object> all;
        try {
            all = Json.readMap(summary);
        } catch (IOException e) {
            throw new LandmarkFormatException(summary, 0, "not readable as JSON (" + e.getMessage() + ")");
        }
        if (!(all.get(KEY) instanceof Map<?, ?> key)) {
            throw new IllegalArgumentException(summary + " has no " + KEY + ": expected the summary of a run of the"
                    + " lungs, with " + KEY + ": {end_exhale_s, end_inhale_s, period_s, superior}");
        }
        double ee = number(summary, key, "end_exhale_s");
        double ei = number(summary, key, "end_inhale_s");
        double period = number(summary, key, "period_s");
        double[] up = numbers(summary, key.get("superior"), "superior");
        double[] law = key.get("law") == null ? null : numbers(summary, key.get("law"), "law");
        Rows rows = rows(csv);
        try {
            return new ModelMotion(rows.times, rows.positions, rows.lung, ee, ei, period, up, law);
        } catch (IllegalArgumentException e) {
            throw new LandmarkFormatException(summary, 0, KEY + " does not fit " + CSV + ": " + e.getMessage());
        }
    }

    private record Rows(double[] times, double[][] positions, String[] lung) {
    }

    private static Rows rows(Path csv) throws IOException, LandmarkFormatException {
        CsvMapper m = new CsvMapper();
        m.enable(CsvParser.Feature.WRAP_AS_ARRAY);
        m.enable(CsvParser.Feature.SKIP_EMPTY_LINES);
        List<Double> times = new ArrayList<>();
        List<double[]> frames = new ArrayList<>();
        List<String> lung = new ArrayList<>();
        double[] frame = null;
        int count = 0; // points read at the current instant
        int line = 0;
        boolean header = false;
        try (MappingIterator<String[]> it = m.readerFor(String[].class).readValues(csv.toFile())) {
            while (it.hasNext()) {
                String[] row = it.next();
                line = it.getParser().currentTokenLocation().getLineNr();
                if (!header) {
                    if (!List.of(row).equals(HEADER)) {
                        throw new LandmarkFormatException(csv, line, "the header is " + String.join(",", row)
                                + "; expected " + String.join(",", HEADER));
                    }
                    header = true;
                    continue;
                }
                if (row.length != HEADER.size()) {
                    throw new LandmarkFormatException(csv, line, "a row of " + row.length + " fields; expected "
                            + HEADER.size() + " (" + String.join(",", HEADER) + ")");
                }
                double t = finite(csv, line, row[0], "t_s", "a time in s");
                int point = point(csv, line, row[1]);
                if (point == 0) {
                    if (!times.isEmpty()) {
                        double before = times.get(times.size() - 1);
                        if (!(t > before)) {
                            throw new LandmarkFormatException(csv, line, "t_s " + row[0] + " starts an instant at"
                                    + " or before the last one (" + before + " s); expected instants in time order");
                        }
                        if (count != lung.size()) {
                            throw new LandmarkFormatException(csv, line, "the instant t = " + before + " s has "
                                    + count + " points; expected " + lung.size() + ", as the first instant");
                        }
                    }
                    times.add(t);
                    frame = new double[3 * Math.max(lung.size(), 16)];
                    frames.add(frame);
                    count = 0;
                } else if (frame == null || t != times.get(times.size() - 1)) {
                    throw new LandmarkFormatException(csv, line, "point " + point + " at t_s " + row[0] + "; expected"
                            + " point 0 to start each instant, and the instant's points at its time");
                }
                if (point != count) {
                    throw new LandmarkFormatException(csv, line, "point " + point + "; expected point " + count
                            + " (each instant's points 0, 1, ... in order)");
                }
                String side = row[2].trim();
                if (!ModelMotion.LUNGS.contains(side)) {
                    throw new LandmarkFormatException(csv, line, "lung '" + row[2] + "'; expected right or left");
                }
                if (frames.size() == 1) {
                    lung.add(side);
                } else if (count >= lung.size() || !lung.get(count).equals(side)) {
                    throw new LandmarkFormatException(csv, line, "point " + point + (count >= lung.size()
                            ? " is not at the first instant" : " is in lung " + side + ", at the first instant in "
                            + lung.get(count)) + "; expected the same points at every instant");
                }
                if (3 * count + 3 > frame.length) {
                    frame = java.util.Arrays.copyOf(frame, 2 * frame.length);
                    frames.set(frames.size() - 1, frame);
                }
                for (int a = 0; a < 3; a++) {
                    frame[3 * count + a] = finite(csv, line, row[3 + a], HEADER.get(3 + a), "a coordinate in mm")
                            * 1e-3;
                }
                count++;
            }
        } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
            throw new LandmarkFormatException(csv, e.getLocation() == null ? line : e.getLocation().getLineNr(),
                    "not readable as CSV (" + e.getOriginalMessage() + ")");
        }
        if (times.size() < 2) {
            throw new LandmarkFormatException(csv, 0, times.size() + " sampled instants; expected rows of "
                    + String.join(",", HEADER) + " at 2 instants or more, over a whole cycle");
        }
        if (count != lung.size()) {
            throw new LandmarkFormatException(csv, line, "the last instant has " + count + " points; expected "
                    + lung.size() + ", as the first instant");
        }
        double[][] pos = new double[frames.size()][];
        for (int k = 0; k < pos.length; k++) {
            pos[k] = java.util.Arrays.copyOf(frames.get(k), 3 * lung.size());
        }
        return new Rows(times.stream().mapToDouble(Double::doubleValue).toArray(), pos, lung.toArray(new String[0]));
    }

    private static int point(Path csv, int line, String token) throws LandmarkFormatException {
        try {
            int p = Integer.parseInt(token.trim());
            if (p >= 0) {
                return p;
            }
        } catch (NumberFormatException e) {
            // refused below
        }
        throw new LandmarkFormatException(csv, line, "point '" + token + "'; expected the point's number, a whole"
                + " number from 0");
    }

    private static double finite(Path csv, int line, String token, String column, String what)
            throws LandmarkFormatException {
        double d;
        try {
            d = Double.parseDouble(token.trim());
        } catch (NumberFormatException e) {
            throw new LandmarkFormatException(csv, line, column + " is '" + token + "', not a number; expected "
                    + what);
        }
        if (!Double.isFinite(d)) {
            throw new LandmarkFormatException(csv, line, column + " is " + token + "; expected " + what
                    + ", finite");
        }
        return d;
    }

    private static double number(Path summary, Map<?, ?> key, String name) throws LandmarkFormatException {
        if (key.get(name) instanceof Number v && Double.isFinite(v.doubleValue())) {
            return v.doubleValue();
        }
        throw new LandmarkFormatException(summary, 0, KEY + "." + name + " is " + key.get(name) + "; expected a"
                + " time in s");
    }

    private static double[] numbers(Path summary, Object v, String name) throws LandmarkFormatException {
        if (v instanceof List<?> list) {
            double[] out = new double[list.size()];
            for (int i = 0; i < out.length; i++) {
                if (!(list.get(i) instanceof Number x) || !Double.isFinite(x.doubleValue())) {
                    throw new LandmarkFormatException(summary, 0, KEY + "." + name + "[" + i + "] is " + list.get(i)
                            + "; expected a finite number");
                }
                out[i] = ((Number) list.get(i)).doubleValue();
            }
            return out;
        }
        throw new LandmarkFormatException(summary, 0, KEY + "." + name + " is " + v + "; expected an array of"
                + " numbers");
    }
}

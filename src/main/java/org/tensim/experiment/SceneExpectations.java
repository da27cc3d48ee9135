package org.tensim.experiment;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.scene.file.SceneExpectation;

/**
 * Evaluates a scene's {@code expect:} checks ({@link SceneExpectation}) on what its run wrote: a column's
 * statistic over the CSV's rows ({@link Columns}) or a number of the summary.
 */
public final class SceneExpectations {
    private SceneExpectations() {
    }

    /** Each CSV column's minimum, maximum, last value and mean over the rows written. */
    public static final class Columns {
        private final List<String> header;
        private final double[] min;
        private final double[] max;
        private final double[] sum;
        private final double[] last;
        private long rows;

        public Columns(List<String> header) {
            this.header = List.copyOf(header);
            int n = header.size();
            min = new double[n];
            max = new double[n];
            sum = new double[n];
            last = new double[n];
            Arrays.fill(min, Double.POSITIVE_INFINITY);
            Arrays.fill(max, Double.NEGATIVE_INFINITY);
            Arrays.fill(last, Double.NaN);
        }

        /** Adds one row (as written to the CSV). */
        public void add(double[] row) {
            for (int i = 0; i < row.length; i++) {
                min[i] = Math.min(min[i], row[i]);
                max[i] = Math.max(max[i], row[i]);
                sum[i] += row[i];
                last[i] = row[i];
            }
            rows++;
        }

        public double min(int column) {
            return min[column];
        }

        public double max(int column) {
            return max[column];
        }

        /**
         * A column's statistic: min, max, final (the last row's) or mean (of the rows); NaN before any row (a
         * non-finite value in a row makes min, max and mean non-finite too, as NaN propagates).
         */
        public double value(String column, String stat) {
            int i = header.indexOf(column);
            if (i < 0) {
                throw new IllegalArgumentException("no column " + column + " in " + header);
            }
            if (rows == 0) {
                return Double.NaN;
            }
            switch (stat) {
                case "min":
                    return min[i];
                case "max":
                    return max[i];
                case "final":
                    return last[i];
                case "mean":
                    return sum[i] / rows;
                default:
                    throw new IllegalArgumentException("unknown statistic " + stat);
            }
        }
    }

    /**
     * Each check's outcome for summary.json, in order: {@code check} (what it reads), {@code measured} (in
     * {@code unit}; "none" when the run gave no value), {@code low}, {@code high}, {@code expected} (as the file
     * states it), {@code pass} and {@code at} (the check's place in the file).
     *
     * @param summary the run's summary fields, in which summary keys ({@code a.b.c}) are looked up
     */
    public static List<Map<String, Object>> evaluate(List<SceneExpectation> checks, Columns columns,
            Map<String, Object> summary) {
        List<Map<String, Object>> out = new ArrayList<>();
        for (SceneExpectation e : checks) {
            double measured = e.source().equals("column") ? columns.value(e.key(), e.stat()) : lookUp(summary,
                    e.key());
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("check", e.label());
            m.put("measured", Double.isFinite(measured) ? (Object) measured : "none");
            m.put("unit", e.unit());
            m.put("low", e.low());
            m.put("high", e.high());
            m.put("expected", e.stated());
            m.put("pass", e.holds(measured));
            m.put("at", e.where());
            out.add(m);
        }
        return out;
    }

    /** How many of the outcomes failed. */
    public static long failed(List<Map<String, Object>> outcomes) {
        return outcomes.stream().filter(m -> !Boolean.TRUE.equals(m.get("pass"))).count();
    }

    /** One line per outcome, e.g. {@code pass: mss_dy_m min = -8.0444 m, in [-8.1204, -7.9596] m (...)}. */
    public static String line(SceneExpectation e, Map<String, Object> outcome) {
        Object v = outcome.get("measured");
        String measured = v instanceof Double d ? String.format(java.util.Locale.ROOT, "%.6g", d) : v.toString();
        return (Boolean.TRUE.equals(outcome.get("pass")) ? "pass" : "FAIL") + ": " + e.label() + " = " + measured
                + (e.unit().isEmpty() ? "" : " " + e.unit()) + ", expected " + e.range() + " at " + e.where();
    }

    /** A number at a dotted key path of the summary, NaN when it is absent or not a number. */
    static double lookUp(Map<String, Object> summary, String path) {
        Object v = summary;
        for (String part : splitPath(path)) {
            if (!(v instanceof Map<?, ?> m)) {
                return Double.NaN;
            }
            v = m.get(part);
        }
        return v instanceof Number n ? n.doubleValue() : Double.NaN;
    }

    /**
     * A key path's parts. A column's name may itself hold no dot, but a path {@code columns.C.min} is split at its
     * first and last dots so that the column's name is one part whatever it holds.
     */
    private static List<String> splitPath(String path) {
        int first = path.indexOf('.');
        int lastDot = path.lastIndexOf('.');
        if (path.startsWith("columns.") && lastDot > first) {
            return List.of("columns", path.substring(first + 1, lastDot), path.substring(lastDot + 1));
        }
        return first < 0 ? List.of(path) : List.of(path.substring(0, first), path.substring(first + 1));
    }
}

package org.tensim.scene.file;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import javax.measure.Unit;
import tech.units.indriya.AbstractUnit;
import tech.units.indriya.format.SimpleUnitFormat;

/**
 * One check of a scene's {@code expect:} block: what a run must show. It reads either a CSV column's statistic
 * over the rows the run writes ({@code {column: mss_dy_m, stat: min, ...}}) or a number of the run's summary
 * ({@code {summary: steps, ...}}), and holds when that value lies in {@code [low, high]}, given as
 * {@code between: [a, b]} or as {@code value: v, tolerance: t} (absolute, {@code [v - t, v + t]}, or relative,
 * {@code tolerance: 2 %}: {@code [v - |v| t, v + |v| t]}). Values may carry units of the column's dimension; bare
 * numbers take the file's {@code units:}. The block is read by {@link ExpectBlock}.
 *
 * @param source "column" or "summary"
 * @param key    the column's name, or the summary's key path (e.g. {@code body_nodes.mss})
 * @param stat   min, max, final or mean for a column; "value" for a summary key
 * @param unit   the unit of the value and of low and high, as written in the column's name ("" for counts)
 * @param low    the least value that holds, in {@code unit}
 * @param high   the greatest value that holds, in {@code unit}
 * @param stated the range as the file states it, for messages, e.g. {@code -8.04 m ± 1 %}
 * @param where  {@code file:line:column: expect[i]}, the check's place in the file
 */
public record SceneExpectation(String source, String key, String stat, String unit, double low, double high,
        String stated, String where) {
    /** The statistics of a column, over the CSV's rows (t = 0 and every {@code run.every}-th step). */
    public static final List<String> STATS = List.of("min", "max", "final", "mean");

    /** Whether a measured value (in {@link #unit}) holds; NaN never does. */
    public boolean holds(double measured) {
        return measured >= low && measured <= high;
    }

    /** What is checked, e.g. {@code mss_dy_m min} or {@code summary steps}. */
    public String label() {
        return source.equals("column") ? key + " " + stat : "summary " + key;
    }

    /** The range in words, e.g. {@code in [-8.12, -7.96] m (-8.04 m ± 1 %)}. */
    public String range() {
        return String.format(Locale.ROOT, "in [%.6g, %.6g]%s (%s)", low, high, unit.isEmpty() ? "" : " " + unit,
                stated);
    }

    /**
     * The numbers of a scene's summary an expectation may name, each with its unit as written in its name:
     * {@code dt_s}, {@code duration_s}, {@code steps}, {@code body_nodes.NAME} and {@code columns.COLUMN.min} /
     * {@code .max} (the same columns' extremes as the CSV's). {@code org.tensim.experiment.SceneRunner} writes
     * each of them (tested).
     */
    public static Map<String, String> summaryKeys(Iterable<String> bodies, List<String> columns) {
        Map<String, String> m = new LinkedHashMap<>();
        m.put("dt_s", "s");
        m.put("duration_s", "s");
        m.put("steps", "");
        for (String b : bodies) {
            m.put("body_nodes." + b, "");
        }
        for (String c : columns) {
            if (!c.equals(TIME_COLUMN)) {
                m.put("columns." + c + ".min", columnUnit(c));
                m.put("columns." + c + ".max", columnUnit(c));
            }
        }
        return m;
    }

    /** The CSV's time column, first of every run's CSV. */
    public static final String TIME_COLUMN = "t_s";

    /** The CSV columns of a scene's run: the time, then every probe's columns. */
    public static List<String> columns(List<SceneProbe> probes) {
        List<String> c = new ArrayList<>(List.of(TIME_COLUMN));
        for (SceneProbe p : probes) {
            c.addAll(p.columns());
        }
        return c;
    }

    /** The unit a column's name ends with ({@code mss_dx_m}: m, {@code t_s}: s), "" when it names none. */
    public static String columnUnit(String column) {
        int u = column.lastIndexOf('_');
        if (u < 0) {
            return "";
        }
        String symbol = column.substring(u + 1);
        return parse(symbol) == null ? "" : symbol;
    }

    /** The unit of a symbol ("" is one), or null when indriya does not read it. */
    static Unit<?> parse(String symbol) {
        if (symbol.isEmpty()) {
            return AbstractUnit.ONE;
        }
        try {
            return SimpleUnitFormat.getInstance().parse(symbol);
        } catch (RuntimeException e) {
            return null;
        }
    }
}

package org.tensim.sweep;

import java.io.Serializable;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The outcome of one point of a sweep.
 *
 * @param id      the point's number in the sweep (0-based, fixed by the spec)
 * @param values  the swept parameters' values, in the spec's order
 * @param status  {@link #OK}, {@link #DIVERGED} or {@link #REFUSED}
 * @param message why it diverged or was refused; empty when ok
 * @param fields  summary fields (name to value; units in the names); those measured before a divergence
 *                are kept
 * @param wallS   wall time of the run, s (scene building included)
 * @param cpuS    CPU time of the thread that ran it, s (NaN where the JVM cannot tell); on a shared machine
 *                wallS - cpuS is the time the run waited for a core
 */
public record PointResult(int id, double[] values, String status, String message, Map<String, Double> fields,
        double wallS, double cpuS) implements Serializable {
    private static final long serialVersionUID = 1L;
    public static final String OK = "ok";
    public static final String DIVERGED = "diverged";
    public static final String REFUSED = "refused";

    public PointResult {
        values = values.clone();
        fields = Collections.unmodifiableMap(new LinkedHashMap<>(fields));
        message = message == null ? "" : message;
    }

    public boolean ok() {
        return OK.equals(status);
    }

    /** A field's value, NaN when the run did not produce it. */
    public double field(String name) {
        Double v = fields.get(name);
        return v == null ? Double.NaN : v;
    }
}

package org.tensim.scene.file;

import java.util.List;
import org.tensim.solver.integrators.Integrators;

/**
 * A scene's {@code run:} block: {@code integrator} (a name of {@link Integrators}, default rk2), {@code dt}
 * (time step, required; {@code auto} for the step a body's own time-step policy recommends, which only bodies whose
 * type {@link BodyType#choosesStep() chooses its step} take, and which is then 0 here), {@code duration} (simulated time, required), {@code csv} (the probes' file,
 * default probes.csv) and {@code every} (a CSV row every that many steps, default 1).
 *
 * @param dtS       s
 * @param durationS s
 */
public record RunSettings(String integrator, double dtS, double durationS, String csv, long every) {
    /** The value of {@code dt} that leaves the step to the body ({@link BodyType#choosesStep()}). */
    public static final String AUTO = "auto";
    /** The keys of the block. */
    public static final List<String> KEYS = List.of("integrator", "dt", "duration", "csv", "every");

    /** Reads the block (required). */
    static RunSettings read(MapReader top, SceneUnits u) {
        MapReader r = new MapReader(top.required("run"), KEYS);
        String integrator = r.choice("integrator", Integrators.choiceNames(), Integrators.DEFAULT);
        boolean auto = r.has("dt") && r.scalar("dt").text().strip().equals(AUTO);
        double dt = auto ? 0 : r.positive("dt", QuantityKind.TIME, u, Double.NaN);
        double duration = r.positive("duration", QuantityKind.TIME, u, Double.NaN);
        String csv = r.string("csv", "probes.csv");
        if (!csv.matches("[A-Za-z0-9._-]+\\.csv") || csv.startsWith(".")) {
            throw SceneException.at(r.node().get("csv"), "\"" + csv + "\" is not a CSV file name (letters, digits,"
                    + " '.', '_', '-', ending in .csv; it is written in the run's folder)");
        }
        long every = r.integer("every", 1, 1);
        return new RunSettings(integrator, dt, duration, csv, every).checked(r.node());
    }

    /** Whether {@code dt: auto} leaves the step to the body. */
    public boolean autoStep() {
        return dtS == 0;
    }

    /** Number of steps of the run (the step must be known: not {@link #autoStep()}). */
    public long steps() {
        return Math.round(durationS / dtS);
    }

    /** The same settings with another integrator, step or duration (each ignored when null). */
    public RunSettings with(String integratorName, Double dt, Double duration) {
        return new RunSettings(integratorName != null ? integratorName : integrator, dt != null ? dt : dtS,
                duration != null ? duration : durationS, csv, every);
    }

    private RunSettings checked(SceneNode at) {
        if (dtS > durationS) {
            throw SceneException.at(at, "the time step " + dtS + " s is longer than the run (" + durationS
                    + " s): the run would make no step");
        }
        return this;
    }
}

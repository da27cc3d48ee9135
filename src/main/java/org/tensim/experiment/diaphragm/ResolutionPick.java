package org.tensim.experiment.diaphragm;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.tensim.io.Json;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.diaphragm.DiaphragmSpec;

/**
 * The resolution the resolution study picked for the interactive uses (the GUI and the
 * real-time mode): the coarsest double dome whose end-inspiration field, carried to the 43-ring
 * model's nodes by the shell mapping, is within the tolerance of that model, and every finer one too.
 * Written by {@code ./tensim diaphragm resolution-study} (with the 43-ring reference) to
 * {@code resolution-pick.json} in its {@code --out} (or to {@code --pick-out FILE}), with the scene it
 * was measured on ({@link #sceneOf}); read where a command is given the file ({@code --pick FILE}), or
 * the pick shipped with the project ({@link #shipped}: a study's output committed with its date, command
 * and load). A pick is used only for the scene it was measured on ({@link #requireMatches}).
 * docs/diaphragm.md describes it.
 *
 * @param rings     rings per face of the generated double dome picked
 * @param error     its relative RMS error against the reference on the reference's upper nodes (0 when none
 *                  passed and the reference itself is the pick), dimensionless
 * @param tolerance the tolerance it was picked under
 * @param reason    one sentence: why this one
 * @param scene     the scene it was measured on ({@link #sceneOf}); null in a pick written before it was recorded
 * @param source    where it was read: the file, or {@value #SHIPPED_NAME} for the shipped pick
 * @param digest    SHA-256 of the file's bytes (64 hex digits)
 * @param measured  when and how it was measured: the file's {@code measured_utc}, {@code command},
 *                  {@code load_average} (those it has)
 * @param models    the study's table, one row per double dome coarse to fine ({@code model} "N rings",
 *                  {@code nodes}, {@code relative_rms_error}, {@code wall_s_per_simulated_s}...); empty when not
 *                  recorded
 */
public record ResolutionPick(int rings, double error, double tolerance, String reason, Map<String, Object> scene,
        String source, String digest, Map<String, Object> measured, List<Map<String, Object>> models) {
    /** The pick's name in the study's output folder. */
    public static final String NAME = "resolution-pick.json";
    /** How the shipped pick is named in summaries and the window (a classpath resource of this package). */
    public static final String SHIPPED_NAME = "shipped resolution-pick.json";
    /** Rings of the reference a pick is measured against: the paper's resolution. */
    public static final int REFERENCE_RINGS = DiaphragmSpec.PAPER_RINGS;
    /**
     * Default tolerance of the interactive uses' pick, relative RMS error against {@link #REFERENCE_RINGS} rings: 5 %,
     * the figure a user of the window reads beside the large step's own error (docs/gui.md).
     */
    public static final double DEFAULT_TOLERANCE = 0.05;

    public ResolutionPick {
        if (rings < 2) {
            throw new IllegalArgumentException("picked resolution must be at least 2 rings, got " + rings);
        }
        scene = scene == null ? null : Map.copyOf(scene);
        measured = measured == null ? Map.of() : Map.copyOf(measured);
        models = models == null ? List.of() : List.copyOf(models);
    }

    /** A pick as the study makes it, before it is written (no source yet). */
    public ResolutionPick(int rings, double error, double tolerance, String reason) {
        this(rings, error, tolerance, reason, null, null, null, null, null);
    }

    /**
     * The pick the study's table gives under another tolerance: the coarsest double dome whose error, and every
     * finer one's, is within it (this pick when the file has no table or the tolerance is its own).
     *
     * @throws IllegalArgumentException when the tolerance is not in (0, 1)
     */
    public ResolutionPick within(double tol) {
        if (!(tol > 0 && tol < 1)) {
            throw new IllegalArgumentException("resolution tolerance must be in (0, 1) (relative RMS error), got " + tol);
        }
        if (models.isEmpty() || tol == tolerance) {
            return this;
        }
        int i = models.size() - 1;
        for (int j = models.size() - 2; j >= 0 && ((Number) models.get(j).get("relative_rms_error")).doubleValue()
                <= tol; j--) {
            i = j;
        }
        Map<String, Object> row = models.get(i);
        int r = Integer.parseInt(String.valueOf(row.get("model")).replaceAll("[^0-9]", ""));
        double e = ((Number) row.get("relative_rms_error")).doubleValue();
        return new ResolutionPick(r, e, tol, String.format(Locale.ROOT, "the coarsest double dome of the study's table"
                + " within %.0f %% of %d rings, with every finer one: %.2f %%", 100 * tol, REFERENCE_RINGS, 100 * e),
                scene, source, digest, measured, models);
    }

    /**
     * The pick in {@code file}.
     *
     * @throws IllegalStateException naming the file when it is missing or not a pick
     */
    public static ResolutionPick read(Path file) {
        if (!Files.isRegularFile(file)) {
            throw new IllegalStateException("--pick " + file + ": no such file (expected the " + NAME + " that"
                    + " `tensim diaphragm resolution-study` writes to its --out)");
        }
        try {
            return parse(Files.readAllBytes(file), file.toString());
        } catch (IOException e) {
            throw new IllegalStateException(file + ": not a resolution pick (" + e.getMessage() + ")", e);
        }
    }

    /**
     * The pick shipped with the project: the output of {@code diaphragm resolution-study --study-rings ...,43}
     * on the default scene, committed with its provenance (date, command, load) and read from the classpath, never
     * from a folder a study writes to.
     *
     * @throws IllegalStateException when the resource is missing or broken (a build problem)
     */
    public static ResolutionPick shipped() {
        try (InputStream in = ResolutionPick.class.getResourceAsStream(NAME)) {
            if (in == null) {
                throw new IllegalStateException("the shipped " + NAME + " is missing from the build (expected beside "
                        + ResolutionPick.class.getName() + ")");
            }
            return parse(in.readAllBytes(), SHIPPED_NAME);
        } catch (IOException e) {
            throw new IllegalStateException(SHIPPED_NAME + ": not a resolution pick (" + e.getMessage() + ")", e);
        }
    }

    private static ResolutionPick parse(byte[] bytes, String source) throws IOException {
        Map<String, Object> m;
        try {
            @SuppressWarnings("unchecked")
            Map<String, Object> read = Json.mapper().readValue(bytes, Map.class);
            m = read;
        } catch (IOException e) {
            throw new IOException("not JSON: " + e.getMessage(), e);
        }
        Object rings = m.get("rings");
        if (!(rings instanceof Number)) {
            throw new IOException("'rings' is " + rings + ", expected a whole number");
        }
        Object scene = m.get("scene");
        @SuppressWarnings("unchecked")
        Map<String, Object> sceneMap = scene instanceof Map<?, ?> ? (Map<String, Object>) scene : null;
        List<Map<String, Object>> models = new java.util.ArrayList<>();
        if (m.get("models") instanceof List<?> rows) {
            for (Object row : rows) {
                if (!(row instanceof Map<?, ?> r) || !(r.get("relative_rms_error") instanceof Number)
                        || !String.valueOf(r.get("model")).matches("\\d+ rings")) {
                    throw new IOException("'models' has " + row + ": expected rows with model \"N rings\" and"
                            + " relative_rms_error");
                }
                @SuppressWarnings("unchecked")
                Map<String, Object> typed = (Map<String, Object>) r;
                models.add(typed);
            }
        }
        Map<String, Object> measured = new LinkedHashMap<>();
        for (String k : new String[] {"measured_utc", "command", "load_average"}) {
            if (m.get(k) != null) {
                measured.put(k, m.get(k));
            }
        }
        try {
            return new ResolutionPick(((Number) rings).intValue(), number(m, "relative_rms_error"),
                    number(m, "tolerance"), String.valueOf(m.get("reason")), sceneMap, source, sha256(bytes),
                    measured, models);
        } catch (IllegalArgumentException e) {
            throw new IOException(e.getMessage(), e);
        }
    }

    /**
     * What a pick depends on of a scene: the mesh family (the generated double dome, whose 43-ring model is also
     * the committed default mesh), the cage, the label file, the muscle load, the attachment, the tendon rule, the
     * tissue constants and the breathing (period, rib amplitude, muscle action). Values as text, so that a pick
     * read back compares equal.
     */
    public static Map<String, Object> sceneOf(DiaphragmSpec spec) {
        Map<String, Object> m = new LinkedHashMap<>();
        DiaphragmSpec.Mesh mesh = spec.mesh();
        boolean dome = mesh.generated() || mesh.file().toAbsolutePath().normalize()
                .equals(DiaphragmSetup.DEFAULT_MESH.toAbsolutePath().normalize());
        m.put("mesh", dome ? "generated double dome" : mesh.file().toString());
        m.put("cage", spec.cage().describe());
        m.put("labels", mesh.labels() == null ? "none" : mesh.labels().toString());
        m.put("muscle_load", BoundaryConditions.name(spec.boundary().muscleLoad()));
        m.put("attachment", BoundaryConditions.name(spec.boundary().attachment()));
        m.put("tendon_rule", spec.tendonRule().name().toLowerCase(Locale.ROOT));
        m.put("tissue", spec.tissue().toString());
        DiaphragmSpec.Breathing b = spec.breathing();
        m.put("breathing", String.format(Locale.ROOT, "period %s s, I:E 1:%s, ribs x%s, muscle %s Pa, abdomen %s Pa",
                b.periodS(), b.expirationRatio(), b.ribAmplitude(), spec.musclePa(), b.abdominalPressurePa()));
        return m;
    }

    /**
     * Refuses this pick for a scene it was not measured on, naming what differs, the pick's source and how to
     * measure one for the scene.
     *
     * @throws IllegalStateException when the scene differs, or the pick does not record its scene
     */
    public void requireMatches(DiaphragmSpec spec) {
        String redo = "; measure one for this scene with `./tensim diaphragm resolution-study --study-rings"
                + " 14,20,28,43` and the same scene options, then give its " + NAME + " with --pick, or open the"
                + " full model with --rings " + REFERENCE_RINGS;
        if (scene == null) {
            throw new IllegalStateException("the resolution pick " + source + " does not record the scene it was"
                    + " measured on (written before picks did)" + redo);
        }
        Map<String, Object> now = sceneOf(spec);
        for (Map.Entry<String, Object> e : now.entrySet()) {
            Object was = scene.get(e.getKey());
            if (!String.valueOf(e.getValue()).equals(String.valueOf(was))) {
                throw new IllegalStateException("no measured resolution study matches this scene: the pick "
                        + source + " was measured with " + e.getKey() + " = " + was + ", this scene has "
                        + e.getValue() + redo);
            }
        }
    }

    /** The pick as summary entries: rings, error (fraction), tolerance, source, digest, when and how measured. */
    public Map<String, Object> toMap() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("rings", rings);
        m.put("relative_rms_error", error);
        m.put("tolerance", tolerance);
        m.put("reference_rings", REFERENCE_RINGS);
        m.put("source", source);
        m.put("sha256", digest);
        m.putAll(measured);
        return m;
    }

    /** One line for the window: the rings, the error and where the pick comes from. */
    public String describe() {
        return String.format(Locale.ROOT, "%d rings, %.1f %% from %d rings (%s)", rings, 100 * error,
                REFERENCE_RINGS, source);
    }

    /**
     * Picks the coarsest double dome within the tolerance among rows (one per ring count, the last the
     * {@value ResolutionPick#REFERENCE_RINGS}-ring reference) and writes it with its provenance.
     */
    static void pick(List<Map<String, Object>> rows, int[] ringCounts, ResolutionStudy.Setup s,
            Path pickFile,
            Map<String, Object> scene, Map<String, Object> summary, String command) throws IOException {
        int i = ResolutionAnalysis.pick(rows, s.tolerance());
        int rings = ringCounts[i];
        int ref = ringCounts[ringCounts.length - 1];
        String reason = i == rows.size() - 1
                ? String.format(Locale.ROOT, "no coarser double dome is within %.0f %% of the %d-ring model (%d rings:"
                        + " %.1f %%): the reference resolution", 100 * s.tolerance(), ref,
                        ringCounts[Math.max(0, i - 1)], 100 * (double) rows.get(Math.max(0, i - 1))
                                .get("relative_rms_error"))
                : String.format(Locale.ROOT, "the coarsest double dome within %.0f %% of the %d-ring model, with every"
                        + " finer one: %.1f %% at %.2f wall s per simulated s against %.2f for the reference",
                        100 * s.tolerance(), ref, 100 * (double) rows.get(i).get("relative_rms_error"),
                        (double) rows.get(i).get("wall_s_per_simulated_s"),
                        (double) rows.get(rows.size() - 1).get("wall_s_per_simulated_s"));
        ResolutionPick pick = new ResolutionPick(rings, (double) rows.get(i).get("relative_rms_error"),
                s.tolerance(), reason, scene, null, null, null, null);
        Map<String, Object> details = new LinkedHashMap<>();
        details.put("nodes", rows.get(i).get("nodes"));
        details.put("wall_s_per_simulated_s", rows.get(i).get("wall_s_per_simulated_s"));
        details.put("measured_utc", java.time.Instant.now().toString());
        details.put("command", command);
        details.put("load_average", DiaphragmReport.round(java.lang.management.ManagementFactory
                .getOperatingSystemMXBean().getSystemLoadAverage(), 2));
        List<Map<String, Object>> table = new java.util.ArrayList<>();
        for (Map<String, Object> r : rows) {
            Map<String, Object> t = new LinkedHashMap<>(r);
            t.remove("error_hotspots"); // in resolution.json; the pick keeps the table
            table.add(t);
        }
        details.put("models", table);
        pick.write(pickFile, details);
        summary.put("picked_rings", rings);
        summary.put("resolution_pick_file", pickFile.toString());
        summary.put("pick_reason", reason);
        if (s.log() != null) {
            s.log().println("picked " + rings + " rings: " + reason);
        }
    }

    void write(Path file, Map<String, Object> details) throws IOException {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("format", "tensim-resolution-pick");
        m.put("rings", rings);
        m.put("relative_rms_error", DiaphragmReport.round(error, 4));
        m.put("tolerance", tolerance);
        m.put("reason", reason);
        if (scene != null) {
            m.put("scene", scene);
        }
        m.putAll(details);
        Json.write(file, m);
    }

    private static double number(Map<String, Object> m, String key) throws IOException {
        Object v = m.get(key);
        if (!(v instanceof Number)) {
            throw new IOException("'" + key + "' is " + v + ", expected a number");
        }
        return ((Number) v).doubleValue();
    }

    private static String sha256(byte[] bytes) {
        try {
            return HexFormat.of().formatHex(java.security.MessageDigest.getInstance("SHA-256").digest(bytes));
        } catch (java.security.NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is missing from this JVM", e);
        }
    }
}

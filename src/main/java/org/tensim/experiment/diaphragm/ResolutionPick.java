package org.tensim.experiment.diaphragm;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import org.tensim.io.Json;
import org.tensim.io.ProjectFolder;

/**
 * The resolution the resolution study picked for the interactive uses (the GUI and the
 * real-time mode): the coarsest double dome whose end-inspiration field is within the
 * tolerance of the finest model, and every finer one too. Written by
 * {@code ./tensim diaphragm resolution-study} to {@link #FILE} (committed, so that a fresh
 * checkout has it) and read by the GUI's default resolution; docs/diaphragm.md describes it.
 *
 * @param rings     rings per face of the generated double dome picked
 * @param error     its relative RMS error against the reference (0 when none passed and the reference
 *                  itself is the pick)
 * @param tolerance the tolerance it was picked under
 * @param reason    one sentence: why this one
 */
public record ResolutionPick(int rings, double error, double tolerance, String reason) {
    /** Where the study writes the pick and the GUI reads it. */
    public static final Path FILE = ProjectFolder.resolve("meshes", "resolution-pick.json");
    /** The resolution used when no pick has been written: the paper's (43 rings). */
    public static final int FALLBACK_RINGS = 43;

    public ResolutionPick {
        if (rings < 2) {
            throw new IllegalArgumentException("picked resolution must be at least 2 rings, got " + rings);
        }
    }

    /** The pick in {@code file}, or the paper's resolution with a reason saying none was found. */
    public static ResolutionPick read(Path file) {
        if (!Files.isRegularFile(file)) {
            return new ResolutionPick(FALLBACK_RINGS, 0, 0, file + " not found: the paper's resolution");
        }
        try {
            Map<String, Object> m = Json.readMap(file);
            Object rings = m.get("rings");
            if (!(rings instanceof Number)) {
                throw new IOException("'rings' is " + rings + ", expected a whole number");
            }
            return new ResolutionPick(((Number) rings).intValue(), number(m, "relative_rms_error"),
                    number(m, "tolerance"), String.valueOf(m.get("reason")));
        } catch (IOException | IllegalArgumentException e) {
            throw new IllegalStateException(file + ": not a resolution pick (" + e.getMessage() + ")", e);
        }
    }

    /** The committed pick ({@link #FILE}). */
    public static ResolutionPick read() {
        return read(FILE);
    }

    void write(Path file, Map<String, Object> details) throws IOException {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("format", "tensim-resolution-pick");
        m.put("scene", "generated double dome");
        m.put("rings", rings);
        m.put("relative_rms_error", DiaphragmReport.round(error, 4));
        m.put("tolerance", tolerance);
        m.put("reason", reason);
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
}

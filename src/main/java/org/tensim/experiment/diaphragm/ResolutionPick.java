package org.tensim.experiment.diaphragm;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import org.tensim.io.Json;

/**
 * The resolution the resolution study picked for the interactive uses (the GUI and the
 * real-time mode): the coarsest double dome whose end-inspiration field is within the
 * tolerance of the finest model, and every finer one too. Written by
 * {@code ./tensim diaphragm resolution-study} to {@code resolution-pick.json} in its {@code --out}
 * (or to {@code --pick-out FILE}); read only where a command is given the file
 * ({@code --pick FILE} of {@code diaphragm} and {@code gui}). docs/diaphragm.md describes it.
 *
 * @param rings     rings per face of the generated double dome picked
 * @param error     its relative RMS error against the reference (0 when none passed and the reference
 *                  itself is the pick)
 * @param tolerance the tolerance it was picked under
 * @param reason    one sentence: why this one
 */
public record ResolutionPick(int rings, double error, double tolerance, String reason) {
    /** The pick's name in the study's output folder. */
    public static final String NAME = "resolution-pick.json";

    public ResolutionPick {
        if (rings < 2) {
            throw new IllegalArgumentException("picked resolution must be at least 2 rings, got " + rings);
        }
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

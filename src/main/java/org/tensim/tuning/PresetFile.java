package org.tensim.tuning;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.io.Json;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.tunable.DiaphragmViewScene;

/**
 * Presets as JSON files, read and written through Jackson:
 *
 * <pre>
 * {
 *   "format" : "tensim-gui-preset",
 *   "version" : 3,
 *   "scene" : "diaphragm",
 *   "integrator" : "rk2",
 *   "tendon" : "tensegrity",
 *   "muscleLoad" : "fibres",
 *   "diaphragm" : { "rings" : "20", "thorax" : "/data/thorax", "contact" : false },
 *   "parameters" : { "muscleActionPa" : 15000.0, "timeStepS" : 0.001, ... }
 * }
 * </pre>
 *
 * {@code diaphragm} (version 3, the diaphragm scene only) is the rest of the scene's definition: the options of
 * {@code tensim diaphragm} without the dashes, as in a sweep or calibration spec, read through the same parser
 * ({@link PresetScene}); {@code {}} is the default scene. Without it (versions 1 and 2) the preset holds the
 * tunables only and applies to whatever scene is open. A {@code muscle-load} key there is the same as
 * {@code muscleLoad}.
 *
 * {@code muscleLoad} (version 2, scenes with a muscle only) names the muscle-load model the values were tuned
 * with, since it sets what {@code muscleActionPa} means (an active fibre stress or a pressure); loading the
 * preset rebuilds the scene with it, as for the tendon. Version 1 did not record it: every version-1 preset
 * was made with the then default load, the pressure, and a version-1 preset of a scene with a muscle is read
 * as {@code "muscleLoad": "pressure"}, so that it gives what it gave when it was saved.
 *
 * Parameter keys carry their unit. A preset may list only some parameters; the
 * others keep their current values. Files are written to a temporary file then
 * renamed over the target ({@link Json#write}), so a crash never leaves a
 * half-written preset. Reading refuses anything malformed with a
 * {@link PresetException} naming the file and the field, and changes nothing.
 */
public final class PresetFile {
    public static final String FORMAT = "tensim-gui-preset";
    public static final int VERSION = 3;
    /** The muscle load every preset of version 1 was made with (the default load until version 2). */
    static final MuscleLoad VERSION_1_MUSCLE_LOAD = MuscleLoad.PRESSURE;

    /** A preset that cannot be used; the message names the file, the field and what was expected. */
    public static final class PresetException extends Exception {
        public PresetException(String message, Throwable cause) {
            super(message, cause);
        }
    }

    private PresetFile() {
    }

    /** Writes the settings atomically (temporary file, then rename). */
    public static void write(Path file, Settings s) throws IOException {
        Map<String, Object> root = new LinkedHashMap<>();
        root.put("format", FORMAT);
        root.put("version", VERSION);
        root.put("scene", s.scene());
        root.put("integrator", s.integrator());
        root.put("tendon", s.tensegrityTendon() ? "tensegrity" : "mass-spring");
        if (s.muscleLoad() != null) {
            root.put("muscleLoad", BoundaryConditions.name(s.muscleLoad()));
        }
        if (s.sceneOptions() != null) {
            root.put("diaphragm", PresetScene.toJson(s.sceneOptions()));
        }
        root.put("parameters", new LinkedHashMap<>(s.values()));
        Json.write(file, root);
    }

    /**
     * Reads a preset for the scene of {@code current}, completing missing values
     * from it, and checks every value against its parameter's range. The tuning
     * itself is not changed: apply the result with {@link Tuning#apply}.
     */
    public static Settings read(Path file, Tuning current) throws PresetException {
        String where = file.toString();
        JsonNode root = tree(file);
        try {
            Path base = file.toAbsolutePath().getParent();
            Settings s = parse(root, where, current, base);
            current.validate(s, where);
            return s;
        } catch (IllegalArgumentException e) {
            throw new PresetException(e.getMessage(), e);
        }
    }

    /**
     * The diaphragm scene a preset describes (its {@code "diaphragm"} object, checked), to build the scene before
     * the preset's values are read with {@link #read}; null when the preset holds none.
     */
    public static PresetScene.Read scene(Path file) throws PresetException {
        JsonNode root = tree(file);
        JsonNode d = root.isObject() ? root.get("diaphragm") : null;
        try {
            MuscleLoad load = null;
            if (d != null && root.has("muscleLoad")) {
                String name = text(root, "muscleLoad", file.toString(), null);
                try {
                    load = BoundaryConditions.parse(MuscleLoad.class, name);
                } catch (IllegalArgumentException e) {
                    throw new IllegalArgumentException(file + ": field 'muscleLoad': " + e.getMessage(), e);
                }
            }
            return d == null ? null : PresetScene.read(d, file.toString(), file.toAbsolutePath().getParent(), load);
        } catch (IllegalArgumentException e) {
            throw new PresetException(e.getMessage(), e);
        }
    }

    private static JsonNode tree(Path file) throws PresetException {
        String where = file.toString();
        JsonNode root;
        try {
            root = Json.mapper().readTree(Files.readAllBytes(file));
        } catch (NoSuchFileException e) {
            throw new PresetException(where + ": no such file", e);
        } catch (JsonProcessingException e) {
            JsonLocation loc = e.getLocation();
            throw new PresetException(where + " is not valid JSON"
                    + (loc == null ? "" : " at line " + loc.getLineNr() + ", column " + loc.getColumnNr()) + ": "
                    + e.getOriginalMessage(), e);
        } catch (IOException e) {
            throw new PresetException("cannot read preset " + where + ": " + e.getMessage(), e);
        }
        return root;
    }

    static Settings parse(JsonNode root, String where, Tuning current, Path base) {
        if (root == null || !root.isObject()) {
            throw new IllegalArgumentException(where + ": expected a JSON object { ... } at the top level, got "
                    + (root == null ? "nothing" : root.getNodeType().toString().toLowerCase()));
        }
        Settings now = current.snapshot();
        JsonNode format = root.get("format");
        if (format != null && !FORMAT.equals(format.asText())) {
            throw new IllegalArgumentException(where + ": field 'format' must be \"" + FORMAT + "\", got " + format);
        }
        JsonNode version = root.get("version");
        if (version != null && (!version.canConvertToInt() || version.asInt() < 1 || version.asInt() > VERSION)) {
            throw new IllegalArgumentException(where + ": field 'version' must be a whole number from 1 to " + VERSION
                    + ", got " + version);
        }
        int presetVersion = version == null ? VERSION : version.asInt();
        String scene = text(root, "scene", where, now.scene());
        MuscleLoad muscleLoad = now.muscleLoad();
        if (presetVersion == 1) {
            if (root.has("muscleLoad")) {
                throw new IllegalArgumentException(where + ": field 'muscleLoad' needs \"version\": 2 or more, got"
                        + " version 1 (whose presets were all made with the pressure load)");
            }
            muscleLoad = muscleLoad == null ? null : VERSION_1_MUSCLE_LOAD;
        } else if (root.has("muscleLoad")) {
            if (muscleLoad == null) {
                throw new IllegalArgumentException(where + ": field 'muscleLoad': scene '" + current.scene()
                        + "' has no muscle");
            }
            String load = text(root, "muscleLoad", where, null);
            try {
                muscleLoad = BoundaryConditions.parse(MuscleLoad.class, load);
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(where + ": field 'muscleLoad': " + e.getMessage(), e);
            }
        }
        List<String> sceneOptions = null;
        JsonNode diaphragm = root.get("diaphragm");
        if (diaphragm != null) {
            if (presetVersion < 3) {
                throw new IllegalArgumentException(where + ": field 'diaphragm' needs \"version\": 3 or more, got"
                        + " version " + presetVersion);
            }
            if (!scene.equals("diaphragm")) {
                throw new IllegalArgumentException(where + ": field 'diaphragm': scene '" + scene + "' is not the"
                        + " diaphragm");
            }
            PresetScene.Read r = PresetScene.read(diaphragm, where, base,
                    root.has("muscleLoad") ? muscleLoad : null);
            if (r.muscleLoad() != null) {
                if (muscleLoad == null) {
                    throw new IllegalArgumentException(where + ": field 'diaphragm.muscle-load': scene '"
                            + current.scene() + "' has no muscle");
                }
                muscleLoad = r.muscleLoad();
            }
            sceneOptions = r.options();
        }
        String integrator = text(root, "integrator", where, now.integrator());
        String tendonText = text(root, "tendon", where, now.tensegrityTendon() ? "tensegrity" : "mass-spring");
        boolean tensegrity;
        if (tendonText.equals("tensegrity")) {
            tensegrity = true;
        } else if (tendonText.equals("mass-spring")) {
            tensegrity = false;
        } else {
            throw new IllegalArgumentException(where + ": field 'tendon' must be \"tensegrity\" or \"mass-spring\", got \""
                    + tendonText + "\"");
        }
        Map<String, Double> values = new LinkedHashMap<>(now.values());
        JsonNode params = root.get("parameters");
        if (params != null) {
            if (!params.isObject()) {
                throw new IllegalArgumentException(where + ": field 'parameters' must be an object of name: number, got "
                        + params.getNodeType().toString().toLowerCase());
            }
            Iterator<Map.Entry<String, JsonNode>> it = params.fields();
            while (it.hasNext()) {
                Map.Entry<String, JsonNode> e = it.next();
                String field = "parameters." + e.getKey();
                if (!values.containsKey(e.getKey())) {
                    throw new IllegalArgumentException(where + ": field '" + field + "' is not a parameter of scene '"
                            + current.scene() + "'; known: " + current.keys());
                }
                if (!e.getValue().isNumber()) {
                    throw new IllegalArgumentException(where + ": field '" + field + "' must be a number, got "
                            + e.getValue());
                }
                double v = e.getValue().asDouble();
                current.parameter(e.getKey()).validate(v, where + ": field '" + field + "'");
                values.put(e.getKey(), v);
            }
        }
        // A version-1 preset without the muscle action meant the pressure's default amplitude, not the window's.
        if (presetVersion == 1 && muscleLoad != null && muscleLoad != now.muscleLoad()
                && values.containsKey(DiaphragmViewScene.MUSCLE_ACTION)
                && (params == null || !params.has(DiaphragmViewScene.MUSCLE_ACTION))) {
            values.put(DiaphragmViewScene.MUSCLE_ACTION, DiaphragmSetup.DEFAULT_MUSCLE_PA);
        }
        for (Iterator<String> it = root.fieldNames(); it.hasNext();) {
            String f = it.next();
            if (!List.of("format", "version", "scene", "integrator", "tendon", "muscleLoad", "diaphragm", "parameters")
                    .contains(f)) {
                throw new IllegalArgumentException(where + ": unknown field '" + f
                        + "'; expected format, version, scene, integrator, tendon, muscleLoad, diaphragm, parameters");
            }
        }
        return new Settings(scene, integrator, tensegrity, values, muscleLoad, sceneOptions);
    }

    private static String text(JsonNode root, String field, String where, String fallback) {
        JsonNode n = root.get(field);
        if (n == null) {
            return fallback;
        }
        if (!n.isTextual()) {
            throw new IllegalArgumentException(where + ": field '" + field + "' must be a string, got " + n);
        }
        return n.asText();
    }
}

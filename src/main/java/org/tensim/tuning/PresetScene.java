package org.tensim.tuning;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.io.Json;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import picocli.CommandLine;
import picocli.CommandLine.Model.OptionSpec;

/**
 * A preset's diaphragm scene: its {@code "diaphragm"} object, with the keys of a spec file's (the options of
 * {@code tensim diaphragm} without the dashes, {@link DiaphragmOptions#fromJson}), read through the same parser
 * and checked as a whole, files included. In memory the options are kept in command-line form without the muscle
 * load, which a preset holds as its own field ({@link Settings#sceneOptions}).
 */
public final class PresetScene {
    private static final String MUSCLE_LOAD = "--muscle-load";

    /**
     * A preset's scene as read.
     *
     * @param options    the options in command-line form, the muscle load left out
     * @param muscleLoad the muscle load the object or the preset named, or null
     */
    public record Read(List<String> options, MuscleLoad muscleLoad) {
    }

    private PresetScene() {
    }

    /**
     * The diaphragm options a command line gave, in command-line form (each as given, in the order given, the
     * muscle load left out), e.g. {@code ["--rings", "20", "--no-contact"]}: what a preset records of the scene.
     */
    public static List<String> given(CommandLine.ParseResult parsed) {
        List<String> names = DiaphragmOptions.names();
        List<String> args = new ArrayList<>();
        for (OptionSpec o : parsed.matchedOptions()) {
            String name = o.names()[0];
            if (!names.contains(name.substring(2)) || name.equals(MUSCLE_LOAD)) {
                continue;
            }
            if (o.arity().max() == 0) {
                args.add(Boolean.FALSE.equals(o.getValue()) ? "--no-" + name.substring(2) : name);
            } else {
                for (String v : o.originalStringValues()) {
                    args.add(name);
                    args.add(v);
                }
            }
        }
        return args;
    }

    /**
     * The preset form of options in command-line form: each option by its name without the dashes; a flag
     * {@code true} ({@code false} for its negation), a repeated option an array of its values, a path made
     * absolute (the object then reads the same from any folder).
     *
     * @throws IllegalArgumentException naming the option when {@code args} are not options of the diaphragm
     */
    public static Map<String, Object> toJson(List<String> args) {
        CommandLine.ParseResult parsed;
        try {
            parsed = new CommandLine(new DiaphragmOptions.Holder()).parseArgs(args.toArray(String[]::new));
        } catch (CommandLine.ParameterException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
        Map<String, Object> json = new LinkedHashMap<>();
        for (OptionSpec o : parsed.matchedOptions()) {
            String key = o.names()[0].substring(2);
            if (o.arity().max() == 0) {
                json.put(key, !Boolean.FALSE.equals(o.getValue()));
                continue;
            }
            List<String> values = o.originalStringValues().stream()
                    .map(v -> o.type() == Path.class ? Path.of(v).toAbsolutePath().normalize().toString() : v)
                    .toList();
            json.put(key, values.size() == 1 && !o.isMultiValue() ? values.get(0) : values);
        }
        return json;
    }

    /**
     * Reads a preset's {@code "diaphragm"} object and checks the scene it describes, the files it names
     * included; relative paths are resolved against {@code base} (the preset's folder).
     *
     * @param where      the preset, for messages
     * @param presetLoad the preset's own {@code "muscleLoad"} (null if none), which the scene is checked with
     * @throws IllegalArgumentException naming {@code where}, the key and what was expected
     */
    public static Read read(JsonNode obj, String where, Path base, MuscleLoad presetLoad) {
        List<String> args;
        DiaphragmSpec spec;
        MuscleLoad load;
        try {
            args = DiaphragmOptions.fromJson(obj, "diaphragm", base);
            MuscleLoad own = DiaphragmOptions.parse(args).muscleLoad;
            if (own != null && presetLoad != null && own != presetLoad) {
                throw new IllegalArgumentException("field 'diaphragm.muscle-load' is '" + BoundaryConditions.name(own)
                        + "' but field 'muscleLoad' is '" + BoundaryConditions.name(presetLoad) + "'; give one");
            }
            load = own != null ? own : presetLoad;
            List<String> checked = new ArrayList<>(args);
            if (own == null && load != null) {
                checked.addAll(List.of(MUSCLE_LOAD, BoundaryConditions.name(load)));
            }
            spec = DiaphragmOptions.parse(checked).spec(null, DiaphragmSpec.PAPER_RINGS);
        } catch (IllegalArgumentException e) {
            String m = e.getMessage();
            throw new IllegalArgumentException(where + ": " + (m.startsWith("field '") ? m : "field 'diaphragm"
                    + key(obj, e) + "': " + m), e);
        }
        String[][] files = {{"mesh", String.valueOf(spec.mesh().file())}, {"boxes", String.valueOf(spec.cage().boxes())},
            {"labels", String.valueOf(spec.mesh().labels())}, {"thorax", String.valueOf(spec.cage().thorax())}};
        for (String[] f : files) {
            if (!f[1].equals("null") && !Files.exists(Path.of(f[1]))) {
                throw new IllegalArgumentException(where + ": field 'diaphragm." + f[0] + "': " + f[1]
                        + ": no such file or folder");
            }
        }
        return new Read(withoutMuscleLoad(args), load);
    }

    /** ".KEY" for the key of the object that an option's refusal names, or "" when none is found. */
    private static String key(JsonNode obj, IllegalArgumentException e) {
        List<String> names = new ArrayList<>();
        if (e.getCause() instanceof CommandLine.ParameterException pe && pe.getArgSpec() instanceof OptionSpec o) {
            names.addAll(List.of(o.names()));
        }
        for (var it = obj.fieldNames(); it.hasNext();) {
            String k = it.next();
            if (names.contains("--" + k) || e.getMessage().matches("(?s).*--" + java.util.regex.Pattern.quote(k)
                    + "\\b.*")) {
                return "." + k;
            }
        }
        return "";
    }

    /** Options in command-line form without {@code --muscle-load} and its value (a preset's own field). */
    public static List<String> withoutMuscleLoad(List<String> args) {
        List<String> options = new ArrayList<>();
        for (int i = 0; i < args.size(); i++) {
            if (args.get(i).equals(MUSCLE_LOAD)) {
                i++;
            } else {
                options.add(args.get(i));
            }
        }
        return options;
    }

    /**
     * A preset's scene with options given beside it: each option given replaces the preset's of that name
     * (paths made absolute), in command-line form.
     */
    public static List<String> merge(List<String> preset, List<String> given) {
        Map<String, Object> m = new LinkedHashMap<>(toJson(preset));
        m.putAll(toJson(given));
        return DiaphragmOptions.fromJson(Json.mapper().valueToTree(m), "diaphragm", Path.of(""));
    }

    /** Whether two sets of options in command-line form describe the same scene (paths compared absolute). */
    public static boolean same(List<String> a, List<String> b) {
        return toJson(a).equals(toJson(b));
    }
}

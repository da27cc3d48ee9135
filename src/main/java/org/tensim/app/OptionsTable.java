package org.tensim.app;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.tensim.scene.tunable.CubeViewScene;
import org.tensim.scene.tunable.DiaphragmViewScene;
import org.tensim.scene.tunable.TunableParameter;
import org.tensim.tuning.DiaphragmOptions;
import org.tensim.tuning.Tuning;
import picocli.CommandLine;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;

/**
 * Writes docs/reference/options.md: every option of {@code tensim diaphragm} and {@code tensim cube} with the names
 * the same quantity has elsewhere (the key of a sweep or calibration spec, the GUI's label and preset key, the
 * {@code summary.json} key that echoes it), its unit and its default. Flags, descriptions and defaults are read from
 * the picocli model ({@link Main#commandLine()}), the GUI's labels from the scenes' {@link TunableParameter} lists;
 * only what ties an option to a GUI key, a summary key and a unit is written here ({@link #LINKS}), and
 * {@code OptionsTableTest} checks every link against the model, the GUI's parameters and a real run's summary.
 *
 * <p>Run {@code java -cp 'build/install/tensim/lib/*' org.tensim.app.OptionsTable > docs/reference/options.md}
 * after changing an option; the test fails, naming the first differing line, until the file is regenerated.
 */
public final class OptionsTable {
    /**
     * What ties one option to the rest: its unit (empty for a name, a count or a switch), the GUI parameter's key it
     * stands for (null: none) and the summary key that echoes it (null: none).
     *
     * @param flag       the option's name on the command line, any of its aliases
     * @param unit       the value's unit, as the option's description writes it
     * @param guiKey     the key of the GUI's tunable parameter (and of presets and specs' {@code parameters})
     * @param summaryKey the {@code summary.json} key whose value is the option's (dotted for a nested object)
     * @param sceneKey   where a scene file (docs/scenes.md) holds the same quantity, as the schema's definition and
     *                   property, e.g. {@code body_cube:stiffness}; null: nowhere
     */
    public record Link(String flag, String unit, String guiKey, String summaryKey, String sceneKey) {
        /** A link with no scene-file key. */
        public Link(String flag, String unit, String guiKey, String summaryKey) {
            this(flag, unit, guiKey, summaryKey, null);
        }
    }

    /** How a scene file's schema definition is written as a key path, e.g. {@code bodies.NAME.stiffness}. */
    static final Map<String, String> SCENE_PATHS = Map.of("body_cube", "bodies.NAME.", "run", "run.", "law_sine",
            "laws.NAME.", "condition_force", "conditions[force].");

    /** The links, per command; an option not listed has no unit, GUI key or summary key. */
    public static final Map<String, List<Link>> LINKS = Map.of(
            "diaphragm", List.of(
                    new Link("--mesh", "", null, "source"),
                    new Link("--thickness", "mm", null, null),
                    new Link("--contact-stiffness", "Pa/m", null, null),
                    new Link("--liver-support", "Pa/m", null, null),
                    new Link("--liver-abdomen", "Pa/m", null, null),
                    new Link("--abdominal-support", "Pa/m", null, null),
                    new Link("--abdominal-pressure", "Pa", null, null),
                    new Link("--apposition-pressure", "Pa", null, null),
                    new Link("--rib-amplitude", "x quiet", DiaphragmViewScene.RIB_AMPLITUDE, "rib_amplitude"),
                    new Link("--muscle-action", "Pa", DiaphragmViewScene.MUSCLE_ACTION, "muscle_force_pa"),
                    new Link("--period", "s", DiaphragmViewScene.BREATHING_PERIOD, "breathing_period_s"),
                    new Link("--attach-threshold", "mm", null, null),
                    new Link("--band-stiffness", "Pa/m", null, null),
                    new Link("--muscle-load", "", null, "muscle_load"),
                    new Link("--weld-tolerance", "mm", null, null),
                    new Link("--tendon-point", "mm", null, null),
                    new Link("--tendon-fraction", "", DiaphragmViewScene.TENDON_SHARE, "tendon_area_fraction"),
                    new Link("--action-line", "mm", null, null),
                    new Link("--seconds", "s", null, "simulated_s"),
                    new Link("--integrator", "", null, "integrator"),
                    new Link("--dt", "s", Tuning.TIME_STEP, "dt_s"),
                    new Link("--threads", "", null, "threads"),
                    new Link("--newton", "", null, "newton_iterations"),
                    new Link("--cg-iterations", "", null, "cg_iterations_cap"),
                    new Link("--vector-scale", "", null, null),
                    new Link("--csv-times", "s", null, null)),
            "cube", List.of(
                    new Link("--seconds", "s", null, "duration_s", "run:duration"),
                    new Link("--dt", "s", Tuning.TIME_STEP, "dt_s", "run:dt"),
                    new Link("--force", "N", CubeViewScene.FORCE_AMPLITUDE, "parameters.forceAmplitudeN",
                            "condition_force:magnitude"),
                    new Link("--frequency", "Hz", CubeViewScene.FORCE_FREQUENCY, "parameters.forceFrequencyHz",
                            "law_sine:frequency"),
                    new Link("--tilt", "degrees", null, "parameters.forceTiltDeg", "condition_force:direction"),
                    new Link("--stiffness", "N/m", CubeViewScene.STIFFNESS, "parameters.stiffnessNPerM",
                            "body_cube:stiffness"),
                    new Link("--damping", "N s/m", CubeViewScene.DAMPING, "parameters.dampingNsPerM",
                            "body_cube:damping"),
                    new Link("--mass", "kg", null, "parameters.nodeMassKg", "body_cube:node_mass"),
                    new Link("--integrator", "", null, "integrator", "run:integrator")));

    /** The spec keys of the solver options (a sweep or calibration spec's {@code solver} object). */
    static final Map<String, String> SOLVER_SPEC_KEYS = Map.of("--integrator", "solver.integrator", "--dt",
            "solver.dtS", "--seconds", "solver.seconds", "--duration", "solver.seconds");

    /** A closing "(default: ...)" or "(default ...)", one level of parentheses inside, then an optional full stop. */
    private static final Pattern DEFAULT = Pattern.compile(
            "\\s*\\((default[: ][^()]*(\\([^()]*\\)[^()]*)*)\\)(\\.?)\\s*$");

    private OptionsTable() {
    }

    /** Prints the page. */
    public static void main(String[] args) {
        System.out.print(markdown());
    }

    /** The whole page, as docs/reference/options.md holds it. */
    public static String markdown() {
        CommandLine cl = Main.commandLine();
        CommandSpec diaphragm = cl.getSubcommands().get("diaphragm").getCommandSpec();
        CommandSpec cube = cl.getSubcommands().get("cube").getCommandSpec();
        Set<String> sceneKeys = new LinkedHashSet<>(DiaphragmOptions.names());
        List<OptionSpec> scene = new ArrayList<>();
        List<OptionSpec> run = new ArrayList<>();
        for (OptionSpec o : options(diaphragm)) {
            (isScene(o, sceneKeys) ? scene : run).add(o);
        }
        StringBuilder b = new StringBuilder();
        b.append("# Options: one quantity, its names everywhere\n\n")
                .append("<!-- Generated by org.tensim.app.OptionsTable from the picocli model; OptionsTableTest checks"
                        + " that this file is what it prints. Regenerate:\n")
                .append("     java -cp 'build/install/tensim/lib/*' org.tensim.app.OptionsTable >"
                        + " docs/reference/options.md -->\n\n")
                .append("Each option of `tensim diaphragm` and `tensim cube` with the names the same quantity has"
                        + " elsewhere: the key of a\nsweep or calibration spec ([formats.md](../formats.md)), the GUI's"
                        + " label and its key in presets and in specs'\n`parameters` ([gui.md](../gui.md)), and the"
                        + " `summary.json` key that echoes the value a run used. Units and\ndefaults are the"
                        + " options' own (`./tensim CMD --help`).\n\n")
                .append("## The diaphragm's scene\n\n")
                .append("One option set for `tensim diaphragm`, `tensim gui`, the studies (`diaphragm"
                        + " resolution-study`, `realtime-study`),\nthe `\"diaphragm\"` object of sweep and calibration"
                        + " specs and of GUI presets (the name without the dashes).\n\n");
        table(b, "diaphragm", scene, sceneKeys);
        b.append("\n## The diaphragm's run (`tensim diaphragm`)\n\n");
        table(b, "diaphragm", run, sceneKeys);
        b.append("\n## The GUI's diaphragm parameters without an option\n\n")
                .append("| GUI label (preset key) | unit | default | range | summary |\n|---|---|---|---|---|\n");
        unlinked(b, DiaphragmViewScene.parameters(org.tensim.scene.diaphragm.BoundaryConditions.defaults()
                .muscleLoad(), org.tensim.scene.diaphragm.TendonRule.PLANE, false), "diaphragm");
        b.append("\n## The cube (`tensim cube`)\n\n")
                .append("The cube's spec (`\"scene\": \"cube\"`) takes its GUI keys in `parameters` and `fixed`; its scene"
                        + " file is\n[examples/cube.yaml](../examples/cube.yaml) ([scenes.md](../scenes.md)).\n\n");
        table(b, "cube", options(cube), Set.of());
        b.append("\n## The GUI's cube parameters without an option\n\n")
                .append("| GUI label (preset key) | unit | default | range | summary |\n|---|---|---|---|---|\n");
        unlinked(b, CubeViewScene.PARAMETERS, "cube");
        return b.toString();
    }

    /** The options of a command, help and version left out, in the order of their first name. */
    static List<OptionSpec> options(CommandSpec c) {
        List<OptionSpec> l = new ArrayList<>();
        for (OptionSpec o : c.options()) {
            if (!o.usageHelp() && !o.versionHelp() && !o.hidden()) {
                l.add(o);
            }
        }
        l.sort((x, y) -> x.names()[0].compareTo(y.names()[0]));
        return l;
    }

    private static boolean isScene(OptionSpec o, Set<String> sceneKeys) {
        return Arrays.stream(o.names()).anyMatch(n -> sceneKeys.contains(n.substring(2)));
    }

    /** The link of an option, by any of its names; null when it has none. */
    static Link link(String command, OptionSpec o) {
        for (Link l : LINKS.get(command)) {
            if (Arrays.asList(o.names()).contains(l.flag())) {
                return l;
            }
        }
        return null;
    }

    /** The GUI's parameter of a key, searched in the command's scene; null when there is none. */
    static TunableParameter guiParameter(String command, String key) {
        if (key == null) {
            return null;
        }
        List<TunableParameter> all = new ArrayList<>(command.equals("cube") ? CubeViewScene.PARAMETERS
                : DiaphragmViewScene.PARAMETERS);
        all.addAll(DiaphragmViewScene.parameters(org.tensim.scene.diaphragm.BoundaryConditions.defaults()
                .muscleLoad(), org.tensim.scene.diaphragm.TendonRule.GEODESIC, false));
        for (TunableParameter p : all) {
            if (p.key().equals(key)) {
                return p;
            }
        }
        // the time step is every scene's setting, not a scene's parameter; its label and unit do not depend on
        // the default step given here
        return key.equals(Tuning.TIME_STEP) ? Tuning.timeStepParameter(1e-3) : null;
    }

    private static void table(StringBuilder b, String command, List<OptionSpec> opts, Set<String> sceneKeys) {
        boolean scene = LINKS.get(command).stream().anyMatch(l -> l.sceneKey() != null);
        b.append("| CLI flag | spec key | ").append(scene ? "scene-file key | " : "")
                .append("GUI label (preset key) | `summary.json` key | unit | default | summary |\n")
                .append(scene ? "|---|---|---|---|---|---|---|---|\n" : "|---|---|---|---|---|---|---|\n");
        for (OptionSpec o : opts) {
            Link l = link(command, o);
            TunableParameter p = l == null ? null : guiParameter(command, l.guiKey());
            String[] d = descriptionAndDefault(o);
            b.append("| ").append(flags(o)).append(" | ").append(specKey(command, o, sceneKeys, l)).append(" | ");
            if (scene) {
                b.append(sceneKey(l)).append(" | ");
            }
            b.append(p == null ? "" : p.label() + " (`" + p.key() + "`)").append(" | ")
                    .append(l == null || l.summaryKey() == null ? "" : "`" + l.summaryKey() + "`").append(" | ")
                    .append(l == null ? "" : cell(l.unit())).append(" | ").append(cell(d[1])).append(" | ")
                    .append(cell(d[0])).append(" |\n");
        }
    }

    private static void unlinked(StringBuilder b, List<TunableParameter> params, String command) {
        Set<String> linked = new LinkedHashSet<>();
        LINKS.get(command).forEach(l -> linked.add(l.guiKey()));
        for (TunableParameter p : params) {
            if (!linked.contains(p.key())) {
                b.append("| ").append(p.label()).append(" (`").append(p.key()).append("`) | ").append(cell(p.unit()))
                        .append(" | ").append(number(p.defaultValue())).append(" | ").append(number(p.min()))
                        .append(" to ").append(number(p.max())).append(" | ").append(cell(p.description()))
                        .append(" |\n");
            }
        }
    }

    /** The option's name (and its negation), then its former names, which still work. */
    private static String flags(OptionSpec o) {
        String[] names = o.names();
        String first = "`" + names[0] + "`" + (o.negatable() && !names[0].startsWith("--no-") ? ", `--no-"
                + names[0].substring(2) + "`" : "");
        List<String> former = new ArrayList<>();
        for (int i = 1; i < names.length; i++) {
            former.add("`" + names[i] + "`");
        }
        String label = o.arity().max() == 0 ? "" : " " + o.paramLabel();
        return first + cell(label) + (former.isEmpty() ? "" : " (also " + String.join(", ", former) + ")");
    }

    /** The scene-file key of a link, as a path ({@code bodies.NAME.stiffness}); empty when it has none. */
    static String sceneKey(Link l) {
        if (l == null || l.sceneKey() == null) {
            return "";
        }
        String[] dp = l.sceneKey().split(":");
        return "`" + SCENE_PATHS.get(dp[0]) + dp[1] + "`";
    }

    private static String specKey(String command, OptionSpec o, Set<String> sceneKeys, Link l) {
        List<String> keys = new ArrayList<>();
        if (isScene(o, sceneKeys)) {
            keys.add("`diaphragm." + o.names()[0].substring(2) + "`");
        }
        for (String n : o.names()) {
            String k = SOLVER_SPEC_KEYS.get(n);
            if (k != null && !keys.contains("`" + k + "`")) {
                keys.add("`" + k + "`");
            }
        }
        if (l != null && l.guiKey() != null && !l.guiKey().equals(Tuning.TIME_STEP)) {
            keys.add("`parameters." + l.guiKey() + "`");
        }
        return String.join(", ", keys);
    }

    /**
     * The description without its closing {@code (default: ...)}, and the default: picocli's default value when
     * the option has one, else what that closing parenthesis says, else empty.
     */
    static String[] descriptionAndDefault(OptionSpec o) {
        String text = String.join(" ", o.description()).replace("${DEFAULT-VALUE}",
                String.valueOf(o.defaultValue())).trim();
        String def = "";
        Matcher m = DEFAULT.matcher(text);
        if (m.find()) {
            def = m.group(1).replaceFirst("^default[: ]\\s*", "");
            text = text.substring(0, m.start()).trim() + m.group(3);
        }
        if (o.defaultValue() != null && def.isEmpty()) {
            def = o.defaultValue();
        }
        if (o.arity().max() == 0 && def.isEmpty()) {
            def = o.negatable() ? "" : "off";
        }
        return new String[] {text, def};
    }

    private static String cell(String s) {
        return s == null ? "" : s.replace("|", "\\|").replace("\n", " ");
    }

    private static String number(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? String.valueOf((long) v) : String.valueOf(v);
    }
}

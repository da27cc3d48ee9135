package org.tensim.tuning;

import java.nio.file.Path;
import java.util.List;
import org.tensim.scene.diaphragm.ActionLines;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.DiaphragmChoices;
import org.tensim.scene.diaphragm.DiaphragmParameters;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.scene.diaphragm.TendonRule;
import org.tensim.scene.shell.TissueModel;
import picocli.CommandLine.Option;

/**
 * The diaphragm scene's options, one set for every way in: a picocli mixin of {@code tensim diaphragm} and
 * {@code tensim gui}, and the keys of a sweep or calibration spec's {@code "diaphragm"} object (the same names
 * without the dashes, read by {@link #fromJson}). {@link #spec} turns them into the one
 * {@link DiaphragmSpec}, with one validation; an option left out keeps the spec's default.
 */
public final class DiaphragmOptions {
    @Option(names = "--mesh", paramLabel = "FILE",
            description = "Diaphragm mesh (.obj, .stl, .off): a thin closed shell, or one surface to offset"
                    + " (default: the generated double dome).")
    public Path mesh;

    @Option(names = "--units", paramLabel = "mm|m", description = "Units of the mesh file (default: mm).")
    String units;

    @Option(names = "--thickness", paramLabel = "MM",
            description = "Thickness given to a single-surface mesh, mm (default: 2.5).")
    Double thicknessMm;

    @Option(names = {"--rings", "--resolution"}, paramLabel = "N",
            description = "Rings per face of the generated double dome: 43 is the paper's 11,354 nodes, 20 about"
                    + " 2,500; --pick FILE takes a resolution study's pick instead (default: 43).")
    Integer rings;

    @Option(names = "--boxes", paramLabel = "FILE",
            description = "Rib and sternum boxes, mm, BodyParts3D frame, e.g. BodyParts3D's in the shared folder,"
                    + " meshes/bodyparts3d/rib-sternum-bounds-mm.json (default: the project's parametric rib cage,"
                    + " placed on the generated dome).")
    public Path boxes;

    @Option(names = "--thorax", paramLabel = "DIR",
            description = "A thorax of bone surfaces: a folder with a parts.json and its OBJ parts in the mesh's frame,"
                    + " e.g. ../shared/meshes/thorax (ribs, cartilage, sternum and vertebrae; the diaphragm attached at"
                    + " its origins and sliding on the bones elsewhere) (default: the parametric rib cage).")
    public Path thorax;

    @Option(names = "--cage", paramLabel = "segments|surfaces",
            description = "How the diaphragm meets the parametric cage (or --boxes): segments (the attachment band to"
                    + " the rib, cartilage and spine lines) or surfaces (the cage's bones swept into closed surfaces,"
                    + " attached at the origins and sliding on the bones elsewhere, as with --thorax, whose bones are"
                    + " always surfaces) (default: segments).")
    String cage;

    @Option(names = "--labels", paramLabel = "FILE",
            description = "Per-vertex labels of the mesh (tendon, muscle, origin-sternal, origin-costal,"
                    + " origin-lumbar; 'tensim-labels 1' format) (default: derived by rule).")
    public Path labels;

    @Option(names = "--tendon-rule", paramLabel = "RULE", converter = ModelNames.TendonRules.class,
            description = "How the central tendon is found without --labels: plane (the paper's: the cap above a"
                    + " plane, --tendon-fraction of the upper surface) or geodesic (the region nearest the two dome"
                    + " tops and their midpoint along the surface, the same share) (default: geodesic; plane with"
                    + " --model paper).")
    TendonRule tendonRule;

    @Option(names = "--contact", negatable = true,
            description = "With --thorax: the muscle slides on the bones, frictionless and one-sided, where it is"
                    + " not attached (default: on; off in the paper's model; --no-contact turns it off).")
    public Boolean contact;

    @Option(names = "--contact-stiffness", paramLabel = "PA_PER_M",
            description = "Contact penalty stiffness per unit area of diaphragm, Pa/m (default: "
                    + DiaphragmSpec.Cage.DEFAULT_CONTACT_PA_PER_M + ").")
    Double contactPaPerM;

    @Option(names = "--liver-support", paramLabel = "PA_PER_M",
            description = "With --thorax and contact: stiffness per unit area of the liver's one-sided elastic support"
                    + " under the right hemidiaphragm, Pa/m; 0 turns it off (default: "
                    + DiaphragmSpec.Cage.DEFAULT_LIVER_PA_PER_M + ").")
    Double liverPaPerM;

    @Option(names = "--abdominal-support", paramLabel = "PA_PER_M",
            description = "Stiffness per unit area of the abdominal contents under the diaphragm, Pa/m: every free"
                    + " lower-surface node tied to its rest point by K A_i / 2; 0 turns it off (default: "
                    + DiaphragmParameters.DEFAULT_ABDOMINAL_SUPPORT_PA_PER_M + "; docs/thorax.md, \"Resolution\").")
    Double abdominalPaPerM;

    @Option(names = "--abdominal-pressure", paramLabel = "PA",
            description = "Rise of the abdominal pressure on the diaphragm's lower face at end-inspiration, Pa,"
                    + " 0..5000: it follows the breathing level and presses the zone of apposition on the chest wall"
                    + " (default: 0, none; docs/thorax.md, \"Is the full mesh converged?\").")
    Double abdominalPressurePa;

    @Option(names = "--apposition-pressure", paramLabel = "PA",
            description = "With bone surfaces and contact: rise of the abdominal pressure on the zone of apposition at"
                    + " end-inspiration, Pa, 0..5000; it presses the muscle lying against the ribs, cartilages and"
                    + " sternum onto them; 0 turns it off (default: " + DiaphragmSpec.Cage.DEFAULT_APPOSITION_PA
                    + "; docs/thorax.md, \"The zone of apposition\").")
    Double appositionPa;

    @Option(names = "--model", paramLabel = "NAME",
            description = "The model: default (the material shell, the attachment band, the fibres' active"
                    + " tension) or paper"
                    + " (exactly the paper's section 3.2: its tissue springs, attachment by a distance threshold,"
                    + " vertical action lines with per-node forces, no contact); the paper's model sets"
                    + " --tissue-model, --attachment and --muscle-load, which must then be left out (default:"
                    + " default).")
    public String model;

    @Option(names = "--rib-amplitude", paramLabel = "FACTOR",
            description = "Rib rotation, times the quiet-breathing value, 0..3 (default: 1).")
    Double ribAmplitude;

    @Option(names = {"--muscle-action", "--muscle-force"}, paramLabel = "PA",
            description = "Peak muscle action, Pa, 0..60000: active fibre stress (--muscle-load fibres, the default;"
                    + " default 19000) or force per unit area of diaphragm (pressure, paper-nodes; default 2600).")
    Double musclePa;

    @Option(names = "--period", paramLabel = "S", description = "Breathing period, s (default: 4).")
    Double periodS;

    @Option(names = "--ie-ratio", paramLabel = "R",
            description = "Expiration time over inspiration time, I:E = 1:R (default: 2).")
    Double ieRatio;

    @Option(names = "--expiratory-pause", paramLabel = "SHARE",
            description = "End-expiratory pause, the share of the expiration spent at rest, 0 to below 1 (default:"
                    + " 0.25, fitted to the DIR-Lab 4D-CT time course; 0: the expiration's cosine takes all of it).")
    Double pauseShare;

    @Option(names = "--attach-threshold", paramLabel = "MM",
            description = "Attach diaphragm nodes closer than this to ribs, cartilage or sternum, mm (default: 20).")
    Double attachMm;

    @Option(names = "--attachment", paramLabel = "MODEL", converter = ModelNames.Attachments.class,
            description = "The attachment: band (elastic ties, a stiffness per unit area) or paper-threshold"
                    + " (the paper's: nodes"
                    + " within the threshold driven with the ribs) (default: band).")
    BoundaryConditions.Attachment attachment;

    @Option(names = "--band-stiffness", paramLabel = "PA_PER_M",
            description = "Attachment band stiffness per unit area of diaphragm, Pa/m (default: "
                    + BoundaryConditions.DEFAULT_BAND_PA_PER_M + ").")
    Double bandPaPerM;

    @Option(names = "--band-all-segments",
            description = "Attachment band: attach to every cage segment within the threshold, not only to the"
                    + " diaphragm's origins (ribs 7-12 and their cartilages, the xiphoid, the spine).")
    boolean allSegments;

    @Option(names = "--muscle-load", paramLabel = "MODEL", converter = ModelNames.MuscleLoads.class,
            description = "The muscle load: fibres (active tension along the fibres to the central tendon, 19"
                    + " kPa of fibre stress),"
                    + " pressure (action-line traction integrated over the muscle's area, 2.6 kPa) or paper-nodes (the"
                    + " paper's per-node forces, 2.6 kPa) (default: fibres).")
    public BoundaryConditions.MuscleLoad muscleLoad;

    @Option(names = "--weld-tolerance", paramLabel = "MM",
            description = "Mesh cleaning: vertices closer than this are merged, mm (default: 0.001).")
    Double weldMm;

    @Option(names = "--min-piece-fraction", paramLabel = "F",
            description = "Mesh cleaning: disconnected pieces with fewer than this fraction of the triangles are"
                    + " dropped; 0 keeps every piece (default: 0.01).")
    Double minPieceFraction;

    @Option(names = "--tendon-normal", paramLabel = "X,Y,Z", split = ",", hideParamSyntax = true,
            description = "Normal of the muscle/tendon plane, pointing to the tendon (default: 0,0,1, superior).")
    double[] tendonNormal;

    @Option(names = "--tendon-point", paramLabel = "X,Y,Z", split = ",", hideParamSyntax = true,
            description = "A point of the muscle/tendon plane, mm, mesh frame (default: placed so that the tendon"
                    + " has --tendon-fraction of the upper surface).")
    double[] tendonPointMm;

    @Option(names = "--tendon-fraction", paramLabel = "F",
            description = "Share of the upper surface's area given to the tendon when no --tendon-point is given"
                    + " (default: 0.12).")
    Double tendonFraction;

    @Option(names = "--tissue-model", paramLabel = "NAME", converter = ModelNames.TissueModels.class,
            description = "How the shell comes from the tissue: material (identified from E, nu and t: membrane"
                    + " triangles, Kirchhoff bending, rigid columns), springs (the same with edge springs only) or"
                    + " paper (the model the paper's figures were reproduced with) (default: material;"
                    + " docs/diaphragm.md).")
    TissueModel tissueModel;

    @Option(names = "--action-line", paramLabel = "X,Y,R", converter = ActionLineConverter.class,
            description = "A vertical muscle action line through (X, Y) with radius of action R, mm; repeat for"
                    + " several (default: one through the top of each dome, R = 0.3 x the mesh width); for"
                    + " --muscle-load pressure and paper-nodes (the fibres' tension has no action lines).")
    List<ActionLines.Line> actionLines;

    /**
     * The scene these options describe: the default (or the paper's) spec with every given option applied
     * ({@link DiaphragmChoices#spec}, which a scene file's diaphragm body goes through too).
     *
     * @param defaultMesh  the mesh file read when {@code --mesh} is left out (null: the generated double dome)
     * @param defaultRings the generated double dome's rings when {@code --rings} is left out
     * @throws IllegalArgumentException naming the option and the value when one is out of range or the options
     *                                  contradict each other
     */
    public DiaphragmSpec spec(Path defaultMesh, int defaultRings) {
        return choices().spec(defaultMesh, defaultRings);
    }

    /** The options' values, null where left out. */
    public DiaphragmChoices choices() {
        DiaphragmChoices c = new DiaphragmChoices();
        c.mesh = mesh;
        c.units = units;
        c.thicknessMm = thicknessMm;
        c.rings = rings;
        c.boxes = boxes;
        c.thorax = thorax;
        c.cage = cage;
        c.labels = labels;
        c.tendonRule = tendonRule;
        c.contact = contact;
        c.contactPaPerM = contactPaPerM;
        c.liverPaPerM = liverPaPerM;
        c.abdominalPaPerM = abdominalPaPerM;
        c.abdominalPressurePa = abdominalPressurePa;
        c.appositionPa = appositionPa;
        c.model = model;
        c.ribAmplitude = ribAmplitude;
        c.musclePa = musclePa;
        c.periodS = periodS;
        c.ieRatio = ieRatio;
        c.pauseShare = pauseShare;
        c.attachMm = attachMm;
        c.attachment = attachment;
        c.bandPaPerM = bandPaPerM;
        c.allSegments = allSegments;
        c.muscleLoad = muscleLoad;
        c.weldMm = weldMm;
        c.minPieceFraction = minPieceFraction;
        c.tendonNormal = tendonNormal;
        c.tendonPointMm = tendonPointMm;
        c.tendonFraction = tendonFraction;
        c.tissueModel = tissueModel;
        c.actionLines = actionLines;
        return c;
    }

    /** Holds the options for a parse outside a command (spec files). */
    @picocli.CommandLine.Command(name = "diaphragm-options")
    static final class Holder {
        @picocli.CommandLine.Mixin
        DiaphragmOptions options = new DiaphragmOptions();
    }

    /**
     * Options as a command line would give them, e.g. {@code ["--thorax", "dir", "--muscle-load", "pressure"]}.
     *
     * @throws IllegalArgumentException naming the option, the value and what was expected
     */
    public static DiaphragmOptions parse(List<String> args) {
        Holder h = new Holder();
        try {
            new picocli.CommandLine(h).parseArgs(args.toArray(String[]::new));
        } catch (picocli.CommandLine.ParameterException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
        return h.options;
    }

    /**
     * The command-line form of a spec file's {@code "diaphragm"} object, whose keys are the options' names
     * without the dashes: {@code {"thorax": "../thorax", "muscle-load": "pressure", "rings": 20,
     * "contact": false, "action-line": ["0,10,40", "0,-10,40"], "tendon-normal": [0, 0, 1]}}. A string, number
     * or {@code true} is one option; {@code false} is the option's negation ({@code --no-contact}); an array of
     * numbers is one comma-separated value and an array of strings repeats the option. Paths are resolved against
     * {@code base} (the spec file's folder).
     *
     * @param field the object's name in messages, e.g. {@code diaphragm}
     * @throws IllegalArgumentException naming {@code field.key} and what was expected
     */
    public static List<String> fromJson(com.fasterxml.jackson.databind.JsonNode obj, String field, Path base) {
        if (!obj.isObject()) {
            throw new IllegalArgumentException("field '" + field + "' must be an object of option: value (the"
                    + " options of `tensim diaphragm` without the dashes), got " + obj);
        }
        picocli.CommandLine.Model.CommandSpec spec = new picocli.CommandLine(new Holder()).getCommandSpec();
        List<String> args = new java.util.ArrayList<>();
        for (var it = obj.fields(); it.hasNext();) {
            var e = it.next();
            String name = "--" + e.getKey();
            picocli.CommandLine.Model.OptionSpec o = spec.findOption(name);
            if (o == null || e.getKey().startsWith("-")) {
                throw new IllegalArgumentException("field '" + field + "." + e.getKey() + "' is not an option of the"
                        + " diaphragm; expected one of " + names());
            }
            com.fasterxml.jackson.databind.JsonNode v = e.getValue();
            boolean isPath = o.type() == Path.class;
            if (v.isBoolean()) {
                if (v.asBoolean()) {
                    args.add(name);
                } else if (o.negatable()) {
                    args.add("--no-" + e.getKey());
                } else if (o.arity().max() != 0) {
                    throw new IllegalArgumentException("field '" + field + "." + e.getKey() + "' must be "
                            + o.paramLabel() + ", got false");
                }
            } else if (v.isArray() && v.size() > 0 && v.get(0).isNumber()) {
                List<String> parts = new java.util.ArrayList<>();
                v.forEach(x -> parts.add(x.asText()));
                args.add(name);
                args.add(String.join(",", parts));
            } else if (v.isArray()) {
                for (com.fasterxml.jackson.databind.JsonNode x : v) {
                    args.add(name);
                    args.add(text(x, field + "." + e.getKey(), isPath, base));
                }
            } else {
                args.add(name);
                args.add(text(v, field + "." + e.getKey(), isPath, base));
            }
        }
        return args;
    }

    /** The option names without dashes, as a spec file's {@code "diaphragm"} object takes them. */
    public static List<String> names() {
        return new picocli.CommandLine(new Holder()).getCommandSpec().options().stream()
                .map(o -> o.names()[0].substring(2)).sorted().toList();
    }

    private static String text(com.fasterxml.jackson.databind.JsonNode v, String field, boolean isPath, Path base) {
        if (!v.isTextual() && !v.isNumber()) {
            throw new IllegalArgumentException("field '" + field + "' must be a string or a number, got " + v);
        }
        return isPath ? base.resolve(v.asText()).normalize().toString() : v.asText();
    }

    /** Whether {@code --rings} was given (or set by {@link PickOption#apply}). */
    public boolean ringsGiven() {
        return rings != null;
    }

    /** Whether the bones are surfaces ({@code --thorax} or {@code --cage surfaces}): contact is on the table. */
    public boolean boneSurfaces() {
        return choices().boneSurfaces();
    }

    /** Whether {@code --model paper} was given; refuses a model that is neither default nor paper. */
    public boolean paperModel() {
        return choices().paperModel();
    }

    /**
     * The GUI's controls these options set, by control key ({@code --period}, {@code --rib-amplitude},
     * {@code --muscle-action}; in the controls' units: s, times quiet breathing, Pa), each with the option that set
     * it; empty when none is given. The window starts its controls at them, over the last-used values.
     */
    public java.util.Map<String, java.util.Map.Entry<String, Double>> controlValues() {
        java.util.Map<String, java.util.Map.Entry<String, Double>> m = new java.util.LinkedHashMap<>();
        if (periodS != null) {
            m.put(org.tensim.scene.tunable.DiaphragmViewScene.BREATHING_PERIOD, java.util.Map.entry("--period",
                    periodS));
        }
        if (ribAmplitude != null) {
            m.put(org.tensim.scene.tunable.DiaphragmViewScene.RIB_AMPLITUDE, java.util.Map.entry("--rib-amplitude",
                    ribAmplitude));
        }
        if (musclePa != null) {
            m.put(org.tensim.scene.tunable.DiaphragmViewScene.MUSCLE_ACTION, java.util.Map.entry("--muscle-action",
                    musclePa));
        }
        return m;
    }

    /**
     * As {@link #controlValues()}, and with the lungs in the state ({@code lungs}) the muscle action starts at the
     * lungs' default ({@link org.tensim.scene.lungs.LungsMuscle#startingPa}, as {@code tensim diaphragm --lungs}
     * runs) unless {@code --muscle-action} gives one.
     */
    public java.util.Map<String, java.util.Map.Entry<String, Double>> controlValues(boolean lungs) {
        java.util.Map<String, java.util.Map.Entry<String, Double>> m = controlValues();
        Double pa = lungs ? org.tensim.scene.lungs.LungsMuscle.startingPa(muscleLoad == null
                ? org.tensim.scene.diaphragm.BoundaryConditions.defaults().muscleLoad() : muscleLoad) : null;
        if (pa != null) {
            m.putIfAbsent(org.tensim.scene.tunable.DiaphragmViewScene.MUSCLE_ACTION,
                    java.util.Map.entry("--lungs", pa));
        }
        return m;
    }
}

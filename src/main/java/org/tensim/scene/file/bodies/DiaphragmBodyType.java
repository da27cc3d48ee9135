package org.tensim.scene.file.bodies;

import java.io.IOException;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import javax.measure.MetricPrefix;
import javax.measure.Unit;
import org.tensim.io.mesh.MeshFormatException;
import org.tensim.model.Topology;
import org.tensim.scene.diaphragm.ActionLines;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.DiaphragmChoices;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.scene.diaphragm.TendonRule;
import org.tensim.scene.file.BodyContext;
import org.tensim.scene.file.BodyType;
import org.tensim.scene.file.MapReader;
import org.tensim.scene.file.QuantityKind;
import org.tensim.scene.file.SceneException;
import org.tensim.scene.file.SceneNode;
import org.tensim.scene.shell.TissueModel;
import tech.units.indriya.unit.Units;

/**
 * {@code type: diaphragm}: the paper's diaphragm scene (section 3.2; docs/diaphragm.md) as {@code tensim diaphragm}
 * builds it ({@link DiaphragmSetup#build}), its keys the command's options with {@code _} for {@code -}
 * ({@code rings}, {@code mesh}, {@code thorax}, {@code muscle_load}, {@code contact_stiffness}, ...; the options'
 * help says what each is and its default). Values may carry units ({@code thickness: 2.5 mm},
 * {@code contact_stiffness: 5e7 Pa/m}, {@code period: 4 s}); a bare number takes the file's units, as everywhere.
 * Files and folders are relative to the scene file. Without {@code mesh} and {@code rings} the body is the
 * project's 43-ring mesh (meshes/diaphragm-default.obj), as the command's default; {@code rings} alone generates
 * the double dome at that resolution.
 *
 * <p>The body carries its scene ({@link org.tensim.scene.file.SceneBody#built()}): {@code tensim run} runs it as
 * the command does and writes the diaphragm's report. Its nodes are the scene's (the mesh's vertices first), and
 * its surface the mesh's closed shell on them. Its file's conditions add loads and supports to its nodes
 * ({@link #refusedCondition} says which); its probes are recorded during the run.
 */
public final class DiaphragmBodyType implements BodyType {
    /** The keys, each an option of {@code tensim diaphragm} without its dashes, {@code _} for {@code -}. */
    public static final List<String> KEYS = List.of("mesh", "units", "thickness", "rings", "labels", "weld_tolerance",
            "min_piece_fraction", "boxes", "thorax", "cage", "contact", "contact_stiffness", "liver_support",
            "abdominal_support", "abdominal_pressure", "apposition_pressure", "model", "tissue_model", "tendon_rule",
            "tendon_normal", "tendon_point", "tendon_fraction", "attach_threshold", "attachment", "band_stiffness",
            "band_all_segments", "muscle_load", "muscle_action", "action_line", "rib_amplitude", "period", "ie_ratio",
            "expiratory_pause");
    private static final Unit<?> MM = MetricPrefix.MILLI(Units.METRE);
    private static final Unit<?> PA = Units.PASCAL;

    /** The type's name in a scene file. */
    public static final String NAME = "diaphragm";

    @Override
    public String name() {
        return NAME;
    }

    @Override
    public List<String> keys() {
        return KEYS;
    }

    /**
     * The diaphragm brings its ribs, supports, muscle load and outputs; {@code run: {dt: auto}} is the command's
     * default step, the one its time-step policy recommends.
     */
    @Override
    public boolean standalone() {
        return true;
    }

    /** The time-step policy's step for the integrator on the built scene, as {@code tensim run} takes it. */
    @Override
    public org.tensim.solver.stability.TimeStep autoStep(org.tensim.scene.file.SceneBody body, String integrator) {
        return ((DiaphragmSetup.Built) body.built()).scene().timeStep(
                org.tensim.solver.integrators.Integrators.create(integrator), 0);
    }

    /** The breathing figures of the run's summary an {@code expect:} check may read (BreathingMetrics#fields). */
    public static final List<String> SUMMARY_KEYS = List.of("dome_excursion_mm", "apex_descent_mm",
            "right_dome_descent_mm", "left_dome_descent_mm", "largest_descent_mm", "ap_extent_change_mm",
            "transverse_extent_change_mm", "vertical_extent_change_mm");

    /** {@link #SUMMARY_KEYS}, in mm: present when the run measured a whole inspiration (else a check fails). */
    @Override
    public java.util.Map<String, String> summaryKeys() {
        java.util.Map<String, String> m = new java.util.LinkedHashMap<>();
        SUMMARY_KEYS.forEach(k -> m.put(k, "mm"));
        return m;
    }

    /** Each built diaphragm's parts, computed once for all its regions (the apposition zone queries the bones). */
    private final java.util.Map<Object, java.util.Map<String, java.util.BitSet>> parts =
            java.util.Collections.synchronizedMap(new java.util.WeakHashMap<>());

    /** The diaphragm's parts ({@link org.tensim.scene.diaphragm.DiaphragmRegions#of}: tendon, muscle, ...). */
    @Override
    public java.util.Map<String, java.util.BitSet> parts(org.tensim.scene.file.SceneBody body) {
        return parts.computeIfAbsent(body.built(),
                b -> org.tensim.scene.diaphragm.DiaphragmRegions.of(((DiaphragmSetup.Built) b).scene()));
    }

    @Override
    public int[] build(BodyContext ctx, Topology topology) {
        MapReader r = ctx.keys();
        DiaphragmSpec spec = spec(ctx);
        DiaphragmSetup.Built built;
        try {
            built = DiaphragmSetup.build(spec);
        } catch (MeshFormatException | IllegalArgumentException e) {
            throw SceneException.at(r.node(), e.getMessage());
        } catch (IOException e) {
            throw SceneException.at(r.node(), "cannot read the diaphragm's files (" + e.getMessage() + ")");
        }
        ctx.own(built.scene().topology(), built);
        ctx.embed(surface(built));
        if (built.meshReport() != null) {
            ctx.report(built.meshReport().describe());
        }
        ctx.report(built.source());
        return null;
    }

    /**
     * The body a diaphragm rebuilt from its spec makes (the GUI's rebuilds), as {@link #build} makes it from a
     * file: its scene's topology, its closed shell, {@code built} as what it built; {@code node} is the body's
     * place in the file, for messages.
     */
    public static org.tensim.scene.file.SceneBody body(String name, SceneNode node, DiaphragmSetup.Built built) {
        return new org.tensim.scene.file.SceneBody(name, NAME, built.scene().topology(), null, node, surface(built),
                List.of(), built);
    }

    /**
     * The diaphragm's closed shell (both its surfaces, m) on its nodes, vertex v on node v: what a pressure
     * condition loads and a {@code surface:} region selects.
     */
    private static org.tensim.scene.file.EmbeddedSurface surface(DiaphragmSetup.Built built) {
        org.tensim.io.mesh.TriangleMesh mesh = built.scene().surfaces().mesh();
        org.tensim.model.LinearMapping.Builder m = new org.tensim.model.LinearMapping.Builder(
                built.scene().topology().nodeCount());
        for (int v = 0; v < mesh.vertexCount(); v++) {
            m.add(new int[] {v}, new double[] {1});
        }
        return new org.tensim.scene.file.EmbeddedSurface(mesh, m.build());
    }

    /**
     * Extra loads and supports on its nodes (fixed, force, gravity, motion, pressure) act on top of its own; the
     * conditions that bring bones or muscle are its own keys' business.
     */
    @Override
    public String refusedCondition(String type) {
        return switch (type) {
            case "contact", "sliding" -> "the diaphragm's contacts are its own (keys contact, contact_stiffness,"
                    + " liver_support, abdominal_support; thorax for bones), and its file has no rigid body to touch";
            case "attachment" -> "the diaphragm's attachments to its cage are its own (keys attachment,"
                    + " attach_threshold, band_stiffness); to hold a region, use a fixed condition";
            case "fibres" -> "the diaphragm's muscle load is its own (keys muscle_load, muscle_action,"
                    + " action_line); to add a load, use a force or pressure condition";
            default -> null;
        };
    }

    /** The spec the body's keys give, by the command's own rules ({@link DiaphragmChoices#spec}). */
    public static DiaphragmSpec spec(BodyContext ctx) {
        MapReader r = ctx.keys();
        DiaphragmChoices c = choices(ctx);
        try {
            return c.spec(c.rings == null && Files.isRegularFile(DiaphragmSetup.DEFAULT_MESH)
                    ? DiaphragmSetup.DEFAULT_MESH : null, DiaphragmSpec.PAPER_RINGS);
        } catch (IllegalArgumentException e) {
            throw SceneException.at(r.node(), e.getMessage() + " (the options' names are this body's keys, with _"
                    + " for -)");
        }
    }

    private static DiaphragmChoices choices(BodyContext ctx) {
        MapReader r = ctx.keys();
        DiaphragmChoices c = new DiaphragmChoices();
        c.mesh = r.has("mesh") ? ctx.file(r.scalar("mesh")).normalize() : null;
        c.units = r.has("units") ? r.choice("units", List.of("mm", "m"), "mm") : null;
        c.thicknessMm = in(ctx, "thickness", QuantityKind.LENGTH, MM);
        c.rings = r.has("rings") ? (int) r.integer("rings", 4, 0) : null;
        c.labels = r.has("labels") ? ctx.file(r.scalar("labels")).normalize() : null;
        c.weldMm = in(ctx, "weld_tolerance", QuantityKind.LENGTH, MM);
        c.minPieceFraction = in(ctx, "min_piece_fraction", QuantityKind.NUMBER, null);
        c.boxes = r.has("boxes") ? ctx.file(r.scalar("boxes")).normalize() : null;
        c.thorax = r.has("thorax") ? ctx.folder(r.scalar("thorax")).normalize() : null;
        c.cage = r.has("cage") ? r.choice("cage", List.of("segments", "surfaces"), null) : null;
        c.contact = r.has("contact") ? r.bool("contact", true) : null;
        c.contactPaPerM = in(ctx, "contact_stiffness", QuantityKind.AREAL_STIFFNESS, null);
        c.liverPaPerM = in(ctx, "liver_support", QuantityKind.AREAL_STIFFNESS, null);
        c.abdominalPaPerM = in(ctx, "abdominal_support", QuantityKind.AREAL_STIFFNESS, null);
        c.abdominalPressurePa = in(ctx, "abdominal_pressure", QuantityKind.PRESSURE, PA);
        c.appositionPa = in(ctx, "apposition_pressure", QuantityKind.PRESSURE, PA);
        c.model = r.has("model") ? r.choice("model", List.of("default", "paper"), null) : null;
        c.tissueModel = r.has("tissue_model") ? named(r, "tissue_model", () -> TissueModel.parse(
                r.string("tissue_model"))) : null;
        c.tendonRule = r.has("tendon_rule") ? named(r, "tendon_rule", () -> BoundaryConditions.parse(TendonRule.class,
                r.string("tendon_rule"))) : null;
        c.tendonNormal = r.has("tendon_normal") ? MapReader.vector(r.required("tendon_normal"), QuantityKind.NUMBER,
                ctx.units()) : null;
        c.tendonPointMm = r.has("tendon_point") ? vectorIn(ctx, r.required("tendon_point")) : null;
        c.tendonFraction = in(ctx, "tendon_fraction", QuantityKind.NUMBER, null);
        c.attachMm = in(ctx, "attach_threshold", QuantityKind.LENGTH, MM);
        c.attachment = r.has("attachment") ? named(r, "attachment", () -> BoundaryConditions.parse(
                BoundaryConditions.Attachment.class, r.string("attachment"))) : null;
        c.bandPaPerM = in(ctx, "band_stiffness", QuantityKind.AREAL_STIFFNESS, null);
        c.allSegments = r.bool("band_all_segments", false);
        c.muscleLoad = r.has("muscle_load") ? named(r, "muscle_load", () -> BoundaryConditions.parse(
                BoundaryConditions.MuscleLoad.class, r.string("muscle_load"))) : null;
        c.musclePa = in(ctx, "muscle_action", QuantityKind.PRESSURE, PA);
        c.actionLines = r.has("action_line") ? actionLines(ctx, r.list("action_line")) : null;
        c.ribAmplitude = in(ctx, "rib_amplitude", QuantityKind.NUMBER, null);
        c.periodS = in(ctx, "period", QuantityKind.TIME, Units.SECOND);
        c.ieRatio = in(ctx, "ie_ratio", QuantityKind.NUMBER, null);
        c.pauseShare = in(ctx, "expiratory_pause", QuantityKind.NUMBER, null);
        return c;
    }

    /** A value in the option's own unit (null: SI), null when the key is absent. */
    private static Double in(BodyContext ctx, String key, QuantityKind kind, Unit<?> unit) {
        MapReader r = ctx.keys();
        return r.has(key) ? ctx.units().in(r.scalar(key), kind, unit == null ? kind.unit() : unit) : null;
    }

    private static double[] vectorIn(BodyContext ctx, SceneNode v) {
        if (!v.isList() || v.items().size() != 3) {
            throw SceneException.at(v, "expected a point of three lengths [x, y, z], got " + v.describe());
        }
        double[] p = new double[3];
        for (int i = 0; i < 3; i++) {
            p[i] = ctx.units().in(v.items().get(i), QuantityKind.LENGTH, MM);
        }
        return p;
    }

    /** {@code action_line: [[x, y, radius], ...]}, lengths (the command's X,Y,R). */
    private static List<ActionLines.Line> actionLines(BodyContext ctx, SceneNode list) {
        List<ActionLines.Line> lines = new ArrayList<>();
        for (SceneNode l : list.items()) {
            double[] xyr = vectorIn(ctx, l);
            try {
                lines.add(new ActionLines.Line(1e-3 * xyr[0], 1e-3 * xyr[1], 1e-3 * xyr[2]));
            } catch (IllegalArgumentException e) {
                throw SceneException.at(l, e.getMessage());
            }
        }
        return lines;
    }

    private static <T> T named(MapReader r, String key, java.util.function.Supplier<T> parse) {
        try {
            return parse.get();
        } catch (IllegalArgumentException e) {
            throw SceneException.at(r.node().get(key), e.getMessage());
        }
    }
}

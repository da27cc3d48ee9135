package org.tensim.scene.file;

import java.util.List;
import java.util.Map;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.RigidMotion;
import org.tensim.model.SignedDistance;
import org.tensim.model.Vec3;
import org.tensim.scene.conditions.BreathingLaw;
import org.tensim.scene.conditions.TimeLaw;
import org.tensim.scene.diaphragm.DiaphragmControls;
import org.tensim.scene.diaphragm.HelicalAxisMotion;
import org.tensim.scene.rigid.LawMotion;
import org.tensim.scene.rigid.RigidShapes;
import org.tensim.scene.thorax.DistanceGrid;

/**
 * Reads a {@code type: rigid} body (docs/scenes.md, "Rigid bodies"): exactly one surface,
 * <ul>
 * <li>{@code mesh: {file, units}}: a closed OBJ/STL/PLY surface, its signed distance sampled on a grid of
 * {@code cell} (length, 1.5 mm; {@link DistanceGrid}) with a 20 mm margin;</li>
 * <li>{@code box: {min: [x,y,z], max: [x,y,z]}}, {@code sphere: {centre, radius}}, {@code plane: {point, normal}}
 * (the solid below the plane, away from its normal): exact distances ({@link RigidShapes});</li>
 * </ul>
 * {@code cavity: true} makes the solid the outside of the surface (a box holding a block); and a
 * {@code motion:} (fixed by default):
 * <ul>
 * <li>{@code {type: translation, displacement: [x,y,z], law}}: {@code x0 + u s(t)};</li>
 * <li>{@code {type: rotation, axis: [x,y,z], centre: [x,y,z], angle, law}}: about the axis through the centre by
 * {@code angle s(t)} ({@link LawMotion});</li>
 * <li>{@code {type: helical, axis, point, angle, translation, law}}: the ribs' finite helical axis law
 * ({@link HelicalAxisMotion}), its law a {@code breathing} law whose amplitude scales angle and translation.</li>
 * </ul>
 * Without {@code law} the factor is 1 at every time (a body placed, not moving).
 */
public final class RigidBodies {
    /** The type's name. */
    public static final String TYPE = "rigid";
    /** The keys of a rigid body. */
    public static final List<String> KEYS = List.of("type", "mesh", "box", "sphere", "plane", "cavity", "cell",
            "motion");
    /** The ways of giving its surface. */
    public static final List<String> SHAPES = List.of("mesh", "box", "sphere", "plane");
    /** The motion types. */
    public static final List<String> MOTIONS = List.of("fixed", "translation", "rotation", "helical");
    /** The keys of each motion type. */
    public static final Map<String, List<String>> MOTION_KEYS = Map.of(
            "fixed", List.of("type"),
            "translation", List.of("type", "displacement", "law"),
            "rotation", List.of("type", "axis", "centre", "angle", "law"),
            "helical", List.of("type", "axis", "point", "angle", "translation", "law"));
    /** Half the side of a plane's bounding box, m. */
    static final double PLANE_EXTENT_M = 1000;

    private RigidBodies() {
    }

    /** Reads the rigid body {@code name} written at {@code b}. */
    static RigidBody read(String name, SceneNode b, SceneUnits u, java.nio.file.Path folder,
            Map<String, TimeLaw> laws) {
        MapReader r = new MapReader(b, KEYS);
        List<String> given = SHAPES.stream().filter(r::has).toList();
        if (given.size() != 1) {
            throw SceneException.at(b, "a rigid body needs exactly one surface: one of " + String.join(", ", SHAPES)
                    + (given.isEmpty() ? "" : " (given: " + String.join(", ", given) + ")"));
        }
        String shape = given.get(0);
        SceneNode s = r.required(shape);
        SignedDistance sdf;
        double[] bounds;
        TriangleMesh mesh = null;
        String report = "";
        if (shape.equals("mesh")) {
            double cell = r.positive("cell", QuantityKind.LENGTH, u, DistanceGrid.DEFAULT_CELL_M);
            mesh = new BodyContext(name, r, u, folder).mesh(s, "rigid body", 1e-3, 100).mesh();
            DistanceGrid grid;
            try {
                grid = DistanceGrid.build(mesh, cell, DistanceGrid.DEFAULT_MARGIN_M);
            } catch (IllegalArgumentException e) {
                throw SceneException.at(r.node().get("cell"), e.getMessage());
            }
            sdf = grid;
            bounds = grid.boundsM();
            report = "distance grid: " + grid.report().describe();
        } else {
            if (r.has("cell")) {
                throw SceneException.at(r.node().get("cell"), "cell is the grid spacing of a mesh's distance; a "
                        + shape + " has an exact one");
            }
            MapReader m = new MapReader(s, shape.equals("box") ? List.of("min", "max")
                    : shape.equals("sphere") ? List.of("centre", "radius") : List.of("point", "normal"));
            if (shape.equals("box")) {
                double[] lo = m.vector("min", QuantityKind.LENGTH, u);
                double[] hi = m.vector("max", QuantityKind.LENGTH, u);
                double[] c = new double[3];
                double[] h = new double[3];
                for (int a = 0; a < 3; a++) {
                    if (!(hi[a] > lo[a])) {
                        throw SceneException.at(m.node().get("max"), "max must be above min on axis "
                                + "xyz".charAt(a) + " (a box of positive size)");
                    }
                    c[a] = (lo[a] + hi[a]) / 2;
                    h[a] = (hi[a] - lo[a]) / 2;
                }
                sdf = RigidShapes.box(c, h);
                mesh = org.tensim.scene.rigid.RigidMeshes.box(lo, hi);
                bounds = new double[] {lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]};
            } else if (shape.equals("sphere")) {
                double[] c = m.vector("centre", QuantityKind.LENGTH, u);
                double rad = m.positive("radius", QuantityKind.LENGTH, u, Double.NaN);
                sdf = RigidShapes.sphere(c, rad);
                mesh = org.tensim.scene.rigid.RigidMeshes.sphere(c, rad);
                bounds = new double[] {c[0] - rad, c[1] - rad, c[2] - rad, c[0] + rad, c[1] + rad, c[2] + rad};
            } else {
                double[] p = m.vector("point", QuantityKind.LENGTH, u);
                double[] n = unit(m, "normal", u);
                sdf = RigidShapes.plane(p, n);
                double e = PLANE_EXTENT_M;
                bounds = new double[] {p[0] - e, p[1] - e, p[2] - e, p[0] + e, p[1] + e, p[2] + e};
            }
        }
        boolean cavity = r.bool("cavity", false);
        if (cavity) {
            sdf = RigidShapes.complement(sdf);
        }
        RigidMotion motion = r.has("motion") ? motion(r.required("motion"), u, laws) : RigidMotion.FIXED;
        String motionType = r.has("motion") ? r.required("motion").get("type").text() : "fixed";
        return new RigidBody(name, shape, b, sdf, motion, bounds, mesh, cavity, motionType, report);
    }

    private static RigidMotion motion(SceneNode node, SceneUnits u, Map<String, TimeLaw> laws) {
        if (!node.isMap()) {
            throw SceneException.at(node, "expected a motion {type: " + String.join("|", MOTIONS) + ", ...}, got "
                    + node.describe());
        }
        String type = TimeLaws.typeOf(node, MOTIONS);
        MapReader m = new MapReader(node, MOTION_KEYS.get(type));
        TimeLaw law = m.has("law") ? SceneConditions.law(m.scalar("law"), laws) : TimeLaw.one();
        switch (type) {
            case "fixed":
                return RigidMotion.FIXED;
            case "translation":
                return LawMotion.translation(vec(m.vector("displacement", QuantityKind.LENGTH, u)), law);
            case "rotation":
                return new LawMotion(vec(unit(m, "axis", u)), vec(m.vector("centre", QuantityKind.LENGTH, u)),
                        m.quantity("angle", QuantityKind.ANGLE, u), Vec3.ZERO, law);
            default:
                if (!(law instanceof BreathingLaw breath)) {
                    throw SceneException.at(m.has("law") ? m.node().get("law") : node, "the helical-axis rib law"
                            + " follows a breathing cycle: give law: NAME of a {type: breathing, ...} law");
                }
                double a = breath.amplitude();
                return new HelicalAxisMotion(vec(unit(m, "axis", u)), vec(m.vector("point", QuantityKind.LENGTH, u)),
                        a * m.quantity("angle", QuantityKind.ANGLE, u),
                        a * m.quantity("translation", QuantityKind.LENGTH, u, 0), breath.cycle(),
                        new DiaphragmControls(1, 0));
        }
    }

    private static double[] unit(MapReader m, String key, SceneUnits u) {
        double[] n = m.vector(key, QuantityKind.NUMBER, u);
        double len = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (!(len > 0) || !Double.isFinite(len)) {
            throw SceneException.at(m.node().get(key), "the " + key + " must not be zero");
        }
        return new double[] {n[0] / len, n[1] / len, n[2] / len};
    }

    private static Vec3 vec(double[] v) {
        return new Vec3(v[0], v[1], v[2]);
    }
}

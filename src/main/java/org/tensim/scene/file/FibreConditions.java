package org.tensim.scene.file;

import java.util.BitSet;
import java.util.List;
import java.util.Locale;
import java.util.function.DoubleUnaryOperator;
import org.tensim.model.Topology;
import org.tensim.model.TriangleElement;
import org.tensim.model.Vec3;
import org.tensim.scene.conditions.FibreField;
import org.tensim.scene.conditions.TimeLaw;

/**
 * The {@code fibres} condition: active muscle fibres on the membrane triangles of a region, built by the generic
 * {@link FibreField} as the diaphragm's muscle is.
 * <pre>
 *   - {type: fibres, region: muscle, stress: 20 kPa, law: breath, towards: [0, 0, 0.1], axis: [0, 0, 1]}
 *   - {type: fibres, region: strip, stress: 5 kPa, along: [1, 0, 0]}
 * </pre>
 * Every membrane triangle of the body whose corner nodes all lie in the region (a shell's two faces: each stands
 * for half the thickness) gets an {@link org.tensim.model.ActiveFibre} of the triangle's own thickness t and
 * active stress {@code sigma_a(t) = stress max(0, law(t))} (Pa; a muscle pulls, it does not push, so a law below
 * 0 gives no tension; without a law, 1): a tension {@code T = sigma_a t} (N/m) along the fibre, scaled by the
 * force-length relation as the fibre shortens. The direction is exactly one of
 * <ul>
 * <li>{@code towards} (a point, lengths) with {@code axis} (a vector, any length): the meridian to the point about
 * the axis, {@code f = n x (a x r)} ({@link FibreField#towards}; the diaphragm's fibres, towards its tendon's
 * centre about the vertical);</li>
 * <li>{@code along} (a vector, any length): that direction projected on each triangle ({@link FibreField#along}).</li>
 * </ul>
 * A triangle where the direction is not defined (the meridian on a wall through the axis, {@code along} normal to
 * it) gets no fibre. Refused: a region covering no membrane triangle (a body of springs only), or giving no
 * triangle a fibre.
 */
final class FibreConditions {
    /** The keys of the condition. */
    static final List<String> KEYS = List.of("type", "region", "stress", "law", "towards", "axis", "along");

    private FibreConditions() {
    }

    /** Applies a {@code fibres} condition to the region's nodes of one body. */
    static void apply(MapReader r, SceneBody b, BitSet nodes, TimeLaw law, SceneUnits u, String region) {
        double sigma = r.nonNegative("stress", QuantityKind.PRESSURE, u, Double.NaN);
        FibreField.Direction dir = direction(r, u);
        // One law object for the whole field: the force pass evaluates it once for all its fibres.
        DoubleUnaryOperator stress = time -> sigma * Math.max(0, law.value(time));
        Topology t = b.topology();
        int covered = 0;
        int added = 0;
        int[] p = new int[3];
        int[] q = new int[3];
        Vec3[] y = new Vec3[3];
        for (TriangleElement e : List.copyOf(t.triangles())) {
            boolean in = true;
            for (int k = 0; k < 3; k++) {
                p[k] = e.p(k);
                q[k] = e.q(k);
                in &= nodes.get(p[k]) && nodes.get(q[k]);
            }
            if (!in) {
                continue;
            }
            covered++;
            for (int k = 0; k < 3; k++) {
                y[k] = t.node(p[k]).position().plus(t.node(q[k]).position()).times(0.5);
            }
            added += FibreField.add(t, p, q, y, dir, e.thicknessM(), stress) ? 1 : 0;
        }
        if (covered == 0) {
            throw SceneException.at(r.node().get("region"), "region '" + region + "' covers no membrane triangle of"
                    + " body '" + b.name() + "' (type " + b.type() + ", " + t.triangles().size() + " membrane"
                    + " triangles): fibres act on membrane triangles, e.g. a shell of the material tissue model");
        }
        if (added == 0) {
            throw SceneException.at(r.node().get(r.has("along") ? "along" : "towards"), String.format(Locale.ROOT,
                    "the fibre direction is defined on none of the %d triangles of region '%s' on body '%s'"
                    + " (normal to each, or a meridian on walls through the axis): give a direction in the"
                    + " region's surface", covered, region, b.name()));
        }
    }

    /** The direction rule: exactly one of towards (with axis) and along. */
    private static FibreField.Direction direction(MapReader r, SceneUnits u) {
        if (r.has("towards") == r.has("along")) {
            throw SceneException.at(r.node(), "give exactly one fibre direction: towards: [x, y, z] (a point, with"
                    + " axis: [x, y, z]) or along: [x, y, z] (a direction)");
        }
        if (r.has("along")) {
            if (r.has("axis")) {
                throw SceneException.at(r.node().get("axis"), "axis goes with towards (the meridians about it), not"
                        + " with along");
            }
            return FibreField.along(nonZero(r, "along", r.vector("along", QuantityKind.NUMBER, u)));
        }
        if (!r.has("axis")) {
            throw SceneException.at(r.node().get("towards"), "towards needs axis: [x, y, z], the axis the meridians"
                    + " to the point run about (the diaphragm's: the vertical)");
        }
        double[] c = r.vector("towards", QuantityKind.LENGTH, u);
        return FibreField.towards(new Vec3(c[0], c[1], c[2]), nonZero(r, "axis", r.vector("axis",
                QuantityKind.NUMBER, u)));
    }

    private static Vec3 nonZero(MapReader r, String key, double[] v) {
        Vec3 d = new Vec3(v[0], v[1], v[2]);
        if (!(d.norm() > 0)) {
            throw SceneException.at(r.node().get(key), key + " must not be the zero vector");
        }
        return d;
    }
}

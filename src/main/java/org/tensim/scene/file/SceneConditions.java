package org.tensim.scene.file;

import java.util.BitSet;
import java.util.List;
import java.util.Map;
import org.tensim.model.ForceLaw;
import org.tensim.model.Node;
import org.tensim.model.Vec3;
import org.tensim.scene.conditions.TimeLaw;

/**
 * Reads a scene's {@code conditions:} list and applies each to the bodies' topologies:
 * <pre>
 * conditions:
 *   - {type: fixed, region: bottom}
 *   - {type: fixed, region: floor, axes: [z]}
 *   - {type: force, region: top, direction: [0, -1, 0], magnitude: 400 N, law: wave}
 *   - {type: force, region: top, direction: [0, -1, 0], total: 4 mN, split: mass}
 *   - {type: gravity, acceleration: [0, -9.81, 0], bodies: [liver]}
 *   - {type: motion, region: clamp, displacement: [0, 5 mm, 0], law: start}
 *   - {type: pressure, region: top_face, pressure: 200 Pa, law: breath}
 *   - {type: contact, region: base, with: plate, stiffness: 50 N/m, gap: 0 mm, hard: false}
 *   - {type: attachment, region: back, with: spine, threshold: 3 mm}
 *   - {type: sliding, region: pleura, with: cavity, stiffness: 50 N/m, hard: true}
 *   - {type: fibres, region: muscle, stress: 20 kPa, law: breath, towards: [0, 0, 0.1], axis: [0, 0, 1]}
 * </pre>
 * A fixed region's nodes do not move; with {@code axes} (a list of x, y, z) they are held on those axes only
 * ({@link Node#hold}) and free on the others (all three: fixed). A force acts on every node of the region: {@code magnitude * law(t)} along the unit direction (N a node), or, with
 * {@code total} instead of {@code magnitude}, the total split over the region's nodes (of all its bodies) in equal
 * shares ({@code split: equal}, the default) or by nodal mass ({@code split: mass}), so the region carries
 * {@code total * law(t)} whatever its node count. A
 * motion moves every node of the region to {@code rest + displacement * law(t)}. The law is a name from
 * {@code laws:}; without one the factor is 1. Gravity acts on every node of its bodies (all when absent). A
 * pressure acts on the faces of the body's surface the region covers ({@link SurfaceFaces}): {@code -p law(t) A n}
 * per face, a dead load, refused on a region that covers no face. Contact, attachment and sliding tie the region
 * to the rigid body named by {@code with} ({@link RigidConditions}); contact and sliding {@code with} a deformable
 * body's surface couple the two bodies ({@link BodyCoupling}). Fibres put an active muscle tension on the
 * region's membrane triangles ({@link FibreConditions}).
 */
public final class SceneConditions {
    /** The condition types. */
    public static final List<String> TYPES = List.of("fixed", "force", "gravity", "motion", "pressure", "contact",
            "attachment", "sliding", "fibres");
    /** The keys of each type. */
    public static final Map<String, List<String>> KEYS;

    static {
        Map<String, List<String>> k = new java.util.LinkedHashMap<>();
        k.put("fixed", List.of("type", "region", "axes"));
        k.put("force", List.of("type", "region", "direction", "magnitude", "total", "split", "law"));
        k.put("gravity", List.of("type", "acceleration", "bodies"));
        k.put("motion", List.of("type", "region", "displacement", "law"));
        k.put("pressure", List.of("type", "region", "pressure", "law"));
        k.putAll(RigidConditions.KEYS);
        k.put("fibres", FibreConditions.KEYS);
        KEYS = java.util.Collections.unmodifiableMap(k);
    }

    private SceneConditions() {
    }

    /** Applies every condition of the list (absent: none), in a scene without rigid bodies. */
    public static void apply(SceneNode list, Map<String, SceneBody> bodies, Map<String, SceneRegions.Region> regions,
            Map<String, TimeLaw> laws, SceneUnits u) {
        apply(list, bodies, regions, laws, u, Map.of());
    }

    /**
     * Applies every condition of the list (absent: none); {@code rigids} are the bodies {@code with:} names.
     *
     * @return the contacts and slidings {@code with:} a deformable body ({@link BodyCoupling}), which need the bodies
     *         in one state and so are not applied to a topology here; empty when none
     */
    public static List<BodyCoupling> apply(SceneNode list, Map<String, SceneBody> bodies,
            Map<String, SceneRegions.Region> regions, Map<String, TimeLaw> laws, SceneUnits u,
            Map<String, RigidBody> rigids) {
        List<BodyCoupling> couplings = new java.util.ArrayList<>();
        if (list == null) {
            return couplings;
        }
        if (!list.isList()) {
            throw SceneException.at(list, "expected a list of conditions (- {type: fixed, region: ...}), got "
                    + list.describe());
        }
        for (SceneNode c : list.items()) {
            if (!c.isMap()) {
                throw SceneException.at(c, "expected a condition {type: ..., ...}, got " + c.describe());
            }
            String type = TimeLaws.typeOf(c, TYPES);
            MapReader r = new MapReader(c, KEYS.get(type));
            if (type.equals("gravity")) {
                double[] g = r.vector("acceleration", QuantityKind.ACCELERATION, u);
                SceneNode names = r.optional("bodies");
                List<SceneNode> items = names == null ? null : names.isList() ? names.items() : List.of(names);
                for (SceneBody b : bodies.values()) {
                    boolean on = items == null;
                    for (int i = 0; items != null && i < items.size(); i++) {
                        on |= SceneCheck.bodyName(items.get(i), bodies).equals(b.name());
                    }
                    if (on) {
                        refuse(c, type, b);
                        b.topology().setGravity(new Vec3(g[0], g[1], g[2]));
                    }
                }
                continue;
            }
            if (r.has("region")) {
                for (String name : region(r.scalar("region"), regions).nodes().keySet()) {
                    refuse(c, type, bodies.get(name)); // before the with: body is looked up
                }
            }
            if (BodyCoupling.withDeformable(type, r, bodies)) {
                couplings.addAll(BodyCoupling.read(type, r, bodies, region(r.scalar("region"), regions), u));
                continue;
            }
            RigidBody rigid = RigidConditions.TYPES.contains(type) ? RigidConditions.rigid(r, bodies, rigids) : null;
            SceneRegions.Region region = region(r.scalar("region"), regions);
            TimeLaw law = r.has("law") ? law(r.scalar("law"), laws) : TimeLaw.one();
            double[] share = type.equals("force") ? shares(r, region, bodies) : null;
            for (Map.Entry<String, BitSet> e : region.nodes().entrySet()) {
                SceneBody b = bodies.get(e.getKey());
                try {
                    if (rigid != null) {
                        RigidConditions.apply(type, r, rigid, b, e.getValue(), u);
                    } else if (type.equals("fibres")) {
                        FibreConditions.apply(r, b, e.getValue(), law, u, region.name());
                    } else if (type.equals("pressure")) {
                        pressure(r, b, e.getValue(), law, u, region.name());
                    } else {
                        applyTo(type, r, b, e.getValue(), law, u, share);
                    }
                } catch (IllegalStateException ex) {
                    throw SceneException.at(c, ex.getMessage() + " (body '" + b.name() + "', region '"
                            + region.name() + "')");
                }
            }
        }
        return couplings;
    }

    /** Refuses a condition its body's type cannot take ({@link BodyType#refusedCondition}), naming its type key. */
    private static void refuse(SceneNode c, String type, SceneBody b) {
        String why = BodyTypes.get(b.type()).refusedCondition(type);
        if (why != null) {
            throw SceneException.at(c.get("type"), "a " + type + " condition cannot act on body '" + b.name()
                    + "' (type " + b.type() + "): " + why);
        }
    }

    private static void applyTo(String type, MapReader r, SceneBody b, BitSet nodes, TimeLaw law, SceneUnits u,
            double[] share) {
        List<Node> all = b.topology().nodes();
        if (type.equals("fixed")) {
            int axes = r.has("axes") ? axes(r.required("axes")) : 7;
            nodes.stream().forEach(i -> {
                if (axes == 7) {
                    all.get(i).fix();
                } else {
                    all.get(i).hold(axes);
                }
            });
        } else if (type.equals("force")) {
            double[] dir = r.vector("direction", QuantityKind.NUMBER, u);
            Vec3 d = new Vec3(dir[0], dir[1], dir[2]);
            if (!(d.norm() > 0)) {
                throw SceneException.at(r.node().get("direction"), "the direction must not be zero");
            }
            Vec3 unit = d.normalized();
            if (share == null) {
                double m = r.nonNegative("magnitude", QuantityKind.FORCE, u, Double.NaN);
                ForceLaw f = nodalForce(unit, m, law);
                nodes.stream().forEach(i -> b.topology().applyForce(all.get(i), f));
            } else {
                double total = r.nonNegative("total", QuantityKind.FORCE, u, Double.NaN);
                nodes.stream().forEach(i -> b.topology().applyForce(all.get(i), nodalForce(unit,
                        total * (share[1] > 0 ? all.get(i).mass() / share[1] : 1 / share[0]), law)));
            }
        } else {
            double[] dv = r.vector("displacement", QuantityKind.LENGTH, u);
            nodes.stream().forEach(i -> all.get(i).drive((t, rest, out, o) -> {
                double s = law.value(t);
                out[o] = rest.x() + dv[0] * s;
                out[o + 1] = rest.y() + dv[1] * s;
                out[o + 2] = rest.z() + dv[2] * s;
            }));
        }
    }

    /** As ForceLaw.sinusoid writes its force: the unit direction times the magnitude (N), then times the law. */
    private static ForceLaw nodalForce(Vec3 unit, double magnitudeN, TimeLaw law) {
        double fx = unit.x() * magnitudeN;
        double fy = unit.y() * magnitudeN;
        double fz = unit.z() * magnitudeN;
        return (t, out, o) -> {
            double s = law.value(t);
            out[o] += fx * s;
            out[o + 1] += fy * s;
            out[o + 2] += fz * s;
        };
    }

    /**
     * A force's split: null for {@code magnitude} (N a node); for {@code total}, {node count, 0} (equal shares) or
     * {node count, total mass in kg} (by nodal mass) over the region's nodes in all its bodies. Exactly one of the two.
     */
    private static double[] shares(MapReader r, SceneRegions.Region region, Map<String, SceneBody> bodies) {
        if (r.has("magnitude") == r.has("total")) {
            throw SceneException.at(r.node(), "give either magnitude (N on each node) or total (N split over the"
                    + " region's nodes)" + (r.has("total") ? ", not both" : ""));
        }
        if (!r.has("total")) {
            if (r.has("split")) {
                throw SceneException.at(r.node().get("split"), "split goes with total, not magnitude (N a node)");
            }
            return null;
        }
        boolean byMass = r.choice("split", List.of("equal", "mass"), "equal").equals("mass");
        double count = 0;
        double mass = 0;
        for (Map.Entry<String, BitSet> e : region.nodes().entrySet()) {
            List<Node> all = bodies.get(e.getKey()).topology().nodes();
            count += e.getValue().cardinality();
            for (int i = e.getValue().nextSetBit(0); i >= 0; i = e.getValue().nextSetBit(i + 1)) {
                mass += all.get(i).mass();
            }
        }
        return new double[] {count, byMass ? mass : 0};
    }

    /** The pressure's nodal forces: {@code p law(t)} times those of a unit pressure on the faces covered. */
    private static void pressure(MapReader r, SceneBody b, BitSet nodes, TimeLaw law, SceneUnits u, String region) {
        double p = r.quantity("pressure", QuantityKind.PRESSURE, u);
        if (b.surface() == null) {
            throw SceneException.at(r.node().get("region"), "body '" + b.name() + "' (type " + b.type() + ") carries"
                    + " no surface for a pressure to act on: give it as nodal forces (type: force)");
        }
        BitSet faces = SurfaceFaces.faces(b.surface(), nodes);
        if (faces.isEmpty()) {
            throw SceneException.at(r.node().get("region"), "region '" + region + "' covers no face of body '"
                    + b.name() + "''s surface (none of its " + b.surface().mesh().triangleCount() + " triangles has"
                    + " the nodes of its three vertices among the region's " + nodes.cardinality() + "): select"
                    + " a part of the surface, e.g. the intersection of surface: " + b.name() + " with a box");
        }
        double[] unit = SurfaceFaces.unitPressureForces(b.surface(), faces);
        List<Node> all = b.topology().nodes();
        // The mapping's nodes are the body's first ones (a volume's lattice is its whole topology).
        for (int i = 0; i < Math.min(all.size(), unit.length / 3); i++) {
            double fx = p * unit[3 * i];
            double fy = p * unit[3 * i + 1];
            double fz = p * unit[3 * i + 2];
            if (fx == 0 && fy == 0 && fz == 0) {
                continue;
            }
            b.topology().applyForce(all.get(i), (t, out, o) -> {
                double s = law.value(t);
                out[o] += fx * s;
                out[o + 1] += fy * s;
                out[o + 2] += fz * s;
            });
        }
    }

    /** The mask (bit 0 x, 1 y, 2 z) of an {@code axes: [x, z]} list: each axis once, at least one. */
    static int axes(SceneNode list) {
        List<SceneNode> items = list.isList() ? list.items() : List.of(list);
        if (items.isEmpty()) {
            throw SceneException.at(list, "expected a list of axes among x, y, z, e.g. [x, z]; got an empty list");
        }
        int mask = 0;
        for (SceneNode a : items) {
            int axis = a.isScalar() ? List.of("x", "y", "z").indexOf(a.text()) : -1;
            if (axis < 0) {
                throw SceneException.at(a, a.describe() + " is not an axis (expected x, y or z)");
            }
            if ((mask >> axis & 1) != 0) {
                throw SceneException.at(a, "axis " + a.text() + " is given twice");
            }
            mask |= 1 << axis;
        }
        return mask;
    }

    static SceneRegions.Region region(SceneNode name, Map<String, SceneRegions.Region> regions) {
        SceneRegions.Region r = regions.get(name.text());
        if (r == null) {
            throw SceneException.at(name, name.describe() + " is not a region of this file"
                    + DidYouMean.suggest(name.text(), regions.keySet()) + (regions.isEmpty() ? " (it has none)"
                    : " (regions: " + String.join(", ", regions.keySet()) + ")"));
        }
        return r;
    }

    static TimeLaw law(SceneNode name, Map<String, TimeLaw> laws) {
        TimeLaw l = laws.get(name.text());
        if (l == null) {
            throw SceneException.at(name, name.describe() + " is not a law of this file"
                    + DidYouMean.suggest(name.text(), laws.keySet()) + (laws.isEmpty() ? " (it has none)"
                    : " (laws: " + String.join(", ", laws.keySet()) + ")"));
        }
        return l;
    }
}

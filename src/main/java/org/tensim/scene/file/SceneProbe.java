package org.tensim.scene.file;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import java.util.Map;

/**
 * What a run writes, one CSV column per value, units in the names:
 * <ul>
 * <li>{@code {body: b, node: 13}}: the node's displacement, {@code NAME_dx_m, NAME_dy_m, NAME_dz_m};</li>
 * <li>{@code {body: b, vertex: 120}}: the displacement of vertex 120 of the surface the body carries (a volume's
 * embedded surface), {@code sum_k w_k u_k} over the nodes carrying it, {@code NAME_dx_m, ...};</li>
 * <li>{@code {body: b, region: r}} (or {@code quantity: mean}): the mean displacement of the region's nodes,
 * {@code NAME_mean_dx_m, ...};</li>
 * <li>{@code {body: b, region: r, quantity: extents}}: the bounding box of the region's current positions,
 * {@code NAME_min_x_m, NAME_max_x_m, NAME_min_y_m, ...};</li>
 * <li>{@code {body: b, region: r, quantity: energy}} (or {@code {body: b, quantity: energy}}, the whole body): the
 * elastic energy of the springs with both ends in the region, {@code sum 1/2 k (l - l0)^2}, and the kinetic energy
 * of its free nodes, {@code sum 1/2 m v^2}, {@code NAME_elastic_J, NAME_kinetic_J} (membrane triangles, shear
 * elements and contact penalties are not counted);</li>
 * <li>{@code {rigid: plate}}: a rigid body's pose {@code x = R x0 + c}: c and R's rotation vector (axis times angle),
 * {@code NAME_cx_m, NAME_cy_m, NAME_cz_m, NAME_rx_rad, NAME_ry_rad, NAME_rz_rad};</li>
 * <li>{@code {body: b, with: plate}} ({@code quantity: contact}): over the body's contact (and sliding) pairs with
 * the rigid body, the largest penetration {@code max(0, g - d)} and the largest separation {@code max(0, d - g)},
 * d a node's signed distance to the rigid solid and g its gap, {@code NAME_penetration_m, NAME_separation_m}; with a
 * deformable body, the same over the followers of the body's contacts or slidings with that body's surface
 * ({@link BodyCoupling}), d the distance to the paired triangle's plane.</li>
 * </ul>
 * {@code body} may be left out when the scene has one body.
 *
 * @param name     the probe's name (its key under {@code probes:}), the columns' prefix
 * @param body     the body's name
 * @param nodes    the nodes it reads
 * @param quantity displacement (one node or surface vertex), mean, extents, energy or pose (body: the rigid body's
 *                 name, no node)
 * @param weights  the nodes' weights of a surface vertex (summing to 1); for a contact probe, each node's gap (m);
 *                 null for a node or a region, and for a contact probe with a deformable body
 * @param with     the rigid body of a contact probe; null for the others
 */
public record SceneProbe(String name, String body, int[] nodes, String quantity, double[] weights, String with) {
    /** A probe of a node, a region or a surface vertex. */
    public SceneProbe(String name, String body, int[] nodes, String quantity, double[] weights) {
        this(name, body, nodes, quantity, weights, null);
    }

    /** The keys of a probe. */
    public static final List<String> KEYS = List.of("body", "node", "vertex", "region", "quantity", "rigid", "with");

    /** A probe of a node or a region. */
    public SceneProbe(String name, String body, int[] nodes, String quantity) {
        this(name, body, nodes, quantity, null);
    }
    /** The quantities of a region probe. */
    public static final List<String> REGION_QUANTITIES = List.of("mean", "extents", "energy");

    /** The probe's CSV columns. */
    public List<String> columns() {
        List<String> c = new ArrayList<>();
        if (quantity.equals("contact")) {
            c.add(name + "_penetration_m");
            c.add(name + "_separation_m");
        } else if (quantity.equals("energy")) {
            c.add(name + "_elastic_J");
            c.add(name + "_kinetic_J");
        } else if (quantity.equals("pose")) {
            for (String a : List.of("cx_m", "cy_m", "cz_m", "rx_rad", "ry_rad", "rz_rad")) {
                c.add(name + "_" + a);
            }
        } else if (quantity.equals("extents")) {
            for (String a : List.of("x", "y", "z")) {
                c.add(name + "_min_" + a + "_m");
                c.add(name + "_max_" + a + "_m");
            }
        } else {
            String p = quantity.equals("mean") ? name + "_mean_" : name + "_";
            for (String a : List.of("dx", "dy", "dz")) {
                c.add(p + a + "_m");
            }
        }
        return c;
    }

    /** Reads the {@code probes:} block (absent: none) of a scene without couplings between deformable bodies. */
    static List<SceneProbe> read(SceneNode block, Map<String, SceneBody> bodies,
            Map<String, SceneRegions.Region> regions, Map<String, RigidBody> rigids) {
        return read(block, bodies, regions, rigids, List.of());
    }

    /** Reads the {@code probes:} block (absent: none); a contact probe may read a {@link BodyCoupling}. */
    static List<SceneProbe> read(SceneNode block, Map<String, SceneBody> bodies,
            Map<String, SceneRegions.Region> regions, Map<String, RigidBody> rigids, List<BodyCoupling> couplings) {
        List<SceneProbe> out = new ArrayList<>();
        if (block == null) {
            return out;
        }
        if (!block.isMap()) {
            throw SceneException.at(block, "expected a map of named probes, got " + block.describe());
        }
        for (Map.Entry<String, SceneNode> e : block.entries().entrySet()) {
            MapReader r = new MapReader(e.getValue(), KEYS);
            if (r.has("rigid")) {
                out.add(pose(e.getKey(), r, rigids));
                continue;
            }
            String body;
            if (r.has("body")) {
                body = SceneCheck.bodyName(r.scalar("body"), bodies);
            } else if (bodies.size() == 1) {
                body = bodies.keySet().iterator().next();
            } else {
                throw SceneException.at(r.node(), "missing required key 'body' (the scene has "
                        + bodies.size() + " bodies: " + String.join(", ", bodies.keySet()) + ")");
            }
            if (r.has("with") && bodies.containsKey(r.scalar("with").text())) {
                out.add(coupled(e.getKey(), body, r, couplings));
                continue;
            }
            if (r.has("with")) {
                out.add(contact(e.getKey(), body, bodies.get(body), r, rigids));
                continue;
            }
            int ways = (r.has("node") ? 1 : 0) + (r.has("vertex") ? 1 : 0) + (r.has("region") ? 1 : 0);
            if (ways == 0 && r.has("quantity") && r.scalar("quantity").text().equals("energy")) {
                out.add(new SceneProbe(e.getKey(), body, java.util.stream.IntStream.range(0,
                        bodies.get(body).topology().nodeCount()).toArray(), "energy"));
                continue;
            }
            if (ways != 1) {
                throw SceneException.at(r.node(), "give one of node (an index), vertex (a surface vertex's index) or"
                        + " region (a name), or quantity: energy for the whole body");
            }
            if (r.has("vertex")) {
                out.add(vertex(e.getKey(), body, bodies.get(body), r));
            } else if (r.has("node")) {
                SceneNode n = r.scalar("node");
                long k = MapReader.integer(n, 0);
                SceneBody b = bodies.get(body);
                if (k >= b.topology().nodeCount()) {
                    throw SceneException.at(n, "node " + k + " does not exist: body '" + body + "' has "
                            + b.topology().nodeCount() + " nodes");
                }
                r.choice("quantity", List.of("displacement"), "displacement");
                out.add(new SceneProbe(e.getKey(), body, new int[] {(int) k}, "displacement"));
            } else {
                SceneRegions.Region reg = SceneConditions.region(r.scalar("region"), regions);
                BitSet s = reg.in(body);
                if (s == null) {
                    throw SceneException.at(r.node().get("region"), "region '" + reg.name() + "' is not on body '"
                            + body + "'");
                }
                out.add(new SceneProbe(e.getKey(), body, s.stream().toArray(),
                        r.choice("quantity", REGION_QUANTITIES, "mean")));
            }
        }
        return out;
    }

    private static SceneProbe contact(String name, String body, SceneBody b, MapReader r,
            Map<String, RigidBody> rigids) {
        for (String k : List.of("node", "vertex", "region")) {
            if (r.has(k)) {
                throw SceneException.at(r.node().get(k), "a contact probe reads every pair of the body with the rigid"
                        + " body: leave out " + k);
            }
        }
        RigidBody rigid = RigidConditions.rigid(r, bodies(b), rigids);
        r.choice("quantity", List.of("contact"), "contact");
        List<Integer> nodes = new ArrayList<>();
        List<Double> gaps = new ArrayList<>();
        for (org.tensim.model.ContactPair p : b.topology().contacts()) {
            if (b.topology().contactBodies().get(p.body()).name().equals(rigid.name())) {
                nodes.add(p.node());
                gaps.add(p.gapM());
            }
        }
        if (nodes.isEmpty()) {
            throw SceneException.at(r.node().get("with"), "body '" + body + "' has no contact or sliding with rigid"
                    + " body '" + rigid.name() + "'");
        }
        return new SceneProbe(name, body, nodes.stream().mapToInt(Integer::intValue).toArray(), "contact",
                gaps.stream().mapToDouble(Double::doubleValue).toArray(), rigid.name());
    }

    /** A contact probe on the body's couplings with a deformable body: its followers, no gaps (the term has them). */
    private static SceneProbe coupled(String name, String body, MapReader r, List<BodyCoupling> couplings) {
        for (String k : List.of("node", "vertex", "region")) {
            if (r.has(k)) {
                throw SceneException.at(r.node().get(k), "a contact probe reads every follower of the body's"
                        + " couplings with the other body: leave out " + k);
            }
        }
        String with = r.scalar("with").text();
        r.choice("quantity", List.of("contact"), "contact");
        int[] nodes = couplings.stream().filter(c -> c.body().equals(body) && c.with().equals(with))
                .flatMapToInt(c -> java.util.Arrays.stream(c.followers())).toArray();
        if (nodes.length == 0) {
            throw SceneException.at(r.node().get("with"), "body '" + body + "' has no contact or sliding with body '"
                    + with + "'");
        }
        return new SceneProbe(name, body, nodes, "contact", null, with);
    }

    private static Map<String, SceneBody> bodies(SceneBody b) {
        return Map.of(b.name(), b);
    }

    private static SceneProbe pose(String name, MapReader r, Map<String, RigidBody> rigids) {
        SceneNode n = r.scalar("rigid");
        for (String k : List.of("body", "node", "vertex", "region")) {
            if (r.has(k)) {
                throw SceneException.at(r.node().get(k), "a rigid body's probe is its pose: leave out " + k);
            }
        }
        if (!rigids.containsKey(n.text())) {
            throw SceneException.at(n, n.describe() + " is not a rigid body of this file"
                    + DidYouMean.suggest(n.text(), rigids.keySet()) + (rigids.isEmpty() ? " (it has none)"
                    : " (rigid bodies: " + String.join(", ", rigids.keySet()) + ")"));
        }
        r.choice("quantity", List.of("pose"), "pose");
        return new SceneProbe(name, n.text(), new int[0], "pose");
    }

    private static SceneProbe vertex(String name, String body, SceneBody b, MapReader r) {
        SceneNode n = r.scalar("vertex");
        if (b.surface() == null) {
            throw SceneException.at(n, "body '" + body + "' (type " + b.type() + ") carries no surface: probe a node"
                    + " or a region");
        }
        org.tensim.model.LinearMapping m = b.surface().mapping();
        long k = MapReader.integer(n, 0);
        if (k >= m.pointCount()) {
            throw SceneException.at(n, "vertex " + k + " does not exist: body '" + body + "''s surface has "
                    + m.pointCount() + " (0 to " + (m.pointCount() - 1) + ")");
        }
        int v = (int) k;
        int[] nodes = new int[m.entries(v)];
        double[] w = new double[nodes.length];
        for (int i = 0; i < nodes.length; i++) {
            nodes[i] = m.node(v, i);
            w[i] = m.weight(v, i);
        }
        r.choice("quantity", List.of("displacement"), "displacement");
        return new SceneProbe(name, body, nodes, "displacement", w);
    }
}

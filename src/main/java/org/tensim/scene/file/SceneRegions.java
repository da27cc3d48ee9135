package org.tensim.scene.file;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.BitSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.io.mesh.MeshFormatException;
import org.tensim.io.mesh.VertexLabel;
import org.tensim.io.mesh.VertexLabelsFile;
import org.tensim.model.Node;

/**
 * Reads a scene's {@code regions:} block and resolves each region to the nodes it selects in each of its bodies.
 * A region names its bodies ({@code bodies: [a, b]} or {@code body: a}; all bodies when absent) and one way of
 * choosing:
 * <ul>
 * <li>{@code box: {min: [x,y,z], max: [x,y,z], frame: absolute|relative}}: nodes inside the box (faces included);
 * in the relative frame each coordinate is a fraction of the body's bounding box (0 its min, 1 its max);</li>
 * <li>{@code sphere: {centre: [x,y,z], radius: r, frame: ...}}: relative radius is a fraction of the bounding
 * box's diagonal;</li>
 * <li>{@code plane: {point: [x,y,z], normal: [x,y,z], frame: ...}}: the half-space the normal points into, the
 * plane included;</li>
 * <li>{@code indices: [0, 1, 2]}: vertices by 0-based index;</li>
 * <li>{@code labels: {file: f.labels, label: tendon}}: the vertices a {@link VertexLabelsFile} gives that label;</li>
 * <li>{@code surface: BODY}: the nodes that carry the body's surface (a volume's embedded surface: each vertex's
 * node of largest weight), on that body only; intersected with a box or a plane it is a part of the surface, on
 * whose faces a pressure acts ({@link SurfaceFaces});</li>
 * <li>{@code part: NAME}: a part the body's type declares ({@link BodyType#parts}: a diaphragm's tendon, muscle,
 * upper, lower, attached, free, apposition, apex; a shell's upper and lower), on every body of the region;</li>
 * <li>{@code union|intersection|difference: [r1, r2, ...]}: of other regions (difference: the first less the
 * others).</li>
 * </ul>
 * Geometric tests include points within 1e-9 of the bounding box's diagonal of a face or the plane, so that
 * nodes lying on a face are selected. A region that selects no node of one of its bodies is refused.
 */
public final class SceneRegions {
    /** Ways of choosing nodes. */
    public static final List<String> KINDS = List.of("box", "sphere", "plane", "indices", "labels", "surface",
            "part", "union", "intersection", "difference");
    /** The keys of a region. */
    public static final List<String> KEYS;
    /** The keys of each geometric kind. */
    public static final Map<String, List<String>> KIND_KEYS = Map.of(
            "box", List.of("min", "max", "frame"),
            "sphere", List.of("centre", "radius", "frame"),
            "plane", List.of("point", "normal", "frame"),
            "labels", List.of("file", "label"));
    private static final List<String> FRAMES = List.of("absolute", "relative");
    private static final double TOLERANCE = 1e-9;

    static {
        List<String> k = new ArrayList<>(List.of("body", "bodies"));
        k.addAll(KINDS);
        KEYS = List.copyOf(k);
    }

    /** A region: its name, where it is written and the nodes it selects in each of its bodies. */
    public record Region(String name, SceneNode node, Map<String, BitSet> nodes) {
        /** The nodes selected in body {@code b}, or null when the region is not on that body. */
        public BitSet in(String body) {
            return nodes.get(body);
        }
    }

    private final SceneNode block;
    private final Map<String, SceneBody> bodies;
    private final SceneUnits units;
    private final Path folder;
    private final Map<String, Region> done = new LinkedHashMap<>();
    private final List<String> resolving = new ArrayList<>();
    private java.util.Set<String> rigid = java.util.Set.of();

    private SceneRegions(SceneNode block, Map<String, SceneBody> bodies, SceneUnits units, Path folder) {
        this.block = block;
        this.bodies = bodies;
        this.units = units;
        this.folder = folder;
    }

    /** Every region of the block, resolved, in file order; an absent block is none. */
    public static Map<String, Region> read(SceneNode block, Map<String, SceneBody> bodies, SceneUnits u,
            Path folder) {
        return read(block, bodies, u, folder, java.util.Set.of());
    }

    /** As {@link #read(SceneNode, Map, SceneUnits, Path)}, refusing a region on one of the rigid bodies named. */
    public static Map<String, Region> read(SceneNode block, Map<String, SceneBody> bodies, SceneUnits u,
            Path folder, java.util.Set<String> rigid) {
        if (block == null) {
            return Map.of();
        }
        if (!block.isMap()) {
            throw SceneException.at(block, "expected a map of named regions, got " + block.describe());
        }
        SceneRegions r = new SceneRegions(block, bodies, u, folder);
        r.rigid = rigid;
        for (String name : block.entries().keySet()) {
            r.resolve(name, block.get(name));
        }
        Map<String, Region> inOrder = new LinkedHashMap<>();
        for (String name : block.entries().keySet()) {
            inOrder.put(name, r.done.get(name));
        }
        return inOrder;
    }

    private Region resolve(String name, SceneNode node) {
        Region known = done.get(name);
        if (known != null) {
            return known;
        }
        if (resolving.contains(name)) {
            throw SceneException.at(node, "region '" + name + "' is defined through itself ("
                    + String.join(" -> ", resolving) + " -> " + name + ")");
        }
        resolving.add(name);
        MapReader r = new MapReader(node, KEYS);
        List<String> kinds = new ArrayList<>();
        for (String k : KINDS) {
            if (r.has(k)) {
                kinds.add(k);
            }
        }
        if (kinds.size() != 1) {
            throw SceneException.at(node, (kinds.isEmpty() ? "no way of choosing nodes" : "more than one way of"
                    + " choosing nodes (" + String.join(", ", kinds) + ")") + "; give exactly one of "
                    + String.join(", ", KINDS));
        }
        String kind = kinds.get(0);
        Map<String, BitSet> sel = new LinkedHashMap<>();
        for (String b : kind.equals("surface") ? surfaceBody(r) : bodyNames(r)) {
            SceneBody body = bodies.get(b);
            BitSet s = select(kind, r.required(kind), body);
            if (s.isEmpty()) {
                double[] bb = body.bounds();
                throw SceneException.at(node, "region '" + name + "' selects no node of body '" + b + "' (its nodes"
                        + " lie in " + SceneCheck.box(bb) + "); widen it or check its frame and units");
            }
            sel.put(b, s);
        }
        resolving.remove(name);
        Region region = new Region(name, node, sel);
        done.put(name, region);
        return region;
    }

    private List<String> bodyNames(MapReader r) {
        List<String> names = new ArrayList<>();
        if (r.has("body") && r.has("bodies")) {
            throw SceneException.at(r.node().get("bodies"), "give body or bodies, not both");
        }
        SceneNode v = r.has("body") ? r.scalar("body") : r.optional("bodies");
        if (v == null) {
            names.addAll(bodies.keySet());
            return names;
        }
        List<SceneNode> items = v.isList() ? v.items() : List.of(v);
        for (SceneNode i : items) {
            names.add(bodyName(i));
        }
        if (names.isEmpty()) {
            throw SceneException.at(v, "expected at least one body name");
        }
        return names;
    }

    private BitSet select(String kind, SceneNode v, SceneBody body) {
        switch (kind) {
            case "box":
            case "sphere":
            case "plane":
                return geometric(kind, v, body);
            case "indices":
                return indices(v, body);
            case "labels":
                return labels(v, body);
            case "surface":
                return surface(v, body);
            case "part":
                return part(v, body);
            default:
                return combination(kind, v, body);
        }
    }

    private BitSet geometric(String kind, SceneNode v, SceneBody body) {
        MapReader r = new MapReader(v, KIND_KEYS.get(kind));
        boolean relative = r.choice("frame", FRAMES, "absolute").equals("relative");
        QuantityKind q = relative ? QuantityKind.NUMBER : QuantityKind.LENGTH;
        double[] bb = body.bounds();
        double diag = Math.sqrt(sq(bb[3] - bb[0]) + sq(bb[4] - bb[1]) + sq(bb[5] - bb[2]));
        double tol = TOLERANCE * (diag > 0 ? diag : 1);
        BitSet s = new BitSet();
        double[] a;
        double[] c;
        double radius = 0;
        if (kind.equals("box")) {
            a = place(r.vector("min", q, units), bb, relative);
            c = place(r.vector("max", q, units), bb, relative);
            for (int i = 0; i < 3; i++) {
                if (a[i] > c[i]) {
                    throw SceneException.at(r.node().get("max"), "max is below min on axis " + "xyz".charAt(i));
                }
            }
        } else if (kind.equals("sphere")) {
            a = place(r.vector("centre", q, units), bb, relative);
            c = null;
            radius = r.quantity("radius", q, units) * (relative ? diag : 1);
            if (!(radius > 0)) {
                throw SceneException.at(r.node().get("radius"), "the radius must be > 0");
            }
        } else {
            a = place(r.vector("point", q, units), bb, relative);
            c = r.vector("normal", QuantityKind.NUMBER, units);
            double len = Math.sqrt(sq(c[0]) + sq(c[1]) + sq(c[2]));
            if (!(len > 0)) {
                throw SceneException.at(r.node().get("normal"), "the normal must not be zero");
            }
            for (int i = 0; i < 3; i++) {
                c[i] /= len;
            }
        }
        for (Node n : body.topology().nodes()) {
            double[] p = {n.position().x(), n.position().y(), n.position().z()};
            boolean in;
            if (kind.equals("box")) {
                in = true;
                for (int i = 0; i < 3; i++) {
                    in &= p[i] >= a[i] - tol && p[i] <= c[i] + tol;
                }
            } else if (kind.equals("sphere")) {
                in = Math.sqrt(sq(p[0] - a[0]) + sq(p[1] - a[1]) + sq(p[2] - a[2])) <= radius + tol;
            } else {
                in = (p[0] - a[0]) * c[0] + (p[1] - a[1]) * c[1] + (p[2] - a[2]) * c[2] >= -tol;
            }
            if (in) {
                s.set(n.id());
            }
        }
        return s;
    }

    private static double[] place(double[] v, double[] bb, boolean relative) {
        if (!relative) {
            return v;
        }
        return new double[] {bb[0] + v[0] * (bb[3] - bb[0]), bb[1] + v[1] * (bb[4] - bb[1]),
            bb[2] + v[2] * (bb[5] - bb[2])};
    }

    private static BitSet indices(SceneNode v, SceneBody body) {
        if (!v.isList()) {
            throw SceneException.at(v, "expected a list of vertex indices [0, 1, ...], got " + v.describe());
        }
        BitSet s = new BitSet();
        for (SceneNode i : v.items()) {
            long k = MapReader.integer(i, 0);
            if (k >= body.vertexCount()) {
                throw SceneException.at(i, "vertex " + k + " does not exist: body '" + body.name() + "' has "
                        + body.vertexCount() + " (0 to " + (body.vertexCount() - 1) + ")");
            }
            s.set(body.nodeOfVertex((int) k));
        }
        return s;
    }

    private List<String> surfaceBody(MapReader r) {
        if (r.has("body") || r.has("bodies")) {
            throw SceneException.at(r.node().get(r.has("body") ? "body" : "bodies"), "a surface region is on the body"
                    + " it names (surface: BODY); leave out body and bodies");
        }
        return List.of(bodyName(r.scalar("surface")));
    }

    private String bodyName(SceneNode n) {
        if (n.isScalar() && rigid.contains(n.text())) {
            throw SceneException.at(n, "body '" + n.text() + "' is rigid: it has no nodes for a region to select;"
                    + " a condition refers to it by with: " + n.text());
        }
        return SceneCheck.bodyName(n, bodies);
    }

    private static BitSet surface(SceneNode v, SceneBody body) {
        if (body.surface() == null) {
            throw SceneException.at(v, "body '" + body.name() + "' (type " + body.type() + ") carries no surface: "
                    + "select its nodes by a box, a sphere, a plane, indices or labels");
        }
        BitSet s = new BitSet();
        for (int n : SurfaceFaces.carriers(body.surface().mapping())) {
            s.set(n);
        }
        return s;
    }

    private static BitSet part(SceneNode v, SceneBody body) {
        if (!v.isScalar()) {
            throw SceneException.at(v, "expected the name of a part of body '" + body.name() + "', got "
                    + v.describe());
        }
        Map<String, BitSet> parts = BodyTypes.get(body.type()).parts(body);
        if (parts.isEmpty()) {
            throw SceneException.at(v, "body '" + body.name() + "' (type " + body.type() + ") declares no parts:"
                    + " select its nodes by a box, a sphere, a plane, indices or labels");
        }
        BitSet s = parts.get(v.text());
        if (s == null) {
            throw SceneException.at(v, "\"" + v.text() + "\" is not a part of body '" + body.name() + "' (type "
                    + body.type() + ")" + DidYouMean.suggest(v.text(), parts.keySet()) + " (its parts: "
                    + String.join(", ", parts.keySet()) + ")");
        }
        return (BitSet) s.clone();
    }

    private BitSet labels(SceneNode v, SceneBody body) {
        MapReader r = new MapReader(v, KIND_KEYS.get("labels"));
        Path f = BodyContext.file(r.scalar("file"), folder);
        SceneNode ln = r.scalar("label");
        VertexLabel label;
        try {
            label = VertexLabel.parse(ln.text());
        } catch (IllegalArgumentException e) {
            throw SceneException.at(ln, e.getMessage());
        }
        VertexLabel[] all;
        try {
            all = VertexLabelsFile.read(f, body.vertexCount());
        } catch (IOException | MeshFormatException e) {
            throw SceneException.at(r.node().get("file"), e.getMessage());
        }
        BitSet s = new BitSet();
        for (int i = 0; i < all.length; i++) {
            if (all[i] == label) {
                s.set(body.nodeOfVertex(i));
            }
        }
        return s;
    }

    private BitSet combination(String kind, SceneNode v, SceneBody body) {
        if (!v.isList() || v.items().isEmpty()) {
            throw SceneException.at(v, "expected a list of region names, got " + v.describe());
        }
        BitSet s = null;
        for (SceneNode i : v.items()) {
            if (!i.isScalar() || block.get(i.text()) == null) {
                throw SceneException.at(i, i.describe() + " is not a region of this file"
                        + (i.isScalar() ? DidYouMean.suggest(i.text(), block.entries().keySet()) : ""));
            }
            BitSet part = resolve(i.text(), block.get(i.text())).in(body.name());
            if (part == null) {
                throw SceneException.at(i, "region '" + i.text() + "' is not on body '" + body.name() + "'");
            }
            if (s == null) {
                s = (BitSet) part.clone();
            } else if (kind.equals("union")) {
                s.or(part);
            } else if (kind.equals("intersection")) {
                s.and(part);
            } else {
                s.andNot(part);
            }
        }
        return s;
    }

    private static double sq(double x) {
        return x * x;
    }
}

package org.tensim.scene.file.bodies;

import java.util.BitSet;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.WeakHashMap;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Topology;
import org.tensim.scene.file.BodyContext;
import org.tensim.scene.file.BodyType;
import org.tensim.scene.file.MapReader;
import org.tensim.scene.file.QuantityKind;
import org.tensim.scene.file.SceneException;
import org.tensim.scene.file.ZoneContext;
import org.tensim.scene.shell.ShellMaterial;
import org.tensim.scene.shell.ShellNetwork;
import org.tensim.scene.shell.StandaloneShell;
import org.tensim.scene.shell.SurfacePair;
import org.tensim.scene.shell.TissueModel;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * {@code type: shell}: the paper's object "defined by two boundary surfaces" (section 2.2), with the diaphragm's
 * tissue models ({@link TissueModel}; docs/diaphragm.md, "The model"), built by the same parts as the diaphragm
 * ({@link TwoSurfaces}, {@link ShellNetwork}, {@link StandaloneShell}). Keys:
 * <ul>
 * <li>{@code surface: {file, units}} and {@code thickness} (length): one surface, offset by the thickness along
 * its vertex normals ({@link TwoSurfaces#offset}); or {@code upper: {file, units}} and {@code lower: {file,
 * units}}: the two boundary surfaces ({@link SurfacePair#of}), their median gap the thickness. Exactly one
 * form;</li>
 * <li>{@code material: {E, nu, density, damping_time}}: Young's modulus (pressure, required), Poisson's ratio
 * (1/3), density (1060 kg/m^3, soft tissue) and the stiffness-proportional damping time (time, 0);</li>
 * <li>{@code tissue_model}: {@code material} (the default: membrane triangles sized for Kirchhoff's bending
 * rigidity, transverse shear elements, every column across the thickness a rigid link), {@code springs}
 * (the same with edge springs) or {@code paper} (the paper's springs: faces, folding springs, columns and
 * diagonals, no rigid link).</li>
 * </ul>
 * Node v is vertex v: the upper surface's vertices first, then the lower's. Zones: {@code tensegrity} and
 * {@code mass-spring} with their own E; parts: {@code upper} and {@code lower} (see
 * {@link #applyZone}).
 */
public final class ShellBodyType implements BodyType {
    /** The keys of {@code material:}. */
    public static final List<String> MATERIAL_KEYS = List.of("E", "nu", "density", "damping_time");
    /** Default Poisson's ratio: the shell network's own (edge springs are exact at 1/3). */
    static final double DEFAULT_NU = 1.0 / 3;
    /** Default density, kg/m^3: soft tissue's. */
    static final double DEFAULT_DENSITY = 1060;
    /** A surface's largest side must lie within these, m. */
    static final double MIN_SIZE_M = 1e-3;
    static final double MAX_SIZE_M = 100;

    /** The keys of a zone's {@code material:}. */
    public static final List<String> ZONE_MATERIAL_KEYS = List.of("E");

    /**
     * What a body was built from, for its zones (a body type is one object for every file loaded): its surfaces,
     * material, tissue model and damping time, each vertex's zone so far (-1: none; else the last zone of its own E
     * holding it) and those zones' E, Pa.
     */
    private record Built(TwoSurfaces s, ShellMaterial m, TissueModel model, double betaS, int[] vertexZone,
            List<Double> zoneE) {
    }

    private final Map<Topology, Built> built = Collections.synchronizedMap(new WeakHashMap<>());

    @Override
    public String name() {
        return "shell";
    }

    @Override
    public List<String> keys() {
        return List.of("surface", "thickness", "upper", "lower", "material", "tissue_model");
    }

    @Override
    public int[] build(BodyContext ctx, Topology t) {
        MapReader r = ctx.keys();
        boolean one = r.has("surface");
        if (one == (r.has("upper") || r.has("lower")) || (!one && !(r.has("upper") && r.has("lower")))) {
            throw SceneException.at(r.node(), "give either surface: {file, units} with thickness (one surface,"
                    + " offset), or upper: {file, units} and lower: {file, units} (the two boundary surfaces)");
        }
        TwoSurfaces s;
        if (one) {
            double thickness = r.positive("thickness", QuantityKind.LENGTH, ctx.units(), Double.NaN);
            s = TwoSurfaces.offset(mesh(ctx, "surface"), thickness);
        } else {
            if (r.has("thickness")) {
                throw SceneException.at(r.node().get("thickness"), "two boundary surfaces give the thickness (their"
                        + " median gap); leave out thickness");
            }
            s = SurfacePair.of(mesh(ctx, "upper"), mesh(ctx, "lower"));
        }
        ShellMaterial m = material(r, ctx, s.thicknessM());
        double beta = new MapReader(r.required("material"), MATERIAL_KEYS).nonNegative("damping_time",
                QuantityKind.TIME, ctx.units(), 0);
        TissueModel model = model(r);
        Topology built = StandaloneShell.of(s, m, model, 1, beta);
        int[] vertexZone = new int[s.mesh().vertexCount()];
        java.util.Arrays.fill(vertexZone, -1);
        this.built.put(built, new Built(s, m, model, beta, vertexZone, new java.util.ArrayList<>()));
        ctx.own(built, s);
        ctx.report(String.format("shell: %d + %d nodes (upper + lower), thickness %.4g mm, %s model, %d springs,"
                + " %d membrane triangles, %d shear elements, %d rigid links", s.upperCount(), s.lowerCount(),
                1e3 * s.thicknessM(), model.name().toLowerCase(java.util.Locale.ROOT), built.springs().size(),
                built.triangles().size(), built.shears().size(), built.rigidLinks().size()));
        return null;
    }

    private static TriangleMesh mesh(BodyContext ctx, String key) {
        return ctx.mesh(ctx.keys().required(key), "shell surface", MIN_SIZE_M, MAX_SIZE_M).mesh();
    }

    private static ShellMaterial material(MapReader r, BodyContext ctx, double thicknessM) {
        MapReader m = new MapReader(r.required("material"), MATERIAL_KEYS);
        double e = m.positive("E", QuantityKind.PRESSURE, ctx.units(), Double.NaN);
        double nu = m.quantity("nu", QuantityKind.NUMBER, ctx.units(), DEFAULT_NU);
        double rho = m.positive("density", QuantityKind.DENSITY, ctx.units(), DEFAULT_DENSITY);
        try {
            return new ShellMaterial(e, nu, thicknessM, rho);
        } catch (IllegalArgumentException ex) {
            throw SceneException.at(m.node(), ex.getMessage());
        }
    }

    private static TissueModel model(MapReader r) {
        if (!r.has("tissue_model")) {
            return TissueModel.MATERIAL;
        }
        try {
            return TissueModel.parse(r.string("tissue_model"));
        } catch (IllegalArgumentException e) {
            throw SceneException.at(r.node().get("tissue_model"), e.getMessage());
        }
    }

    /** A shell's parts: {@code upper} and {@code lower}, its two boundary surfaces' nodes. */
    @Override
    public Map<String, BitSet> parts(org.tensim.scene.file.SceneBody body) {
        TwoSurfaces s = (TwoSurfaces) body.built();
        BitSet upper = new BitSet();
        for (int v = 0; v < s.mesh().vertexCount(); v++) {
            upper.set(v, s.isUpper(v));
        }
        BitSet lower = new BitSet();
        lower.set(0, s.mesh().vertexCount());
        lower.andNot(upper);
        Map<String, BitSet> parts = new java.util.LinkedHashMap<>();
        parts.put("upper", upper);
        parts.put("lower", lower);
        return parts;
    }

    /** {@code tensegrity} (the diaphragm's central tendon) and {@code mass-spring} (a patch of its own E) zones. */
    @Override
    public List<String> zoneModels() {
        return List.of("tensegrity", "mass-spring");
    }

    @Override
    public List<String> zoneMaterialKeys() {
        return ZONE_MATERIAL_KEYS;
    }

    /**
     * A zone with {@code material: {E}} (required for {@code mass-spring}, optional for {@code tensegrity}) is a
     * patch of the shell of that modulus, identified as the shell is ({@link StandaloneShell}, its tissue model):
     * every edge whose two ends are in the zone takes the zone's E, as the diaphragm's tendon edges take the
     * tendon's, so a spring on such an edge (a face edge, a column or diagonal of it) is the zone's, and a membrane
     * triangle or shear element takes the mean of its three edges' E: the zone's wholly inside, between the two on
     * its border. The shell is rebuilt with those moduli and its springs, triangles and shear elements replaced in
     * place (same nodes, same order: a zone of the body's own E changes nothing, to the bit). The zone's nu,
     * thickness and density are the body's: the thickness is the surfaces' gap and nu the sandwich identification's
     * for the whole shell. Later zones win over earlier ones. In the paper's model the columns and diagonals keep
     * the body's E ({@link org.tensim.scene.shell.PaperShellSprings}).
     *
     * <p>A {@code tensegrity} zone also makes the zone's columns across the thickness rigid links, by the
     * diaphragm's tendon heuristic ({@link ShellNetwork#columnPairs}: each zone node with its partner on the other
     * face, also in the zone, shortest first, each node at most once, 0.3 to 2.5 thicknesses: disjoint struts);
     * the paper's tissue model only: the others make every column rigid already.
     */
    @Override
    public void applyZone(ZoneContext zone, Topology t, BitSet nodes) {
        Built b = built.get(t);
        boolean hasE = zone.material() != null && zone.material().has("E");
        if (zone.model().equals("mass-spring")) {
            if (!hasE) {
                throw SceneException.at(zone.node(), "a mass-spring zone of a shell needs material: {E: ...} (the"
                        + " body's E is " + b.m().youngPa() + " Pa)");
            }
        } else {
            tensegrity(zone, t, b, nodes);
        }
        if (hasE) {
            double e = zone.material().positive("E", QuantityKind.PRESSURE, zone.units(), Double.NaN);
            stiffness(zone, t, b, nodes, e);
        }
    }

    private static void stiffness(ZoneContext zone, Topology t, Built b, BitSet nodes, double youngPa) {
        TriangleMesh mesh = b.s().mesh();
        boolean edge = false;
        for (int tr = 0; tr < mesh.triangleCount() && !edge; tr++) {
            int in = 0;
            for (int k = 0; k < 3; k++) {
                in += nodes.get(mesh.corner(tr, k)) ? 1 : 0;
            }
            edge = in >= 2;
        }
        if (!edge) {
            throw SceneException.at(zone.node(), "the zone holds both ends of none of the shell's edges ("
                    + nodes.cardinality() + " nodes): widen its region");
        }
        int id = b.zoneE().size();
        b.zoneE().add(youngPa);
        int[] z = b.vertexZone();
        for (int v = nodes.nextSetBit(0); v >= 0; v = nodes.nextSetBit(v + 1)) {
            z[v] = id;
        }
        double[] zoneE = b.zoneE().stream().mapToDouble(Double::doubleValue).toArray();
        double body = b.m().youngPa();
        // An edge is a zone's when both its ends are (the last zone of each), else the body's.
        Topology fresh = StandaloneShell.of(b.s(), b.m(), b.model(), 1, b.betaS(),
                (i, j) -> z[i] >= 0 && z[i] == z[j] ? zoneE[z[i]] : body);
        if (fresh.springs().size() != t.springs().size() || fresh.triangles().size() != t.triangles().size()
                || fresh.shears().size() != t.shears().size()) {
            throw new IllegalStateException("a shell rebuilt with its zone's E has other elements than the body");
        }
        for (int i = 0; i < fresh.springs().size(); i++) {
            t.replaceSpring(i, fresh.springs().get(i));
        }
        for (int i = 0; i < fresh.triangles().size(); i++) {
            t.replaceTriangle(i, fresh.triangles().get(i));
        }
        for (int i = 0; i < fresh.shears().size(); i++) {
            t.replaceShear(i, fresh.shears().get(i));
        }
    }

    private static void tensegrity(ZoneContext zone, Topology t, Built b, BitSet nodes) {
        TwoSurfaces s = b.s();
        TissueModel model = b.model();
        if (model.rigidColumns()) {
            throw SceneException.at(zone.node(), "a tensegrity zone of a shell needs tissue_model: paper (the "
                    + model.name().toLowerCase(java.util.Locale.ROOT) + " model makes every column rigid already)");
        }
        List<int[]> pairs = ShellNetwork.columnPairs(s, nodes::get);
        if (pairs.isEmpty()) {
            throw SceneException.at(zone.node(), "the zone holds no column across the thickness (a node and its"
                    + " partner on the other face; " + nodes.cardinality() + " nodes): widen its region");
        }
        for (int[] c : pairs) {
            t.addRigidLink(t.node(c[0]), t.node(c[1]));
        }
    }
}

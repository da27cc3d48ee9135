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
 * Node v is vertex v: the upper surface's vertices first, then the lower's. Zones: {@code tensegrity} (see
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

    /** Each built body's two surfaces, for its zones (a body type is one object for every file loaded). */
    private final Map<Topology, TwoSurfaces> surfaces = Collections.synchronizedMap(new WeakHashMap<>());

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
        surfaces.put(built, s);
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

    /** A {@code tensegrity} zone: the diaphragm's central tendon on any shell. */
    @Override
    public List<String> zoneModels() {
        return List.of("tensegrity");
    }

    /**
     * Makes the zone's columns across the thickness rigid links, by the diaphragm's tendon heuristic
     * ({@link ShellNetwork#columnPairs}: each zone node with its partner on the other face, also in the zone,
     * shortest first, each node at most once, 0.3 to 2.5 thicknesses: disjoint struts). The paper's tissue model
     * only: the others make every column rigid already.
     */
    @Override
    public void applyZone(ZoneContext zone, Topology t, BitSet nodes) {
        TwoSurfaces s = surfaces.get(t);
        TissueModel model = model(zone.bodyKeys());
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

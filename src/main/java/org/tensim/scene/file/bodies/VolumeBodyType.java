package org.tensim.scene.file.bodies;

import java.util.BitSet;
import java.util.List;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.LinearMapping;
import org.tensim.model.Spring;
import org.tensim.model.Topology;
import org.tensim.scene.file.BodyContext;
import org.tensim.scene.file.BodyType;
import org.tensim.scene.file.EmbeddedSurface;
import org.tensim.scene.file.MapReader;
import org.tensim.scene.file.QuantityKind;
import org.tensim.scene.file.SceneException;
import org.tensim.scene.file.ZoneContext;
import org.tensim.scene.volume.BoxSurface;
import org.tensim.scene.volume.SpringFit;
import org.tensim.scene.volume.VolumeBody;
import org.tensim.scene.volume.VolumeParameters;

/**
 * {@code type: volume}: a closed surface filled with a lattice of mass-spring cells that carries it
 * ({@link VolumeBody}; docs/volume.md). Keys:
 * <ul>
 * <li>{@code surface: {file, units}} (a mesh, units mm or m) or {@code box: [lx, ly, lz]} (lengths: the box
 * [0, lx] x [0, ly] x [0, lz], its surface a grid of about one cell's spacing); exactly one;</li>
 * <li>{@code cell}: the lattice's cell side (length, required);</li>
 * <li>{@code material: {E, nu, density, damping_time}}: Young's modulus (pressure, required), Poisson's ratio
 * (0.25), density (1000 kg/m^3), stiffness-proportional damping time (time, 0: each spring k gets c = beta k);</li>
 * <li>{@code fit}: {@code isotropic} (default), {@code axial} or {@code volumetric} ({@link SpringFit}).</li>
 * </ul>
 * Regions' boxes, spheres and planes select lattice nodes (the bounding box is the lattice's, a little larger than
 * the surface); {@code indices} and {@code labels} name surface vertices, each selecting the node that carries it
 * with the largest weight, so a label file on the surface pins the nodes under that part of it.
 */
public final class VolumeBodyType implements BodyType {
    /** The keys of {@code material:}. */
    public static final List<String> MATERIAL_KEYS = List.of("E", "nu", "density", "damping_time");
    /** Default Poisson's ratio: the isotropic lattice's own. */
    static final double DEFAULT_NU = 0.25;
    /** Default density, kg/m^3. */
    static final double DEFAULT_DENSITY = 1000;
    /** A surface's largest side must lie within these, m. */
    static final double MIN_SIZE_M = 1e-3;
    static final double MAX_SIZE_M = 100;

    @Override
    public String name() {
        return "volume";
    }

    @Override
    public List<String> keys() {
        return List.of("surface", "box", "cell", "material", "fit");
    }

    /** Spring stiffness and damping change the compiled state's constants only. */
    @Override
    public List<String> liveKeys() {
        return List.of("material.E", "material.damping_time");
    }

    /** A zone's E sets its parallel springs' stiffness only. */
    @Override
    public List<String> liveZoneMaterialKeys() {
        return List.of("E");
    }

    @Override
    public int[] build(BodyContext ctx, Topology t) {
        MapReader r = ctx.keys();
        if (r.has("surface") == r.has("box")) {
            throw SceneException.at(r.node(), "give exactly one of surface: {file, units} or box: [lx, ly, lz]");
        }
        VolumeParameters p = parameters(r, ctx);
        TriangleMesh mesh;
        String what;
        if (r.has("box")) {
            double[] s = r.vector("box", QuantityKind.LENGTH, ctx.units());
            for (int a = 0; a < 3; a++) {
                if (!(s[a] > 0)) {
                    throw SceneException.at(r.node().get("box"), "the box's sides must be > 0, got " + s[a] + " m on "
                            + "xyz".charAt(a));
                }
            }
            mesh = BoxSurface.of(s[0], s[1], s[2], p.cellSizeM());
            what = "the box of body '" + ctx.name() + "'";
        } else {
            mesh = ctx.mesh(r.required("surface"), "volume", MIN_SIZE_M, MAX_SIZE_M).mesh();
            what = r.required("surface").get("file").text();
        }
        VolumeBody v;
        try {
            v = VolumeBody.build(t, mesh, p, what);
        } catch (IllegalArgumentException e) {
            throw SceneException.at(r.node().get(r.has("box") ? "box" : "surface"), e.getMessage());
        }
        ctx.embed(new EmbeddedSurface(v.surface(), v.surfaceMapping()));
        ctx.report(v.report().describe());
        return carriers(v.surfaceMapping());
    }

    /** The body's parameters from its keys. */
    static VolumeParameters parameters(MapReader r, BodyContext ctx) {
        double cell = r.positive("cell", QuantityKind.LENGTH, ctx.units(), Double.NaN);
        MapReader m = new MapReader(r.required("material"), MATERIAL_KEYS);
        double e = m.positive("E", QuantityKind.PRESSURE, ctx.units(), Double.NaN);
        double nu = m.quantity("nu", QuantityKind.NUMBER, ctx.units(), DEFAULT_NU);
        double rho = m.positive("density", QuantityKind.DENSITY, ctx.units(), DEFAULT_DENSITY);
        double beta = m.nonNegative("damping_time", QuantityKind.TIME, ctx.units(), 0);
        SpringFit fit = SpringFit.parse(r.choice("fit", List.of("isotropic", "axial", "volumetric"), "isotropic"));
        try {
            return VolumeParameters.of(cell, e, nu, rho).withDampingTime(beta).withFit(fit);
        } catch (IllegalArgumentException ex) {
            throw SceneException.at(m.node(), ex.getMessage());
        }
    }

    /** For each surface vertex, the node carrying it with the largest weight (the first of equals). */
    static int[] carriers(LinearMapping map) {
        return org.tensim.scene.file.SurfaceFaces.carriers(map);
    }

    /** {@code tensegrity} and {@code mass-spring} zones ({@link #applyZone}). */
    @Override
    public List<String> zoneModels() {
        return List.of("tensegrity", "mass-spring");
    }

    @Override
    public List<String> zoneMaterialKeys() {
        return List.of("E");
    }

    /**
     * A zone's springs (both ends in the zone) are made as stiff as its {@code material: {E}} (at least the body's
     * E) by a parallel spring of stiffness {@code k (E_zone / E - 1)} each (damping {@code beta} times that), so
     * the zone is the same lattice of modulus E_zone. A {@code tensegrity} zone also makes each of its cell edges
     * (the springs of rest length h along the axes) a rigid link, as the diaphragm's tendon makes its columns
     * across the thickness rigid: the zone's cells keep their edges' lengths and resist shear by their face
     * diagonals only, struts and cables. Its E may then be left out (the body's).
     */
    @Override
    public void applyZone(ZoneContext zone, Topology t, BitSet nodes) {
        MapReader body = zone.bodyKeys();
        MapReader m = new MapReader(body.required("material"), MATERIAL_KEYS);
        double e = m.positive("E", QuantityKind.PRESSURE, zone.units(), Double.NaN);
        double beta = m.nonNegative("damping_time", QuantityKind.TIME, zone.units(), 0);
        double h = body.positive("cell", QuantityKind.LENGTH, zone.units(), Double.NaN);
        boolean rigid = zone.model().equals("tensegrity");
        if (!rigid && (zone.material() == null || !zone.material().has("E"))) {
            throw SceneException.at(zone.node(), "a mass-spring zone of a volume needs material: {E: ...} (the"
                    + " body's E is " + e + " Pa)");
        }
        double ez = zone.material() != null && zone.material().has("E")
                ? zone.material().positive("E", QuantityKind.PRESSURE, zone.units(), Double.NaN) : e;
        if (ez < e) {
            throw SceneException.at(zone.material().node().get("E"), "the zone's E (" + ez + " Pa) is below the"
                    + " body's (" + e + " Pa): a zone can stiffen a volume, not soften it");
        }
        double factor = ez / e - 1;
        List<Spring> inZone = new java.util.ArrayList<>();
        for (Spring s : t.springs()) {
            if (nodes.get(s.a()) && nodes.get(s.b())) {
                inZone.add(s);
            }
        }
        int links = 0;
        for (Spring s : inZone) {
            if (factor > 0) {
                t.addSpring(s.a(), s.b(), s.stiffness() * factor, s.restLength(), beta * s.stiffness() * factor);
            }
            if (rigid && Math.abs(s.restLength() - h) <= 1e-9 * h) {
                t.addRigidLink(s.a(), s.b(), s.restLength());
                links++;
            }
        }
        if (inZone.isEmpty() || (rigid && links == 0)) {
            throw SceneException.at(zone.node(), "the zone holds both ends of none of the volume's "
                    + (rigid ? "cell edges" : "springs") + " (" + nodes.cardinality() + " nodes): widen its region");
        }
    }
}

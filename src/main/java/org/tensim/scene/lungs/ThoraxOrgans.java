package org.tensim.scene.lungs;

import java.util.ArrayList;
import java.util.List;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Check;
import org.tensim.model.LinearMapping;
import org.tensim.model.Topology;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.RibCage;
import org.tensim.scene.thorax.TriangleTree;
import org.tensim.scene.volume.VolumeBody;
import org.tensim.scene.volume.VolumeParameters;
import org.tensim.solver.SlidingStiffness;
import org.tensim.solver.SurfaceSliding;

/**
 * The lungs and the liver built into a diaphragm scene's own topology, after all its nodes (so node ranges of the
 * diaphragm, its cage and anchors, and every figure computed on them, are unchanged), with the couplings that move
 * them in the same force pass as the diaphragm:
 * <ul>
 * <li>each lung a lattice volume ({@link LungVolumes}) whose outer surface ({@link LungOuterSurface}: the merged
 * lobes without the fissures' sheets, which lie inside the lung) slides, bilaterally and without friction, on the
 * parietal pleura ({@link PleuraCarriers}: that outer surface at rest, carried by the diaphragm's upper surface, the
 * ribs' frames and fixed frames). The followers are the outer surface's own vertices, carried by the lattice's
 * trilinear weights ({@link VolumeBody#surfaceMapping}): so what is held on the pleura is the lung's surface itself,
 * and its departure from the pleura is the sliding term's own penetration and separation;</li>
 * <li>the liver (optional) a lattice volume whose followers near the diaphragm (lattice nodes within the band
 * of its surface and {@link Options#liverReachM} of the diaphragm's lower surface) touch that lower surface,
 * one-sided, carried by the diaphragm's own nodes; held behind by zero-length springs to fixed anchors at its
 * bare area (the posterior fifth of its depth, upper half of its height: the coronary and triangular ligaments'
 * region, against the posterior diaphragm).</li>
 * </ul>
 * The couplings are described by {@link Coupling}s; the solver term that enforces them is made from these.
 */
public final class ThoraxOrgans {
    /**
     * What the organs are built from.
     *
     * @param lung              the parenchyma ({@link LungVolumes#PARENCHYMA})
     * @param liver             the liver's tissue, or null for no liver volume
     * @param rules             the pleura's carrier rule
     * @param pleuraPaPerM      the lungs' sliding stiffness per area, Pa/m (a surface vertex's k = this times its
     *                          lumped area, {@link SlidingStiffness})
     * @param liverPaPerM       the liver's contact stiffness per area, Pa/m
     * @param liverHoldPaPerM   the bare area's springs per area, Pa/m
     * @param liverBelowPaPerM  the abdomen's support under the liver, springs per area, Pa/m (0: none): its surface
     *                          nodes in its lower half that do not touch the diaphragm, tied to fixed anchors
     *                          ({@link #ABDOMEN_PA_PER_M} by default)
     * @param liverReachM       how far from the diaphragm's lower surface a liver surface node may be to be a
     *                          follower, m
     * @param followerBandM     how far from the liver's surface (either side) a lattice node may be to be a
     *                          contact follower, m: small against the surface's radius of curvature, so that the rest
     *                          distance it is held at is the same to its triangle's plane and to the neighbours'
     *                          it walks to (a follower at d from a surface bending by theta between triangles sees
     *                          their planes differ by about d theta^2 / 2)
     * @param samples           lung points drawn (LungSamples, fixed seed)
     * @param probesM           user probes, 3 per point, m, each inside a lung
     */
    public record Options(VolumeParameters lung, VolumeParameters liver, PleuraCarriers.Rules rules,
            double pleuraPaPerM, double liverPaPerM, double liverHoldPaPerM, double liverBelowPaPerM,
            double liverReachM, double followerBandM, int samples, double[] probesM) {
        /**
         * The abdomen's support under the liver by default, Pa/m: a Winkler foundation's modulus, the viscera below
         * taken as stiff as the liver's own support of the diaphragm, {@code E / h} with the healthy liver's
         * E = 5.5 kPa (transient elastography, Roulot et al., J Hepatol 48:606, 2008) over the shared liver's height
         * h = 0.158 m (docs/thorax.md, "The liver's support"). Without it the liver goes down as far as the most
         * descending part of the muscle above it (1.15 times the right dome on the clustered thorax; docs/lungs.md).
         */
        public static final double ABDOMEN_PA_PER_M = 3.5e4;

        public Options {
            Check.positive("pleural sliding stiffness", "Pa/m", pleuraPaPerM);
            Check.positive("liver contact stiffness", "Pa/m", liverPaPerM);
            Check.positive("liver bare-area stiffness", "Pa/m", liverHoldPaPerM);
            Check.nonNegative("liver's abdominal support", "Pa/m", liverBelowPaPerM);
            Check.positive("liver reach", "m", liverReachM);
            Check.positive("follower band", "m", followerBandM);
            Check.atLeast("lung sample points", samples, 1);
            if (probesM.length % 3 != 0) {
                throw new IllegalArgumentException("lung probes need 3 coordinates each, got " + probesM.length);
            }
        }

        /**
         * The defaults: the parenchyma, no liver volume ({@link #withLiver}, which {@code tensim diaphragm --lungs}
         * adds), the pleura's default rule; pleura 1e6 Pa/m
         * (the lung's elastic stress at tidal strains, a few hundred Pa: its bulk modulus E / (3 (1 - 2 nu)),
         * 1.7 kPa, times a tenth of volume change, leaves a few tenths of a mm), liver contact 3e5 Pa/m,
         * bare area 1e4 Pa/m (a soft hold: the abdomen's compliance), the abdomen below it
         * {@link #ABDOMEN_PA_PER_M}, reach 20 mm, the liver's followers within
         * 4 mm of its surface, 300 points.
         */
        public static Options defaults() {
            return new Options(LungVolumes.PARENCHYMA.withDampingTime(0.005), null, PleuraCarriers.Rules.defaults(),
                    1e6, 3e5, 1e4, ABDOMEN_PA_PER_M, 0.02, 0.004, 300, new double[0]);
        }

        /**
         * The same with the organs' damping times at most {@code 0.4 dt}: stiffness-proportional damping
         * {@code c = beta k} adds the rate {@code beta omega^2} to a mode of angular frequency omega, which an
         * explicit step of dt keeps stable for {@code beta omega^2 dt <~ 1}; with {@code omega dt < 1.5} (the scene's
         * step) {@code beta = 0.4 dt} is safe for every mode of the organs' light boundary nodes.
         */
        public Options dampedFor(double dtS) {
            double cap = 0.4 * dtS;
            return new Options(lung.withDampingTime(Math.min(lung.dampingTimeS(), cap)), liver == null ? null
                    : liver.withDampingTime(Math.min(liver.dampingTimeS(), cap)), rules, pleuraPaPerM, liverPaPerM,
                    liverHoldPaPerM, liverBelowPaPerM, liverReachM, followerBandM, samples, probesM);
        }

        /** The same with the liver volume of {@link #LIVER}. */
        public Options withLiver() {
            return new Options(lung, LIVER, rules, pleuraPaPerM, liverPaPerM, liverHoldPaPerM, liverBelowPaPerM,
                    liverReachM, followerBandM, samples, probesM);
        }

        /** The same without the liver volume. */
        public Options withoutLiver() {
            return new Options(lung, null, rules, pleuraPaPerM, liverPaPerM, liverHoldPaPerM, liverBelowPaPerM,
                    liverReachM, followerBandM, samples, probesM);
        }

        /** The same with other cell sizes, m (the lungs', the liver's). */
        public Options withCells(double lungM, double liverM) {
            return new Options(lung.withCellSize(lungM), liver == null ? null : liver.withCellSize(liverM), rules,
                    pleuraPaPerM, liverPaPerM, liverHoldPaPerM, liverBelowPaPerM, liverReachM, followerBandM, samples,
                    probesM);
        }

        /** The same with the abdomen's support under the liver at {@code paPerM}, Pa/m (0: none). */
        public Options withAbdomen(double paPerM) {
            return new Options(lung, liver, rules, pleuraPaPerM, liverPaPerM, liverHoldPaPerM, paPerM, liverReachM,
                    followerBandM, samples, probesM);
        }

        /** The same with user probes, 3 per point, m. */
        public Options withProbes(double[] m) {
            return new Options(lung, liver, rules, pleuraPaPerM, liverPaPerM, liverHoldPaPerM, liverBelowPaPerM,
                    liverReachM, followerBandM, samples, m.clone());
        }
    }

    /**
     * The liver's default tissue: E 6 kPa (healthy liver's shear modulus about 2 kPa by MR elastography, E = 3 G
     * nearly incompressible; docs/lungs.md cites), nu 0.45 (volumetric fit), 1060 kg/m^3, 15 mm cells, damping
     * time 5 ms.
     */
    public static final VolumeParameters LIVER = VolumeParameters.of(0.015, 6e3, 0.45, 1060)
            .withFit(org.tensim.scene.volume.SpringFit.VOLUMETRIC).withDampingTime(0.005);

    /**
     * A coupling: followers (points of the state's nodes: a lung's surface vertices, the liver's lattice nodes) held
     * on a surface carried by the state's nodes.
     *
     * @param name      for reports
     * @param followers the followers on the state's nodes
     * @param surface   the surface's points on the state's nodes
     * @param triangles the surface's triangles, 3 point ids each, outward by winding
     * @param stiffness per follower, N/m
     * @param bilateral sliding (held on the surface) rather than one-sided contact
     */
    public record Coupling(String name, LinearMapping followers, LinearMapping surface, int[] triangles,
            double[] stiffness, boolean bilateral) {
    }

    private final List<LungVolumes.Lung> lungs;
    private final VolumeBody liver;
    private final List<PleuraCarriers.Built> pleurae;
    private final List<Coupling> couplings;
    private final LinearMapping points;
    private final int[] pointLung;
    private final int firstNode;
    private final int[] liverHeld;
    private final int[] liverSupported;

    private ThoraxOrgans(List<LungVolumes.Lung> lungs, VolumeBody liver, List<PleuraCarriers.Built> pleurae,
            List<Coupling> couplings, LinearMapping points, int[] pointLung, int firstNode, int[] liverHeld,
            int[] liverSupported) {
        this.lungs = lungs;
        this.liver = liver;
        this.pleurae = pleurae;
        this.couplings = couplings;
        this.points = points;
        this.pointLung = pointLung;
        this.firstNode = firstNode;
        this.liverHeld = liverHeld;
        this.liverSupported = liverSupported;
    }

    /**
     * Builds the organs into the scene's topology.
     *
     * @param lungSurfaces the right lung's then the left's closed surface, m (the merged lobes)
     * @param liverSurface the liver's closed surface, m, or null (then no liver whatever the options say)
     */
    public static ThoraxOrgans build(DiaphragmScene scene, List<TriangleMesh> lungSurfaces, TriangleMesh liverSurface,
            Options o) {
        Topology t = scene.topology();
        int first = t.nodeCount();
        o = o.dampedFor(scene.recommendedTimeStep());
        List<LungVolumes.Lung> lungs = new ArrayList<>();
        String[] side = {"right", "left"};
        for (int i = 0; i < lungSurfaces.size(); i++) {
            long t0 = System.nanoTime();
            VolumeBody body = VolumeBody.build(t, lungSurfaces.get(i), o.lung(), "the " + side[i] + " lung",
                    minMass(o.lung()));
            lungs.add(new LungVolumes.Lung(i == 0 ? org.tensim.io.thorax.ThoraxPart.Side.RIGHT
                    : org.tensim.io.thorax.ThoraxPart.Side.LEFT, List.of(side[i]), lungSurfaces.get(i), body,
                    (System.nanoTime() - t0) * 1e-9));
        }
        VolumeBody liver = null;
        int[] held = new int[0];
        if (liverSurface != null && o.liver() != null) {
            liver = VolumeBody.build(t, liverSurface, o.liver(), "the liver", minMass(o.liver()));
            held = OrganGeometry.holdBareArea(t, liver, o.liver().cellSizeM(), o.liverHoldPaPerM());
        }
        // The liver's followers of the diaphragm's lower surface (found before any node is added after the
        // liver's, so that the abdomen's anchors below come before the couplings' node count).
        int[] lower = liver == null ? null : OrganGeometry.lowerTriangles(scene);
        int[] liverFollowers = new int[0];
        int[] supported = new int[0];
        if (liver != null) {
            int nd = scene.diaphragmNodes();
            TriangleTree tree = new TriangleTree(OrganGeometry.restPositions(t, nd), lower, 3);
            liverFollowers = OrganGeometry.surfaceNodes(t, liver, o.followerBandM(), tree, o.liverReachM());
            if (o.liverBelowPaPerM() > 0) {
                supported = OrganGeometry.supportBelow(t, liver, o.liver().cellSizeM(), o.liverBelowPaPerM(),
                        o.followerBandM(), liverFollowers, held);
            }
        }
        OrganGeometry.refuseOverdamped(t, first, scene.recommendedTimeStep());
        List<RibCage.Segment> segs = scene.cage().segments();
        List<PleuraCarriers.Rib> ribs = OrganGeometry.ribs(t, segs);
        int[] upper = scene.upperTriangles();
        List<PleuraCarriers.Built> pleurae = new ArrayList<>();
        List<LungOuterSurface> outers = new ArrayList<>();
        for (LungVolumes.Lung l : lungs) {
            LungOuterSurface outer = LungOuterSurface.of(l.surface(), LungOuterSurface.DEFAULT_FISSURE_M);
            outers.add(outer);
            pleurae.add(PleuraCarriers.build(t, outer.outer(), upper, ribs, o.rules(), 0));
        }
        int n = t.nodeCount();
        List<Coupling> couplings = new ArrayList<>();
        for (int i = 0; i < lungs.size(); i++) {
            TriangleMesh outer = outers.get(i).outer();
            LinearMapping f = OrganGeometry.rows(lungs.get(i).body().surfaceMapping(), outers.get(i).mergedVertex(),
                    n);
            double[] area = SlidingStiffness.lumpedAreas(java.util.stream.IntStream.range(0, outer.vertexCount())
                    .toArray(), outer.triangles(), outer.coordinates());
            double[] k = new double[area.length];
            for (int v = 0; v < k.length; v++) {
                k[v] = o.pleuraPaPerM() * area[v];
            }
            couplings.add(new Coupling(side[i] + " lung on the pleura", f,
                    OrganGeometry.rebase(pleurae.get(i).mapping(), n), outer.triangles(), k, true));
        }
        if (liver != null) {
            double h = o.liver().cellSizeM();
            int nd = scene.diaphragmNodes();
            int[] f = liverFollowers;
            couplings.add(new Coupling("liver under the diaphragm", OrganGeometry.nodes(f, n),
                    OrganGeometry.identity(nd, n), lower,
                    OrganGeometry.filled(f.length, o.liverPaPerM() * h * h), false));
        }
        // The sample points and the probes, each in the lattice of the lung that holds it.
        LungSamples s = LungSamples.draw(lungSurfaces, o.samples(), LungSamples.SEED);
        LinearMapping.Builder b = new LinearMapping.Builder(n);
        List<Integer> which = new ArrayList<>();
        for (int k = 0; k < s.count(); k++) {
            int lung = s.lung()[k];
            LatticePoints.embed(b, t, lungs.get(lung).body(), o.lung().cellSizeM(),
                    java.util.Arrays.copyOfRange(s.positions(), 3 * k, 3 * k + 3), "lung sample point");
            which.add(lung);
        }
        for (int k = 0; 3 * k < o.probesM().length; k++) {
            double[] p = java.util.Arrays.copyOfRange(o.probesM(), 3 * k, 3 * k + 3);
            int lung = OrganGeometry.lungHolding(lungSurfaces, p);
            if (lung < 0) {
                throw new IllegalArgumentException(String.format(java.util.Locale.ROOT, "lung probe %d at (%.1f,"
                        + " %.1f, %.1f) mm is inside neither lung: expected a point in a lung's volume", k,
                        1e3 * p[0], 1e3 * p[1], 1e3 * p[2]));
            }
            LatticePoints.embed(b, t, lungs.get(lung).body(), o.lung().cellSizeM(), p, "lung probe");
            which.add(lung);
        }
        return new ThoraxOrgans(lungs, liver, pleurae, couplings, b.build(),
                which.stream().mapToInt(Integer::intValue).toArray(), first, held, supported);
    }

    /**
     * Makes the couplings' solver terms ({@link SurfaceSliding}: the lungs' SLIDING, the liver's CONTACT) and adds
     * them to the scene. Each follower's gap is its signed distance to its nearest triangle at rest, so that the
     * organs start unstrained where their meshes (of different sources) leave gaps or overlaps: what is held is
     * the rest relation, and a follower's penetration or separation is its departure from it.
     *
     * @return the terms, in the order of {@link #couplings()}
     */
    public List<SurfaceSliding> install(DiaphragmScene scene) {
        Topology t = scene.topology();
        double[] x0 = OrganGeometry.restPositions(t, t.nodeCount());
        List<SurfaceSliding> terms = new ArrayList<>();
        for (Coupling c : couplings) {
            SurfaceSliding.Mode mode = c.bilateral() ? SurfaceSliding.Mode.SLIDING : SurfaceSliding.Mode.CONTACT;
            int count = c.followers().pointCount();
            SurfaceSliding probe = SurfaceSliding.mapped(c.followers(), c.surface(), c.triangles(), c.stiffness(),
                    mode, new double[count], x0);
            double[] p = new double[3 * c.surface().pointCount()];
            c.surface().apply(x0, p);
            double[] y = new double[3 * count];
            c.followers().apply(x0, y);
            // The term's own signed distances (to the closest point where a follower is past its triangle's rim);
            // one off the surface, past a border, keeps its triangle's plane distance.
            double[] gaps = new double[count];
            probe.distancesM(x0, gaps);
            for (int e = 0; e < gaps.length; e++) {
                if (Double.isNaN(gaps[e])) {
                    gaps[e] = OrganGeometry.planeDistance(p, c.triangles(), probe.pairedTriangle(e), y, 3 * e);
                }
            }
            SurfaceSliding term = SurfaceSliding.mapped(c.followers(), c.surface(), c.triangles(), c.stiffness(),
                    mode, gaps, x0);
            scene.addTerm(term);
            terms.add(term);
        }
        return terms;
    }

    /**
     * Share of an interior node's mass {@code rho h^3} that every organ node has at least: the clipped corner nodes
     * would otherwise carry down to 1/512 of it, and the couplings' stiffness on them (not linearised by the implicit
     * integrators) would set the step; inertia is negligible in breathing (the organs' lowest modes are some 100
     * times faster than the breath), so the added mass changes the motion little.
     */
    public static final double MASS_FLOOR = 0.25;

    private static double minMass(VolumeParameters p) {
        double h = p.cellSizeM();
        return MASS_FLOOR * p.densityKgPerM3() * h * h * h;
    }

    /** The couplings to enforce (the lungs' sliding on the pleura, the liver's contact). */
    public List<Coupling> couplings() {
        return couplings;
    }

    public List<LungVolumes.Lung> lungs() {
        return lungs;
    }

    /** The liver volume, or null. */
    public VolumeBody liver() {
        return liver;
    }

    /** Liver nodes held at the bare area. */
    public int[] liverHeld() {
        return liverHeld.clone();
    }

    /** Liver nodes on the abdomen's support below it (none when {@link Options#liverBelowPaPerM} is 0). */
    public int[] liverSupported() {
        return liverSupported.clone();
    }

    /** Per lung, its carried pleura. */
    public List<PleuraCarriers.Built> pleurae() {
        return pleurae;
    }

    /** The sample points then the probes, on the state's nodes. */
    public LinearMapping points() {
        return points;
    }

    /** Per point, its lung: 0 right, 1 left. */
    public int[] pointLung() {
        return pointLung.clone();
    }

    /** The first organ node (the topology's node count before the organs). */
    public int firstNode() {
        return firstNode;
    }

}

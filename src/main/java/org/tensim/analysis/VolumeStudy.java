package org.tensim.analysis;

import org.tensim.io.mesh.TetMesh;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Check;
import org.tensim.model.Topology;
import org.tensim.scene.volume.BoxSurface;
import org.tensim.scene.volume.BoxTets;
import org.tensim.scene.volume.SpringFit;
import org.tensim.scene.volume.LatticeMaterial;
import org.tensim.scene.volume.VolumeBody;
import org.tensim.scene.volume.VolumeParameters;

/**
 * The volume body against known answers, by small-displacement statics ({@link LinearStatics}) with the loads on
 * the embedded surface, carried to the lattice by the mapping's transpose:
 * <ul>
 * <li>the cantilever: a square beam of depth D and length L = 10 D, its nodes at x = 0 fixed, a uniform shear
 * traction F / D^2 (along -z) on its tip face; the tip deflection is the work-conjugate mean
 * {@code sum f . u / F} over the tip face, against Euler-Bernoulli's {@code F L^3 / (3 E I)}, {@code I = D^4 / 12},
 * and Timoshenko's, which adds {@code F L / (kappa G A)}, kappa = 10 (1 + nu) / (12 + 11 nu) (Cowper), G the
 * lattice's shear modulus;</li>
 * <li>the compressed block: a cube of side S on rollers on its three low faces (each holds the displacement normal
 * to it), a pressure sigma on its top face, its other faces free: uniaxial stress, axial strain {@code -sigma / E}
 * and lateral strain {@code nu sigma / E}, measured as the area-weighted mean displacement of the top face (and of
 * the x = S face) over S. With a whole number of cells across the lattice fits the cube and the answer is exact;
 * with a half cell more, the last layer of cells is half full (a clipped lattice) and the answer converges.</li>
 * </ul>
 */
public final class VolumeStudy {
    /** CG stops at this fraction of the load's norm. */
    static final double TOLERANCE = 1e-10;

    /**
     * One cantilever solve.
     *
     * @param cellsAcross      cells across the depth D
     * @param cellM            cell size, m
     * @param nodes            lattice nodes
     * @param springs          springs
     * @param deflectionM      tip deflection, m (positive along the load)
     * @param eulerBernoulliM  F L^3 / (3 E I), m
     * @param timoshenkoM      Euler-Bernoulli's plus the shear deflection, m
     * @param iterations       CG iterations
     */
    public record Cantilever(int cellsAcross, double cellM, int nodes, int springs, double deflectionM,
            double eulerBernoulliM, double timoshenkoM, int iterations) {
        /** (deflection - Euler-Bernoulli) / Euler-Bernoulli. */
        public double errorAgainstEulerBernoulli() {
            return (deflectionM - eulerBernoulliM) / eulerBernoulliM;
        }
    }

    /**
     * One block solve.
     *
     * @param cellsAcross      cells across the side S (a fraction when the lattice is clipped)
     * @param cellM            cell size, m
     * @param nodes            lattice nodes
     * @param axialStrain      measured strain along the load (negative: shortening)
     * @param expectedStrain   -sigma / E
     * @param lateralStrain    measured strain across the load (positive: bulging)
     * @param modelPoisson     the lattice's Poisson ratio along its axes
     * @param requestedPoisson the nu asked for
     * @param iterations       CG iterations
     */
    public record Block(double cellsAcross, double cellM, int nodes, double axialStrain, double expectedStrain,
            double lateralStrain, double modelPoisson, double requestedPoisson, int iterations) {
        /** (strain - expected) / |expected|. */
        public double strainError() {
            return (axialStrain - expectedStrain) / Math.abs(expectedStrain);
        }

        /** Measured Poisson ratio, -lateral / axial strain. */
        public double measuredPoisson() {
            return -lateralStrain / axialStrain;
        }
    }

    /**
     * The material a tet body's springs aim at: isotropic, E with nu = 1/4 ({@code TetSprings}), which is the
     * lattice's isotropic fit's, so that its shear modulus and Poisson ratio stand for the tets' in Timoshenko's
     * correction and the block's report.
     */
    private static final java.util.function.Function<VolumeParameters, LatticeMaterial> TET_MATERIAL =
        q -> new LatticeMaterial(q.youngPa(), q.poisson(), SpringFit.ISOTROPIC);

    /**
     * Which tetrahedral mesh a study builds: the structured mesh of {@link BoxTets} cut by {@code split}, its
     * interior nodes moved by up to {@code jitter} of a cell along each axis ({@link BoxTets#jittered}, seed 1).
     */
    public record Tets(BoxTets.Split split, double jitter) {
        /** The structured mesh, no jitter. */
        public static Tets of(BoxTets.Split split) {
            return new Tets(split, 0);
        }

        TetMesh box(double lx, double ly, double lz, int nx, int ny, int nz) {
            TetMesh m = BoxTets.of(lx, ly, lz, nx, ny, nz, split);
            return jitter == 0 ? m : BoxTets.jittered(m, lx / nx, jitter, 1);
        }
    }

    private VolumeStudy() {
    }

    /**
     * The cantilever at {@code cellsAcross} cells across its depth (material and density from {@code p}; its cell
     * size is replaced by depth / cellsAcross).
     *
     * @param depthM D, m (&gt; 0); the beam is 10 D long
     * @param forceN F, N (&gt; 0)
     */
    public static Cantilever cantilever(VolumeParameters p, double depthM, double forceN, int cellsAcross) {
        return cantilever(p, depthM, forceN, cellsAcross, false);
    }

    /**
     * As {@link #cantilever(VolumeParameters, double, double, int)}; with {@code slidingRoot} the root's nodes hold
     * only their axial displacement (and the root's mid-planes their transverse ones), so that the root can contract
     * sideways as the beam's fibres do: the root of Euler-Bernoulli's and Timoshenko's beams (needs an even
     * {@code cellsAcross}, for nodes on the mid-planes).
     */
    public static Cantilever cantilever(VolumeParameters p, double depthM, double forceN, int cellsAcross,
            boolean slidingRoot) {
        return cantilever(p, depthM, forceN, cellsAcross, slidingRoot, null);
    }

    /**
     * As {@link #cantilever(VolumeParameters, double, double, int, boolean)}; with {@code tets} (null: a lattice)
     * the beam is the structured tetrahedral mesh of {@link BoxTets} (cubes of side D / cellsAcross cut so) built by
     * {@link VolumeBody#buildTets} instead.
     */
    public static Cantilever cantilever(VolumeParameters p, double depthM, double forceN, int cellsAcross,
            boolean slidingRoot, Tets tets) {
        if (slidingRoot && cellsAcross % 2 != 0) {
            throw new IllegalArgumentException("a sliding root needs an even number of cells across, got "
                    + cellsAcross);
        }
        Check.positive("cantilever depth", "m", depthM);
        Check.positive("cantilever tip force", "N", forceN);
        Check.atLeast("cantilever cells across", cellsAcross, 1);
        double d = depthM;
        double len = 10 * d;
        double h = d / cellsAcross;
        Topology t = new Topology();
        // the beam fits the lattice: every cell is full, which one sample at its centre tells
        VolumeBody body = tets != null ? VolumeBody.buildTets(t, tets.box(len, d, d, 10 * cellsAcross,
                cellsAcross, cellsAcross), p, "the cantilever") : VolumeBody.build(t, BoxSurface.of(len, d, d, h),
                p.withCellSize(h).withFillSamples(1), "the cantilever");
        TriangleMesh surface = body.surface();
        boolean[] fixed = new boolean[3 * t.nodeCount()];
        if (slidingRoot) {
            boolean[] root = new boolean[fixed.length];
            VolumeStatics.fixPlane(t, fixed, 0, 0, 0, len);
            VolumeStatics.fixPlane(t, root, 1, d / 2, 1, len);
            VolumeStatics.fixPlane(t, root, 2, d / 2, 2, len);
            for (int i = 0; i < fixed.length; i++) {
                fixed[i] |= root[i] && fixed[i - i % 3];
            }
        } else {
            for (int axis = 0; axis < 3; axis++) {
                VolumeStatics.fixPlane(t, fixed, 0, 0, axis, len);
            }
        }
        double eps = 1e-9 * len;
        double[] f = VolumeStatics.traction(surface, (x, y, z) -> x >= len - eps, new double[] {0, 0,
            -forceN / (d * d)});
        VolumeStatics.Solved s = VolumeStatics.solve(t, body, fixed, f, TOLERANCE);
        double deflection = VolumeStatics.conjugate(f, s.surfaceDisplacementM());
        LatticeMaterial m = tets != null ? TET_MATERIAL.apply(p) : p.material();
        double inertia = d * d * d * d / 12;
        double eb = forceN * len * len * len / (3 * m.youngPa() * inertia);
        double nu = m.modelPoisson();
        double kappa = 10 * (1 + nu) / (12 + 11 * nu);
        double shear = forceN * len / (kappa * m.shearModulusPa() * d * d);
        return new Cantilever(cellsAcross, h, body.nodeCount(), body.report().springs(), deflection, eb, eb + shear,
                s.iterations());
    }

    /**
     * The compressed block of side {@code sideM} at {@code cellsAcross} cells across (a whole number fits the
     * lattice to the cube; a fraction leaves the last layer part full).
     *
     * @param stressPa sigma, the pressure on the top face, Pa (&gt; 0)
     */
    public static Block block(VolumeParameters p, double sideM, double stressPa, double cellsAcross) {
        return block(p, sideM, stressPa, cellsAcross, null);
    }

    /**
     * As {@link #block(VolumeParameters, double, double, double)}; with {@code tets} (null: a lattice) the block is
     * the structured tetrahedral mesh of {@link BoxTets} cut so ({@code cellsAcross} must then be a whole number).
     */
    public static Block block(VolumeParameters p, double sideM, double stressPa, double cellsAcross,
            Tets tets) {
        if (tets != null && cellsAcross != Math.rint(cellsAcross)) {
            throw new IllegalArgumentException("a tetrahedral block needs a whole number of cubes across, got "
                    + cellsAcross);
        }
        Check.positive("block side", "m", sideM);
        Check.positive("block pressure", "Pa", stressPa);
        Check.positive("block cells across", "", cellsAcross);
        double s = sideM;
        double h = s / cellsAcross;
        Topology t = new Topology();
        int n = (int) Math.rint(cellsAcross);
        VolumeBody body = tets != null ? VolumeBody.buildTets(t, tets.box(s, s, s, n, n, n), p, "the block")
                : VolumeBody.build(t, BoxSurface.of(s, s, s, Math.min(h, s) / 2), p.withCellSize(h), "the block");
        TriangleMesh surface = body.surface();
        boolean[] fixed = new boolean[3 * t.nodeCount()];
        for (int axis = 0; axis < 3; axis++) {
            VolumeStatics.fixPlane(t, fixed, axis, 0, axis, s);
        }
        double eps = 1e-9 * s;
        VolumeStatics.Pick top = (x, y, z) -> z >= s - eps;
        VolumeStatics.Pick side = (x, y, z) -> x >= s - eps;
        double[] f = VolumeStatics.traction(surface, top, new double[] {0, 0, -stressPa});
        VolumeStatics.Solved r = VolumeStatics.solve(t, body, fixed, f, TOLERANCE);
        double axial = VolumeStatics.meanOver(surface, top, r.surfaceDisplacementM(), 2) / s;
        double lateral = VolumeStatics.meanOver(surface, side, r.surfaceDisplacementM(), 0) / s;
        LatticeMaterial m = tets != null ? TET_MATERIAL.apply(p) : p.material();
        return new Block(cellsAcross, h, body.nodeCount(), axial, -stressPa / m.youngPa(), lateral,
                m.modelPoisson(), m.poisson(), r.iterations());
    }

    /**
     * Observed order of convergence from three solutions at cell sizes h1 &gt; h2 &gt; h3 in a constant ratio r:
     * {@code log(|q1 - q2| / |q2 - q3|) / log r} (needs no exact answer; NaN when the differences vanish).
     */
    public static double observedOrder(double q1, double q2, double q3, double ratio) {
        double a = Math.abs(q1 - q2);
        double b = Math.abs(q2 - q3);
        return a > 0 && b > 0 ? Math.log(a / b) / Math.log(ratio) : Double.NaN;
    }

    /** Order of the error against a reference between two cell sizes: {@code log(|e1| / |e2|) / log(h1 / h2)}. */
    public static double orderAgainst(double e1, double e2, double h1, double h2) {
        return Math.log(Math.abs(e1) / Math.abs(e2)) / Math.log(h1 / h2);
    }
}

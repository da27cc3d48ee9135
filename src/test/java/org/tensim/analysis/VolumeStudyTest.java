package org.tensim.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.scene.volume.BoxTets;
import org.tensim.scene.volume.SpringFit;
import org.tensim.scene.volume.VolumeParameters;

/**
 * The volume body's known answers at three resolutions each (the larger study: {@code ./tensim volume-study},
 * docs/volume.md): Euler-Bernoulli's cantilever and the compressed block's uniaxial strain.
 */
class VolumeStudyTest {
    private static final VolumeParameters LUNG = VolumeParameters.of(0.01, 1e3, 0.4, 300);
    private static final double DEPTH_M = 0.02;
    private static final double FORCE_N = 1e-4;

    @Test
    void cantileverConvergesToEulerBernoulliAtSecondOrder() {
        int[] across = {2, 4, 8};
        double[] q = new double[3];
        double[] e = new double[3];
        for (int i = 0; i < 3; i++) {
            VolumeStudy.Cantilever c = VolumeStudy.cantilever(LUNG, DEPTH_M, FORCE_N, across[i]);
            q[i] = c.deflectionM();
            e[i] = c.errorAgainstEulerBernoulli();
            System.out.printf("cantilever, %d cells across: tip %.6g m, Euler-Bernoulli %.6g m (%+.2f %%),"
                    + " Timoshenko %.6g m%n", across[i], q[i], c.eulerBernoulliM(), 100 * e[i], c.timoshenkoM());
            if (i > 0) {
                assertTrue(q[i] > q[i - 1], "a finer lattice is softer in bending: " + q[i] + " after " + q[i - 1]);
            }
        }
        double observed = VolumeStudy.observedOrder(q[0], q[1], q[2], 2);
        double againstBeam = VolumeStudy.orderAgainst(e[1], e[2], 2, 1);
        System.out.printf("cantilever: observed order %.2f, against Euler-Bernoulli %.2f%n", observed, againstBeam);
        assertTrue(Math.abs(e[2]) < 0.05, "within 5 % of Euler-Bernoulli at 8 cells across: " + e[2]);
        // measured 1.63 (observed from 2, 4 and 8 cells: 2 cells across is not yet asymptotic) and 2.07 (against the
        // beam, from 4 and 8 cells); docs/volume.md gives the study to 16 cells
        assertEquals(1.63, observed, 0.2, "observed order");
        assertEquals(2.07, againstBeam, 0.2, "order against Euler-Bernoulli");
    }

    @Test
    void clippedBlockConvergesToTheUniaxialStrainAndReportsItsLateralStrain() {
        double[] across = {2.5, 4.5, 8.5};
        double[] e = new double[3];
        VolumeStudy.Block b = null;
        for (int i = 0; i < 3; i++) {
            b = VolumeStudy.block(LUNG, DEPTH_M, 10, across[i]);
            e[i] = b.strainError();
            System.out.printf("block, %.1f cells across: strain %.6g against -sigma/E %.6g (%+.3f %%), lateral"
                    + " strain %.6g, measured nu %.4f (the lattice's %.3f, asked %.3f)%n", across[i], b.axialStrain(),
                    b.expectedStrain(), 100 * e[i], b.lateralStrain(), b.measuredPoisson(), b.modelPoisson(),
                    b.requestedPoisson());
        }
        double order = VolumeStudy.orderAgainst(e[1], e[2], 1 / 4.5, 1 / 8.5);
        System.out.printf("block: order %.2f%n", order);
        assertTrue(Math.abs(e[2]) < 0.05, "within 5 % of -sigma / E: " + e[2]);
        assertTrue(Math.abs(e[2]) < Math.abs(e[1]) && Math.abs(e[1]) < Math.abs(e[0]), java.util.Arrays.toString(e));
        assertEquals(2, order, 0.3, "order of the clipped block's strain");
        // the isotropic lattice's Poisson ratio is 1/4, whatever nu was asked for
        assertEquals(0.25, b.measuredPoisson(), 0.01 * 0.25);
        assertEquals(0.4, b.requestedPoisson(), 0);
    }

    @Test
    void axialFitGivesTheRequestedLateralStrainAndAWholeCellBlockIsExactBeyondItsLoad() {
        VolumeParameters axial = LUNG.withFit(SpringFit.AXIAL);
        VolumeStudy.Block b = VolumeStudy.block(axial, DEPTH_M, 10, 8.5);
        assertTrue(Math.abs(b.strainError()) < 0.01, "axial strain: " + b.strainError());
        assertEquals(0.4, b.measuredPoisson(), 0.01 * 0.4);
        // a lattice that fits the block: only the load's spreading over the top face's nodes remains (order h^3)
        VolumeStudy.Block whole = VolumeStudy.block(LUNG, DEPTH_M, 10, 4);
        assertTrue(Math.abs(whole.strainError()) < 5e-4, "whole cells: " + whole.strainError());
    }

    /**
     * The tetrahedral variant (five tets a cube, {@link BoxTets.Split#FIVE}) on the cantilever: softer as it is
     * refined, within 5 % of Euler-Bernoulli at 8 cubes across, at about second order.
     */
    @Test
    void tetCantileverConvergesToEulerBernoulli() {
        int[] across = {2, 4, 8};
        double[] q = new double[3];
        double[] e = new double[3];
        for (int i = 0; i < 3; i++) {
            VolumeStudy.Cantilever c = VolumeStudy.cantilever(LUNG, DEPTH_M, FORCE_N, across[i], false,
                    VolumeStudy.Tets.of(BoxTets.Split.FIVE));
            q[i] = c.deflectionM();
            e[i] = c.errorAgainstEulerBernoulli();
            System.out.printf("tet cantilever, %d cubes across (%d nodes): tip %.6g m (%+.2f %%)%n", across[i],
                    c.nodes(), q[i], 100 * e[i]);
            if (i > 0) {
                assertTrue(q[i] > q[i - 1], "softer when finer: " + q[i] + " after " + q[i - 1]);
            }
        }
        double observed = VolumeStudy.observedOrder(q[0], q[1], q[2], 2);
        double againstBeam = VolumeStudy.orderAgainst(e[1], e[2], 2, 1);
        System.out.printf("tet cantilever: observed order %.2f, against Euler-Bernoulli %.2f%n", observed,
                againstBeam);
        assertTrue(Math.abs(e[2]) < 0.05, "within 5 % of Euler-Bernoulli at 8 cubes across: " + e[2]);
        // measured -20.87, -5.48, -0.98 %: orders 1.78 (observed) and 2.48 (against the beam, 4 and 8 cubes)
        assertEquals(1.78, observed, 0.2, "observed order");
        assertEquals(2.48, againstBeam, 0.3, "order against Euler-Bernoulli");
    }

    /**
     * The tetrahedral block (five tets a cube, whole cubes): within 1 % of -sigma / E at every resolution, converging
     * at first order to a network about 1 % softer than E with a Poisson ratio below the target's 1/4 (the springs
     * are fitted tet by tet, and the assembled network is not the isotropic target: docs/volume.md).
     */
    @Test
    void tetBlockIsWithinOnePercentOfTheUniaxialStrainAndReportsTheNetworksPoissonRatio() {
        double[] across = {2, 4, 8};
        double[] q = new double[3];
        VolumeStudy.Block b = null;
        for (int i = 0; i < 3; i++) {
            b = VolumeStudy.block(LUNG, DEPTH_M, 10, across[i], VolumeStudy.Tets.of(BoxTets.Split.FIVE));
            q[i] = b.axialStrain();
            System.out.printf("tet block, %.0f cubes across: strain %.6g (%+.3f %%), measured nu %.4f%n", across[i],
                    q[i], 100 * b.strainError(), b.measuredPoisson());
            assertTrue(Math.abs(b.strainError()) < 0.01, "within 1 % of -sigma / E: " + b.strainError());
        }
        double observed = VolumeStudy.observedOrder(q[0], q[1], q[2], 2);
        System.out.printf("tet block: observed order %.2f%n", observed);
        // measured 0.92; nu 0.172, 0.184, 0.190 (0.193 at 16 cubes)
        assertEquals(0.92, observed, 0.2, "observed order of the strain");
        assertEquals(0.190, b.measuredPoisson(), 0.005, "the network's Poisson ratio at 8 cubes across");
    }

    /**
     * Kuhn's six tets a cube give every cube one body diagonal: the fitted network is measurably anisotropic, about
     * 8 % softer along the axes than E and with almost no Poisson effect, which is why the five-tet split is the
     * study's default.
     */
    @Test
    void theSixTetSplitsNetworkIsSofterAlongTheAxesAndNearlyWithoutPoissonEffect() {
        VolumeStudy.Block b = VolumeStudy.block(LUNG, DEPTH_M, 10, 4, VolumeStudy.Tets.of(BoxTets.Split.SIX));
        System.out.printf("six-tet block, 4 cubes across: strain error %+.3f %%, measured nu %.4f%n",
                100 * b.strainError(), b.measuredPoisson());
        // measured +8.42 % and nu 0.052 (+7.16 % and 0.044 at 16 cubes)
        assertEquals(0.0842, b.strainError(), 0.005);
        assertEquals(0.052, b.measuredPoisson(), 0.005);
    }

    /**
     * Tets of many shapes (the five-tet box with its interior nodes jittered by up to 0.15 of a cube): the network is
     * another material again, here stiffer along the load, with nu about 0.18; the identification is mesh-dependent.
     */
    @Test
    void aJitteredTetBlockMeasuresItsOwnMaterial() {
        VolumeStudy.Block b = VolumeStudy.block(LUNG, DEPTH_M, 10, 4, new VolumeStudy.Tets(BoxTets.Split.FIVE, 0.15));
        System.out.printf("jittered tet block, 4 cubes across: strain error %+.3f %%, measured nu %.4f%n",
                100 * b.strainError(), b.measuredPoisson());
        // measured -1.880 % and nu 0.1845 (-3.605 % and 0.1984 at 16 cubes)
        assertEquals(-0.0188, b.strainError(), 0.001);
        assertEquals(0.1845, b.measuredPoisson(), 0.005);
    }
}

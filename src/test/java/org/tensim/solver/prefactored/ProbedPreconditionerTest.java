package org.tensim.solver.prefactored;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.scene.diaphragm.BreathingCycle;
import org.tensim.scene.diaphragm.DiaphragmControls;
import org.tensim.scene.diaphragm.DiaphragmParameters;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.solver.Simulation;

/**
 * The probed preconditioner ({@link PreconditionerMatrix#PROBED}) on a coarse diaphragm (membrane, shear
 * elements, fibres, rigid columns, the band): converged, it gives the isotropic matrix's step; with the real-time
 * setting's four CG iterations it comes closer to the converged step than the isotropic matrix does.
 */
class ProbedPreconditionerTest {
    static final double SECONDS = 0.5;
    static final double DT = 0.025;

    private static DiaphragmScene scene() throws Exception {
        return DiaphragmSetup.generated(12, null, DiaphragmParameters.defaults(), new BreathingCycle(4, 2),
                new DiaphragmControls(1, DiaphragmSetup.defaultMusclePa())).scene();
    }

    private static double[] run(DiaphragmScene scene, PrefactoredBdf2 bdf2) {
        Simulation sim = scene.newSimulation();
        sim.setIntegrator(bdf2);
        sim.runUntil(SECONDS, DT);
        double[] d = new double[3 * scene.diaphragmNodes()];
        for (int k = 0; k < d.length; k++) {
            d[k] = sim.state().x[k] - sim.state().x0[k];
        }
        return d;
    }

    private static double relativeRms(double[] d, double[] ref) {
        double num = 0;
        double den = 0;
        for (int k = 0; k < d.length; k++) {
            num += (d[k] - ref[k]) * (d[k] - ref[k]);
            den += ref[k] * ref[k];
        }
        return Math.sqrt(num / den);
    }

    private static PrefactoredBdf2 bdf2(PreconditionerMatrix m, int newton, int cg) {
        return new PrefactoredBdf2().setPreconditioner(m).setNewtonIterations(newton).setKrylovIterations(cg);
    }

    @Test
    void convergedItGivesTheIsotropicMatrixsStepAndWithFourIterationsComesCloser() throws Exception {
        DiaphragmScene scene = scene();
        PrefactoredBdf2 probedConverged = bdf2(PreconditionerMatrix.PROBED, 4, 60);
        double[] probed = run(scene, probedConverged);
        assertTrue(probedConverged.preconditionerProbed(), "the diaphragm's matrix is probed");
        assertEquals(0, probedConverged.probedFallbacks(), "the probed matrix was positive definite");
        PrefactoredBdf2 isoConverged = bdf2(PreconditionerMatrix.ISOTROPIC, 4, 60);
        double[] iso = run(scene, isoConverged);
        assertFalse(isoConverged.preconditionerProbed());
        double same = relativeRms(probed, iso);
        double probed4 = relativeRms(run(scene, bdf2(PreconditionerMatrix.PROBED, 1, 4)), iso);
        double iso4 = relativeRms(run(scene, bdf2(PreconditionerMatrix.ISOTROPIC, 1, 4)), iso);
        System.out.printf("converged probed vs isotropic %.3g; 1 x 4 from converged: probed %.4f, isotropic %.4f%n",
                same, probed4, iso4);
        assertTrue(same < 1e-4, "converged, the two preconditioners give one step: " + same);
        assertTrue(probed4 < 0.8 * iso4, "1 x 4 CG: probed " + probed4 + " against isotropic " + iso4);
    }

    /**
     * On the diaphragm, at its linearisation after a step, the probed entries are the operator's own: each node's
     * diagonal block and the mean diagonal of its blocks with its neighbours, against the columns of
     * {@code P^T J P} computed one by one.
     */
    @Test
    void theProbedEntriesAreTheOperatorsColumns() throws Exception {
        DiaphragmScene scene = scene();
        Simulation sim = scene.newSimulation();
        PrefactoredBdf2 bdf2 = new PrefactoredBdf2();
        sim.setIntegrator(bdf2);
        sim.step(DT);
        sim.step(DT);
        JacobianProbe probe = bdf2.matrix().probe();
        JacobianProbe.Operator a = bdf2.newtonKrylov().probeOperator();
        probe.restart();
        probe.run(a, Integer.MAX_VALUE);
        int n = bdf2.matrix().freeCount();
        double[] v = new double[3 * n];
        double[][] y = new double[3][3 * n];
        java.util.Random rnd = new java.util.Random(7);
        double worst = 0;
        double scale = 0;
        java.util.List<Integer> sampled = new java.util.ArrayList<>();
        for (int i = 0; i < n; i++) {
            if (probe.rowStart[i + 1] - probe.rowStart[i] > JacobianProbe.HUB_DEGREE) {
                sampled.add(i); // every hub
            }
        }
        assertTrue(!sampled.isEmpty(), "the diaphragm has hubs");
        for (int k = 0; k < 40; k++) {
            sampled.add(rnd.nextInt(n));
        }
        for (int j : sampled) {
            for (int d = 0; d < 3; d++) {
                java.util.Arrays.fill(v, 0);
                v[3 * j + d] = 1;
                a.apply(v, y[d]);
            }
            for (int r = 0; r < 3; r++) {
                for (int d = 0; d < 3; d++) {
                    worst = Math.max(worst, Math.abs(y[d][3 * j + r] - probe.diagonalBlocks()[9 * j + 3 * r + d]));
                    scale = Math.max(scale, Math.abs(y[d][3 * j + r]));
                }
            }
            for (int p = probe.rowStart[j]; p < probe.rowStart[j + 1]; p++) {
                int i = probe.column[p];
                double mean = (y[0][3 * i] + y[1][3 * i + 1] + y[2][3 * i + 2]) / 3;
                worst = Math.max(worst, Math.abs(mean - probe.traces()[probe.entry(i, j)]));
            }
            // Nothing outside the graph.
            for (int i = 0; i < n; i++) {
                boolean inGraph = java.util.Arrays.binarySearch(probe.column, probe.rowStart[j], probe.rowStart[j + 1], i) >= 0;
                for (int d = 0; d < 3 && !inGraph; d++) {
                    for (int r = 0; r < 3; r++) {
                        assertEquals(0, y[d][3 * i + r], 1e-12 * scale, "entry (" + i + ", " + j + ") outside the graph");
                    }
                }
            }
        }
        assertTrue(worst <= 1e-9 * scale, "largest difference " + worst + " against entries up to " + scale);
    }
}

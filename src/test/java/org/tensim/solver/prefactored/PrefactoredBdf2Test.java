package org.tensim.solver.prefactored;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;

/**
 * The large-step BDF2 solver: exact static equilibria at large steps (fixed, driven and viscous
 * boundary conditions), the background refactorisation that never makes a step wait.
 */
class PrefactoredBdf2Test {
    static final double G = 9.81;

    /**
     * A vertical chain of n + 1 nodes, spacing L, top node fixed (or driven to a constant offset),
     * under gravity, with axial and viscous damping. At equilibrium spring i (from the top, 1-based)
     * carries the weight of the n - i + 1 nodes below it: its stretch is m g (n - i + 1) / k.
     */
    static Topology chain(int n, double m, double k, double l, Vec3 topOffset) {
        Topology t = new Topology();
        List<Node> nodes = new ArrayList<>();
        for (int i = 0; i <= n; i++) {
            nodes.add(t.addNode(0, 0, -i * l, m));
        }
        if (topOffset == null) {
            nodes.get(0).fix();
        } else {
            nodes.get(0).drive((time, rest, out, o) -> {
                out[o] = rest.x() + topOffset.x();
                out[o + 1] = rest.y() + topOffset.y();
                out[o + 2] = rest.z() + topOffset.z();
            });
        }
        for (int i = 0; i < n; i++) {
            t.addSpring(nodes.get(i), nodes.get(i + 1), k, 0.2 * Math.sqrt(k * m));
        }
        t.setGravity(new Vec3(0, 0, -G));
        t.setViscousDamping(0.05 * Math.sqrt(k * m));
        return t;
    }

    static double exactZ(int node, int n, double m, double k, double l, double top) {
        double z = top;
        for (int i = 1; i <= node; i++) {
            z -= l + m * G * (n - i + 1) / k;
        }
        return z;
    }

    @Test
    void reachesTheExactEquilibriumOfAHangingChainAtLargeSteps() {
        int n = 12;
        double m = 0.01;
        double k = 50;
        double l = 0.01;
        // w h = sqrt(k / m) h = 70 x 0.05 = 3.5 for one spring, more for the chain's stiffest mode:
        // far beyond any explicit method's limit.
        Simulation sim = new Simulation(SystemState.compile(chain(n, m, k, l, null)), new PrefactoredBdf2());
        sim.runUntil(30, 0.05);
        SystemState s = sim.state();
        for (int i = 0; i <= n; i++) {
            assertEquals(exactZ(i, n, m, k, l, 0), s.x[3 * i + 2], 1e-9, "z of node " + i);
            assertEquals(0, s.x[3 * i], 1e-12, "x of node " + i);
        }
    }

    @Test
    void aDrivenTopNodeCarriesTheChainToItsShiftedEquilibrium() {
        int n = 8;
        double m = 0.02;
        double k = 80;
        double l = 0.02;
        Vec3 off = new Vec3(0.01, -0.02, 0.03);
        PrefactoredBdf2 bdf2 = new PrefactoredBdf2();
        Simulation sim = new Simulation(SystemState.compile(chain(n, m, k, l, off)), bdf2);
        sim.runUntil(30, 0.04);
        SystemState s = sim.state();
        for (int i = 0; i <= n; i++) {
            assertEquals(off.x(), s.x[3 * i], 1e-9, "x of node " + i);
            assertEquals(off.y(), s.x[3 * i + 1], 1e-9, "y of node " + i);
            assertEquals(exactZ(i, n, m, k, l, off.z()), s.x[3 * i + 2], 1e-9, "z of node " + i);
        }
        assertEquals(1, bdf2.synchronousFactorisations(), "the first step factors, once");
        assertTrue(bdf2.errorEstimate() < 1e-6, "at rest the error estimate vanishes: " + bdf2.errorEstimate());
    }

    /**
     * A chain moved along its length by its top node, {@code z = A sin(2 pi t / T)}: where the motion passes its
     * start (t = T/2, T) the displacement from the initial positions nearly vanishes, and the estimate stays
     * relative to the motion's amplitude instead of growing without bound; it is smaller at a smaller step.
     */
    @Test
    void theErrorEstimateIsRelativeToTheMotionsAmplitude() {
        double[] atCrossing = new double[2]; // the largest estimate over the cycle
        double[] steps = {0.02, 0.002};
        for (int r = 0; r < 2; r++) {
            Topology t = new Topology();
            List<Node> nodes = new ArrayList<>();
            for (int i = 0; i <= 6; i++) {
                nodes.add(t.addNode(0, 0, -0.02 * i, 0.01));
            }
            nodes.get(0).drive((time, rest, out, o) -> {
                out[o] = rest.x();
                out[o + 1] = rest.y();
                out[o + 2] = rest.z() + 0.01 * Math.sin(2 * Math.PI * time);
            });
            for (int i = 0; i < 6; i++) {
                t.addSpring(nodes.get(i), nodes.get(i + 1), 1e4, 2);
            }
            PrefactoredBdf2 bdf2 = new PrefactoredBdf2();
            Simulation sim = new Simulation(SystemState.compile(t), bdf2);
            int n = (int) Math.round(1 / steps[r]);
            for (int i = 1; i <= n; i++) {
                sim.runUntil(i * steps[r], steps[r]);
                if (i * steps[r] > 0.2) { // the largest estimate over the cycle, crossings at 0.5 and 1 s included
                    atCrossing[r] = Math.max(atCrossing[r], bdf2.errorEstimate());
                }
            }
        }
        // Measured 3.6e-4 and 5.3e-5; divided by the displacement of the moment instead, 44 at 20 ms.
        assertTrue(atCrossing[0] < 0.01, "largest over the cycle, 20 ms: " + atCrossing[0]);
        assertTrue(atCrossing[1] < atCrossing[0], "smaller at a smaller step: " + atCrossing[1] + " against "
                + atCrossing[0]);
    }

    /** An executor that holds its jobs until released: a refactorisation as slow as a test wants. */
    static final class HeldExecutor implements java.util.concurrent.Executor {
        final List<Runnable> held = new ArrayList<>();

        @Override
        public synchronized void execute(Runnable r) {
            held.add(r);
        }

        synchronized void release() {
            for (Runnable r : held) {
                r.run();
            }
            held.clear();
        }
    }

    @Test
    void aStiffnessChangeRefactorsInTheBackgroundWhileStepsGoOnWithTheOldFactor() {
        int n = 12;
        double m = 0.01;
        double k = 50;
        double l = 0.01;
        HeldExecutor slow = new HeldExecutor();
        PrefactoredBdf2 bdf2 = new PrefactoredBdf2().setRefactorExecutor(slow);
        Simulation sim = new Simulation(SystemState.compile(chain(n, m, k, l, null)), bdf2);
        sim.runUntil(1, 0.05);
        assertEquals(1, bdf2.synchronousFactorisations());
        SystemState s = sim.state();
        for (int i = 0; i < s.springCount(); i++) {
            s.setSpringStiffness(i, 4 * k); // the stiffness quadruples while running
        }
        long before = sim.steps();
        sim.runUntil(30, 0.05); // the refactorisation is held back all this time
        assertTrue(sim.steps() > before + 500, "steps went on");
        assertEquals(1, slow.held.size(), "one refactorisation requested, not one per step");
        assertTrue(bdf2.refactorInFlight());
        assertEquals(1, bdf2.synchronousFactorisations(), "no step waited for the new factor");
        assertEquals(0, bdf2.backgroundFactorisations());
        // With the old factor as preconditioner the steps still reach the new equilibrium.
        for (int i = 0; i <= n; i++) {
            assertEquals(exactZ(i, n, m, 4 * k, l, 0), s.x[3 * i + 2], 1e-9, "z of node " + i + " (old factor)");
        }
        slow.release();
        sim.step(0.05);
        assertEquals(1, bdf2.backgroundFactorisations(), "the new factor is taken at the next step");
        assertTrue(!bdf2.refactorInFlight());
        sim.step(0.03); // a new step size: refactored in the background as well
        assertEquals(1, slow.held.size());
        assertEquals(1, bdf2.synchronousFactorisations());
    }
}

package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.hipparchus.linear.Array2DRowRealMatrix;
import org.hipparchus.linear.EigenDecompositionSymmetric;
import org.junit.jupiter.api.Test;
import org.tensim.model.ForceLaw;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.solver.integrators.ImplicitEuler;
import org.tensim.solver.parallel.ParallelSpringPass;
import org.tensim.solver.parallel.Parallelism;
import org.tensim.solver.prefactored.PrefactoredBdf2;
import org.tensim.solver.stability.CriticalTimeStep;
import org.tensim.testsupport.AllocationCounter;

/**
 * Membrane triangles in the solvers: the critical step counts them (against a dense eigenvalue
 * solve), the implicit solvers (their Jacobians include the triangles' tangent) reach the static
 * equilibrium at steps far beyond the explicit limit, and the multi-threaded force pass adds them.
 */
class TriangleSolversTest {
    private static final double E = 30e3;
    private static final double T = 2e-3;

    /**
     * A square sheet of side 0.05 m, n x n cells cut along alternating diagonals, with springs on
     * its border (so that springs and triangles mix); the x = 0 edge fixed, the x = side edge pulled
     * along x by {@code pullN} per node.
     */
    static Topology sheet(int n, double nu, double pullN) {
        double side = 0.05;
        Topology t = new Topology();
        double mass = 1060 * side * side * T / ((n + 1) * (n + 1));
        for (int j = 0; j <= n; j++) {
            for (int i = 0; i <= n; i++) {
                var node = t.addNode(i * side / n, j * side / n, 0.001 * Math.sin(3.0 * i + j), mass);
                if (i == 0) {
                    node.fix();
                } else if (i == n && pullN != 0) {
                    t.applyForce(node, ForceLaw.constant(new Vec3(pullN, 0, 0)));
                }
            }
        }
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                int a = j * (n + 1) + i;
                boolean flip = (i + j) % 2 == 0;
                t.addTriangle(a, a + 1, flip ? a + n + 2 : a + n + 1, T, E, nu);
                t.addTriangle(flip ? a : a + 1, a + n + 2, a + n + 1, T, E, nu);
            }
            t.addSpring(t.node(j * (n + 1) + n), t.node((j + 1) * (n + 1) + n), 0.5 * E * T, 0);
        }
        return t;
    }

    @Test
    void criticalStepCountsTheTrianglesAsADenseEigenSolveDoes() {
        SystemState s = SystemState.compile(sheet(4, 0.45, 0));
        CriticalTimeStep c = s.criticalTimeStep();
        // Dense M^-1/2 K M^-1/2 on the free coordinates: springs and triangles at rest.
        int n3 = 3 * s.nodeCount;
        TriangleTangent k = new TriangleTangent(s);
        double[][] a = new double[n3][n3];
        for (int col = 0; col < n3; col++) {
            double[] e = new double[n3];
            e[col] = 1;
            double[] y = new double[n3];
            k.multiplyAdd(e, y, null);
            for (int sp = 0; sp < s.springCount(); sp++) {
                int p = s.springA[sp];
                int q = s.springB[sp];
                double[] d = new double[3];
                double len = 0;
                for (int i = 0; i < 3; i++) {
                    d[i] = s.x0[3 * q + i] - s.x0[3 * p + i];
                    len += d[i] * d[i];
                }
                double proj = 0;
                for (int i = 0; i < 3; i++) {
                    proj += d[i] * (e[3 * q + i] - e[3 * p + i]) / len;
                }
                for (int i = 0; i < 3; i++) {
                    y[3 * q + i] += s.springK[sp] * proj * d[i];
                    y[3 * p + i] -= s.springK[sp] * proj * d[i];
                }
            }
            for (int row = 0; row < n3; row++) {
                a[row][col] = y[row] * Math.sqrt(s.invMass[row / 3] * s.invMass[col / 3]);
            }
        }
        for (int i = 0; i < n3; i++) {
            for (int j = 0; j < i; j++) {
                double m = 0.5 * (a[i][j] + a[j][i]); // round-off of the products
                a[i][j] = m;
                a[j][i] = m;
            }
        }
        double[] ev = new EigenDecompositionSymmetric(new Array2DRowRealMatrix(a, false)).getEigenvalues();
        double w = Math.sqrt(java.util.Arrays.stream(ev).max().getAsDouble());
        assertTrue(w > 0);
        assertEquals(w, c.omegaMaxPower(), 2e-3 * w, "power iteration");
        assertTrue(c.omegaMaxGershgorin() >= w * (1 - 1e-12), "Gershgorin " + c.omegaMaxGershgorin() + " < " + w);
        // Without the triangles the estimate would be far lower: they are most of the stiffness.
        CriticalTimeStep springsOnly = CriticalTimeStep.estimate(s.nodeCount, s.springA, s.springB, s.springK,
                s.mass, s.invMass, s.x0);
        assertTrue(springsOnly.omegaMaxPower() < 0.8 * w, "springs alone: " + springsOnly.omegaMaxPower());
    }

    @Test
    void implicitSolversReachTheStaticEquilibriumAtLargeSteps() {
        for (Integrator in : new Integrator[] {new PrefactoredBdf2(), new ImplicitEuler().setTolerance(1e-10)}) {
            Topology t = sheet(5, 0.4, 0.02);
            t.setViscousDamping(2e-4);
            Simulation sim = new Simulation(SystemState.compile(t), in);
            double crit = sim.criticalTimeStep().stepSeconds();
            double h = 20 * crit; // far beyond any explicit method's limit
            sim.runUntil(4000 * h, h);
            SystemState s = sim.state();
            double[] f = new double[3 * s.nodeCount];
            sim.forces().computeForces(sim.time(), s.x, new double[f.length], f);
            double worst = 0;
            for (int i = 0; i < s.nodeCount; i++) {
                if (s.invMass[i] != 0) {
                    for (int d = 0; d < 3; d++) {
                        worst = Math.max(worst, Math.abs(f[3 * i + d]));
                    }
                }
            }
            assertTrue(worst < 1e-6 * 0.02, in.name() + ": largest residual force " + worst + " N");
            double stretch = s.x[3 * 5] - s.x0[3 * 5];
            assertTrue(stretch > 0, in.name() + " stretches the sheet, " + stretch);
        }
    }

    /** Steps with triangles allocate nothing once warm (explicit RK2, BDF2 with its Jacobian, implicit Euler). */
    @Test
    void stepsWithTrianglesAllocateNothing() {
        for (Integrator in : new Integrator[] {new MidpointRK2(), new PrefactoredBdf2(), new ImplicitEuler()}) {
            Topology t = sheet(5, 0.45, 0.01);
            t.setViscousDamping(1e-2); // RK2 needs some damping to be stable at any step
            Simulation sim = new Simulation(SystemState.compile(t), in);
            double h = in.explicit() ? 0.3 * sim.criticalTimeStep().stepSeconds() : 1e-3;
            for (int i = 0; i < 3000; i++) {
                sim.step(h);
            }
            long bytes = AllocationCounter.currentThread().bytesAllocatedBy(() -> {
                for (int i = 0; i < 300; i++) {
                    sim.step(h);
                }
            }, 2);
            assertEquals(0, bytes, in.name() + ": bytes allocated by 300 steps");
        }
    }

    @Test
    void theParallelForcePassAddsTheTriangles() {
        Topology t = sheet(6, 0.3, 0.01);
        Simulation serial = new Simulation(SystemState.compile(t));
        Simulation parallel = new Simulation(SystemState.compile(t));
        double[] x = serial.state().x.clone();
        for (int k = 0; k < x.length; k++) {
            x[k] *= 1 + 0.01 * Math.sin(k);
        }
        double[] v = new double[x.length];
        double[] fs = new double[x.length];
        double[] fp = new double[x.length];
        serial.forces().computeForces(0, x, v, fs);
        try (Parallelism p = Parallelism.install(parallel, 2, ParallelSpringPass.Order.AUTO, 1)) {
            assertTrue(parallel.forces().trianglePass() != null, "a parallel triangle pass is installed");
            parallel.forces().computeForces(0, x, v, fp);
        }
        double[] one = new double[x.length];
        try (Parallelism p = Parallelism.install(parallel, 1, ParallelSpringPass.Order.AUTO, 1)) {
            parallel.forces().computeForces(0, x, v, one);
        }
        assertTrue(parallel.forces().trianglePass() == null, "closing restores the serial loop");
        for (int k = 0; k < x.length; k++) {
            assertEquals(one[k], fp[k], 0, "the same bits with one thread or two, component " + k);
        }
        double scale = 0;
        for (double value : fs) {
            scale = Math.max(scale, Math.abs(value));
        }
        double[] springsOnly = new double[x.length];
        serial.forces().springs(x, springsOnly);
        double triangles = 0;
        for (int k = 0; k < x.length; k++) {
            assertEquals(fs[k], fp[k], 1e-12 * scale, "component " + k);
            triangles = Math.max(triangles, Math.abs(fs[k] - springsOnly[k]));
        }
        assertTrue(triangles > 0.1 * scale, "the triangles' forces are in the comparison");
    }
}

package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tensim.testsupport.FiniteDifferences.maxAbs;
import static org.tensim.testsupport.FiniteDifferences.perturbed;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.model.Topology;
import org.tensim.solver.integrators.ImplicitEuler;
import org.tensim.solver.prefactored.PrefactoredBdf2;
import org.tensim.testsupport.AllocationCounter;
import org.tensim.testsupport.FiniteDifferences;
import org.tensim.testsupport.RandomMeshes;

/**
 * The transverse shear element ({@link org.tensim.model.TransverseShear}, {@link ShearElements}) as
 * physics: forces are minus the energy's gradient, the tangent is the forces' derivative, the energy
 * ignores rigid motions, and pure bending of a cylinder or a sphere (columns on the normals) costs
 * nothing (no shear locking) while a fold with upright columns does.
 */
class ShearElementsTest {
    private static final double KAPPA_G = RandomMeshes.SHEAR_KAPPA_G;
    private static final double T = RandomMeshes.SHEAR_T;

    @Test
    void forcesAreMinusTheEnergyGradient() {
        Random rnd = new Random(3);
        SystemState s = SystemState.compile(RandomMeshes.shears(rnd, 0));
        double[] x = perturbed(s.x, rnd, 1e-3);
        double[] f = new double[x.length];
        s.shears.forces(x, f);
        double scale = maxAbs(f);
        assertTrue(scale > 0, "the deformed elements exert forces");
        double[] g = FiniteDifferences.gradient(s.shears::energy, x, 1e-8);
        for (int k = 0; k < x.length; k++) {
            assertEquals(-g[k], f[k], 1e-6 * scale, "component " + k);
        }
    }

    @Test
    void tangentIsTheDerivativeOfTheForcesAndItsFirstTermIsPositive() {
        Random rnd = new Random(5);
        SystemState s = SystemState.compile(RandomMeshes.shears(rnd, 0));
        double[] x = perturbed(s.x, rnd, 1e-3);
        double[] z = perturbed(s.x, rnd, 1);
        for (int k = 0; k < z.length; k++) {
            z[k] -= s.x[k];
        }
        s.shears.linearise(x, true);
        double[] kz = new double[x.length];
        s.shears.multiplyAdd(z, kz, null, 1);
        double[] df = FiniteDifferences.directional(s.shears::forces, x, z, 1e-7);
        double scale = maxAbs(kz);
        assertTrue(scale > 0);
        for (int k = 0; k < x.length; k++) {
            assertEquals(-df[k], kz[k], 1e-5 * scale, "component " + k);
        }
        // Without the geometric term: z . K z >= 0 for any z, and the diagonal matches e_k . K e_k.
        s.shears.linearise(x, false);
        double[] diag = new double[x.length];
        s.shears.addDiagonal(diag, 1);
        for (int trial = 0; trial < 20; trial++) {
            double[] w = perturbed(s.x, rnd, 1);
            double[] kw = new double[x.length];
            s.shears.multiplyAdd(w, kw, null, 1);
            double q = 0;
            for (int k = 0; k < x.length; k++) {
                q += w[k] * kw[k];
            }
            assertTrue(q >= -1e-12 * maxAbs(kw), "z . K z = " + q);
        }
        for (int k = 0; k < x.length; k++) {
            double[] unit = new double[x.length];
            unit[k] = 1;
            double[] ku = new double[x.length];
            s.shears.multiplyAdd(unit, ku, null, 1);
            assertEquals(ku[k], diag[k], 1e-12 * maxAbs(diag), "diagonal " + k);
        }
    }

    @Test
    void aCompactProductLeavesOutTheNodesWithoutAnOffset() {
        // The implicit solvers apply the tangent on the free nodes only (compact offsets, -1 for the
        // others): the same as the full product with z = 0 on the left-out nodes, read on the others.
        Random rnd = new Random(9);
        SystemState s = SystemState.compile(RandomMeshes.shears(rnd, 0));
        double[] x = perturbed(s.x, rnd, 1e-3);
        s.shears.linearise(x, true);
        int n = s.nodeCount;
        int[] off = new int[n];
        int m = 0;
        for (int i = 0; i < n; i++) {
            off[i] = i % 3 == 1 ? -1 : 3 * m++;
        }
        double[] zc = new double[3 * m];
        double[] zf = new double[3 * n];
        for (int i = 0; i < n; i++) {
            for (int d = 0; d < 3 && off[i] >= 0; d++) {
                zc[off[i] + d] = rnd.nextGaussian();
                zf[3 * i + d] = zc[off[i] + d];
            }
        }
        double[] yf = new double[3 * n];
        double[] yc = new double[3 * m];
        s.shears.multiplyAdd(zf, yf, null, 0.7, 0.2);
        s.shears.multiplyAdd(zc, yc, off, 0.7, 0.2);
        double scale = maxAbs(yf);
        assertTrue(scale > 0);
        for (int i = 0; i < n; i++) {
            for (int d = 0; d < 3 && off[i] >= 0; d++) {
                assertEquals(yf[3 * i + d], yc[off[i] + d], 1e-12 * scale, "node " + i);
            }
        }
    }

    @Test
    void energyIgnoresRigidMotionsAndTheRestStateIsForceFree() {
        Random rnd = new Random(9);
        SystemState s = SystemState.compile(RandomMeshes.shears(rnd, 0));
        double[] f = new double[s.x.length];
        s.shears.forces(s.x, f);
        assertEquals(0, maxAbs(f), 1e-15, "at rest, N");
        double[] x = perturbed(s.x, rnd, 1e-3);
        double e = s.shears.energy(x);
        assertTrue(e > 0);
        double c = Math.cos(1.1);
        double sn = Math.sin(1.1);
        double[] y = new double[x.length];
        for (int v = 0; v < x.length / 3; v++) {
            // Rotation about an axis (1, 1, 1) / sqrt 3 by 1.1 rad (Rodrigues), then a translation.
            double[] p = {x[3 * v], x[3 * v + 1], x[3 * v + 2]};
            double a = 1 / Math.sqrt(3);
            double dot = a * (p[0] + p[1] + p[2]);
            double[] cr = {a * (p[2] - p[1]), a * (p[0] - p[2]), a * (p[1] - p[0])};
            for (int d = 0; d < 3; d++) {
                y[3 * v + d] = p[d] * c + cr[d] * sn + a * dot * (1 - c) + 0.3 * (d - 1);
            }
        }
        assertEquals(e, s.shears.energy(y), 1e-9 * e, "energy after a rigid motion");
    }

    /** A flat square grid (n x n cells of size h, each cut along a diagonal) with partners t below. */
    private static Topology flatGrid(int n, double h) {
        Topology t = new Topology();
        int side = n + 1;
        for (int f = 0; f < 2; f++) {
            for (int a = 0; a < side; a++) {
                for (int b = 0; b < side; b++) {
                    t.addNode(a * h, b * h, -f * T, 1);
                }
            }
        }
        int lower = side * side;
        for (int a = 0; a < n; a++) {
            for (int b = 0; b < n; b++) {
                int i = a * side + b;
                int[][] tris = {{i, i + side, i + side + 1}, {i, i + side + 1, i + 1}};
                for (int[] tr : tris) {
                    t.addShear(tr, new int[] {lower + tr[0], lower + tr[1], lower + tr[2]}, KAPPA_G, T);
                }
            }
        }
        return t;
    }

    @Test
    void pureBendingOfACylinderAndASphereCostsNothingButAFoldWithUprightColumnsDoes() {
        int n = 8;
        double h = 0.004;
        Topology t = flatGrid(n, h);
        SystemState s = SystemState.compile(t);
        int nodes = s.nodeCount / 2;
        double radius = 0.05;
        for (int shape = 0; shape < 3; shape++) {
            double[] x = s.x.clone();
            for (int v = 0; v < nodes; v++) {
                double px = s.x0[3 * v];
                double py = s.x0[3 * v + 1];
                double[] p;
                double[] normal;
                if (shape == 0) {
                    // Cylinder about the y axis: the plane rolled up, arc length kept.
                    double th = px / radius;
                    p = new double[] {radius * Math.sin(th), py, radius * Math.cos(th) - radius};
                    normal = new double[] {Math.sin(th), 0, Math.cos(th)};
                } else if (shape == 1) {
                    // Sphere: each point projected on it along the radius from its centre.
                    double[] c = {0, 0, -radius};
                    double[] d = {px - c[0], py - c[1], -c[2]};
                    double len = Math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                    normal = new double[] {d[0] / len, d[1] / len, d[2] / len};
                    p = new double[] {c[0] + radius * normal[0], c[1] + radius * normal[1], c[2] + radius * normal[2]};
                } else {
                    // A fold at the element's scale with the columns left upright.
                    double w = (v / (n + 1) + v % (n + 1)) % 2 == 0 ? 1e-4 : -1e-4;
                    p = new double[] {px, py, w};
                    normal = new double[] {0, 0, 1};
                }
                for (int d = 0; d < 3; d++) {
                    x[3 * v + d] = p[d];
                    x[3 * (nodes + v) + d] = p[d] - T * normal[d];
                }
            }
            double e = s.shears.energy(x);
            if (shape < 2) {
                // Scale: a uniform shear strain of 1e-6 over the grid would cost kappa G t gamma^2 / 2 per area.
                double tiny = 0.5 * KAPPA_G * T * 1e-12 * (n * h) * (n * h);
                assertTrue(e < tiny, (shape == 0 ? "cylinder" : "sphere") + ": shear energy " + e + " J");
            } else {
                // Slope 2e-4 / h along x and y on every cell (the columns upright): |gamma|^2 = 2 slope^2,
                // kappa G t |gamma|^2 / 2 per area.
                double slope = 2e-4 / h;
                double expected = KAPPA_G * T * slope * slope * (n * h) * (n * h);
                assertEquals(expected, e, 1e-9 * expected, "fold: shear energy, J");
            }
        }
    }

    @Test
    void badParametersAreRefusedWithTheirNameAndUnit() {
        Topology t = flatGrid(1, 0.004);
        int[] up = {0, 2, 3};
        int[] low = {4, 6, 7};
        var ex = assertThrows(IllegalArgumentException.class, () -> t.addShear(up, low, -1, T));
        assertTrue(ex.getMessage().contains("kappa G") && ex.getMessage().contains("Pa"), ex.getMessage());
        ex = assertThrows(IllegalArgumentException.class, () -> t.addShear(up, low, KAPPA_G, 0));
        assertTrue(ex.getMessage().contains("thickness") && ex.getMessage().contains("m"), ex.getMessage());
        ex = assertThrows(IllegalArgumentException.class, () -> t.addShear(new int[] {0, 0, 3}, low, KAPPA_G, T));
        assertTrue(ex.getMessage().contains("twice"), ex.getMessage());
        ex = assertThrows(IllegalArgumentException.class, () -> t.addShear(new int[] {0, 1, 2, 3}, low, KAPPA_G, T));
        assertTrue(ex.getMessage().contains("3 upper corners"), ex.getMessage());
    }

    /**
     * A clamped shell of the material model (triangles, shear elements, rigid columns) under a load
     * steps without allocating once warm: explicit RK2, BDF2 with its Jacobian, implicit Euler.
     */
    @Test
    void stepsWithShearElementsAllocateNothing() {
        for (Integrator in : new Integrator[] {new MidpointRK2(), new PrefactoredBdf2(), new ImplicitEuler()}) {
            var m = new org.tensim.scene.shell.ShellMaterial(40e3, 0.45, T, 1060);
            var s = org.tensim.scene.shell.TwoSurfaces.offset(org.tensim.analysis.FlatMeshes.disc(3, 0.03), T);
            Topology t = org.tensim.scene.shell.StandaloneShell.of(s, m,
                    org.tensim.scene.shell.TissueModel.MATERIAL, 1);
            int half = s.mesh().vertexCount() / 2;
            for (int v = 0; v < half; v++) {
                if (Math.hypot(t.node(v).position().x(), t.node(v).position().y()) > 0.0299) {
                    t.node(v).fix();
                    t.node(v + half).fix();
                } else {
                    t.applyForce(t.node(v), org.tensim.model.ForceLaw.constant(new org.tensim.model.Vec3(0, 0, -1e-3)));
                }
            }
            t.setViscousDamping(1e-3);
            Simulation sim = new Simulation(SystemState.compile(t), in);
            assertTrue(sim.state().shears.count() > 0, "shear elements in the shell");
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

    /** On several threads the triangle pass adds the shear elements: the serial forces, and the same bits on 1 or 2 threads. */
    @Test
    void theParallelForcePassAddsTheShearElements() {
        var m = new org.tensim.scene.shell.ShellMaterial(40e3, 0.45, T, 1060);
        var sh = org.tensim.scene.shell.TwoSurfaces.offset(org.tensim.analysis.FlatMeshes.disc(6, 0.05), T);
        Topology t = org.tensim.scene.shell.StandaloneShell.of(sh, m,
                org.tensim.scene.shell.TissueModel.MATERIAL, 1);
        Simulation serial = new Simulation(SystemState.compile(t));
        Simulation parallel = new Simulation(SystemState.compile(t));
        Random rnd = new Random(13);
        double[] x = perturbed(serial.state().x, rnd, 2e-4);
        double[] v = new double[x.length];
        double[] fs = new double[x.length];
        double[] fp = new double[x.length];
        double[] one = new double[x.length];
        serial.forces().computeForces(0, x, v, fs);
        var order = org.tensim.solver.parallel.ParallelSpringPass.Order.AUTO;
        try (var p = org.tensim.solver.parallel.Parallelism.install(parallel, 2, order, 1)) {
            assertTrue(parallel.forces().trianglePass() != null && parallel.forces().trianglePass().addsShearForces());
            parallel.forces().computeForces(0, x, v, fp);
        }
        try (var p = org.tensim.solver.parallel.Parallelism.install(parallel, 1, order, 1)) {
            parallel.forces().computeForces(0, x, v, one);
        }
        double[] shearOnly = new double[x.length];
        serial.state().shears.forces(x, shearOnly);
        double scale = maxAbs(fs);
        assertTrue(maxAbs(shearOnly) > 0.01 * scale, "the shear forces are in the comparison: " + maxAbs(shearOnly)
                + " of " + scale);
        for (int k = 0; k < x.length; k++) {
            assertEquals(one[k], fp[k], 0, "the same bits with one thread or two, component " + k);
            assertEquals(fs[k], fp[k], 1e-12 * scale, "serial against parallel, component " + k);
        }
    }

    /**
     * Kelvin-Voigt damping: the viscous forces dissipate {@code beta (dg/dt)^T K dg/dt}, checked against the
     * rate of the energy ({@code dW/dt = -f_elastic . v}, so {@code f_viscous . v = -beta d/dt(dW/dt)} along
     * a straight path), and they vanish for a rigid rotation's velocity.
     */
    @Test
    void dampingDissipatesAndIgnoresRigidMotions() {
        Random rnd = new Random(17);
        Topology t = RandomMeshes.shears(rnd, 0);
        Topology damped = new Topology();
        for (var n : t.nodes()) {
            damped.addNode(n.position(), 1);
        }
        double beta = 2e-3;
        for (var sh : t.shears()) {
            damped.addShear(new int[] {sh.node(0), sh.node(1), sh.node(2)}, new int[] {sh.node(3), sh.node(4), sh.node(5)},
                    KAPPA_G, T, beta);
        }
        SystemState s = SystemState.compile(damped);
        assertTrue(s.velocityDependentForces(), "damped shear elements make the forces depend on v");
        double[] x = perturbed(s.x, rnd, 1e-3);
        double[] v = new double[x.length];
        for (int k = 0; k < v.length; k++) {
            v[k] = rnd.nextGaussian();
        }
        double[] fe = new double[x.length];
        double[] fd = new double[x.length];
        s.shears.forces(x, fe);
        s.shears.forces(x, v, fd);
        double power = 0;
        for (int k = 0; k < x.length; k++) {
            power += (fd[k] - fe[k]) * v[k];
        }
        // -beta v^T K v with K the tangent's first (positive) term.
        s.shears.linearise(x, false);
        double[] kv = new double[x.length];
        s.shears.multiplyAdd(v, kv, null, 1);
        double vkv = 0;
        for (int k = 0; k < x.length; k++) {
            vkv += v[k] * kv[k];
        }
        assertTrue(vkv > 0);
        assertEquals(-beta * vkv, power, 1e-9 * beta * vkv, "viscous power, W");
        // A rigid rotation's velocity w x x (w = (0.3, -0.2, 0.5) rad/s) adds no force.
        double[] w = {0.3, -0.2, 0.5};
        for (int i = 0; i < x.length / 3; i++) {
            v[3 * i] = w[1] * x[3 * i + 2] - w[2] * x[3 * i + 1];
            v[3 * i + 1] = w[2] * x[3 * i] - w[0] * x[3 * i + 2];
            v[3 * i + 2] = w[0] * x[3 * i + 1] - w[1] * x[3 * i];
        }
        double[] fr = new double[x.length];
        s.shears.forces(x, v, fr);
        for (int k = 0; k < x.length; k++) {
            assertEquals(fe[k], fr[k], 1e-9 * maxAbs(fe), "rigid velocity, component " + k);
        }
    }
}

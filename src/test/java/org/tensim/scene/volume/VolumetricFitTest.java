package org.tensim.scene.volume;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.analysis.VolumeStudy;
import org.tensim.model.Topology;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/**
 * The volumetric fit (springs of shear modulus mu and a volume term {@code lambda - mu} a cell): the Poisson ratio
 * asked, Young's modulus kept, energy conserved without damping.
 */
class VolumetricFitTest {
    private static final double DEPTH_M = 0.02;

    @Test
    void theCompressedBlockGivesTheAskedPoissonRatio() {
        for (double nu : new double[] {0.35, 0.4, 0.45}) {
            VolumeParameters p = VolumeParameters.of(0.01, 1e3, nu, 300).withFit(SpringFit.VOLUMETRIC);
            // A clipped lattice (half-full last layer) and one that fits the block in whole cells.
            VolumeStudy.Block clipped = VolumeStudy.block(p, DEPTH_M, 10, 8.5);
            VolumeStudy.Block whole = VolumeStudy.block(p, DEPTH_M, 10, 4);
            System.out.printf("volumetric fit, nu %.2f asked: block of 8.5 cells strain %+.3f %%, nu %.4f; of 4"
                    + " whole cells %+.4f %%, nu %.5f%n", nu, 100 * clipped.strainError(), clipped.measuredPoisson(),
                    100 * whole.strainError(), whole.measuredPoisson());
            assertEquals(nu, clipped.measuredPoisson(), 0.02 * nu, "clipped block's nu");
            assertTrue(Math.abs(clipped.strainError()) < 0.01, "clipped block's strain: " + clipped.strainError());
            // Whole cells: a homogeneous strain is an exact equilibrium; the load's spread remains (as for the
            // other fits, docs/volume.md).
            assertEquals(nu, whole.measuredPoisson(), 0.002 * nu, "whole-cell block's nu");
            assertTrue(Math.abs(whole.strainError()) < 1e-3, "whole-cell block's strain: " + whole.strainError());
        }
    }

    @Test
    void theCantileverKeepsYoungsModulus() {
        VolumeParameters p = VolumeParameters.of(0.01, 1e3, 0.4, 300).withFit(SpringFit.VOLUMETRIC);
        VolumeStudy.Cantilever c = VolumeStudy.cantilever(p, DEPTH_M, 1e-4, 8);
        System.out.printf("volumetric fit cantilever, 8 cells across: %+.2f %% against Euler-Bernoulli, %+.2f %%"
                + " against Timoshenko%n", 100 * c.errorAgainstEulerBernoulli(),
                100 * (c.deflectionM() / c.timoshenkoM() - 1));
        assertTrue(Math.abs(c.errorAgainstEulerBernoulli()) < 0.05, "within 5 %: " + c.errorAgainstEulerBernoulli());
    }

    /**
     * A free block squeezed and let go, undamped, in velocity Verlet: the total energy's worst deviation over the
     * same time falls as dt^2 when dt is halved (a force that were not minus the energy's gradient would leave a
     * deviation that does not shrink), and is small.
     */
    @Test
    void aFreeBlockConservesEnergyWithoutDamping() {
        double[] worst = new double[2];
        double e0 = 0;
        for (int run = 0; run < 2; run++) {
            Topology t = new Topology();
            double h = 0.01;
            VolumeBody.build(t, BoxSurface.of(3 * h, 3 * h, 3 * h, h),
                    VolumeParameters.of(h, 1e3, 0.45, 300).withFit(SpringFit.VOLUMETRIC).withFillSamples(1));
            assertEquals(27, t.volumeElements().size());
            SystemState s = SystemState.compile(t);
            // A squeeze: every node moved towards the centre by 5 % (a volume change of 14 %), with small random
            // velocities.
            for (int k = 0; k < s.x.length; k++) {
                s.x[k] = 1.5 * h + 0.95 * (s.x0[k] - 1.5 * h);
            }
            Random r = new Random(2);
            for (int k = 0; k < s.v.length; k++) {
                s.v[k] = 1e-3 * r.nextGaussian();
            }
            Simulation sim = new Simulation(s, Integrators.create("verlet"));
            double critical = s.criticalTimeStep().stepSeconds();
            double dt = 0.1 * critical / (1 << run);
            e0 = sim.forces().totalEnergy();
            double volume0 = s.volumes.energy(s.x);
            double elastic0 = sim.forces().elasticEnergy(s.x);
            assertTrue(volume0 > 0.3 * elastic0, "the volume term holds much of the squeeze's energy: " + volume0);
            int steps = 3000 << run;
            for (int i = 0; i < steps; i++) {
                sim.step(dt);
                worst[run] = Math.max(worst[run], Math.abs(sim.forces().totalEnergy() - e0) / e0);
            }
            System.out.printf("free volumetric block: energy %.6g J (volume term %.3f of the elastic), worst"
                    + " deviation %.3g of it over %d steps of %.3g ms (critical %.3g ms)%n", e0, volume0 / elastic0,
                    worst[run], steps, dt * 1e3, critical * 1e3);
        }
        double order = Math.log(worst[0] / worst[1]) / Math.log(2);
        System.out.printf("energy deviation's order in dt: %.2f%n", order);
        assertEquals(2, order, 0.3, "the energy's deviation is the integrator's, O(dt^2)");
        assertTrue(worst[1] < 2e-3, "energy within 0.2 % at a twentieth of the critical step: " + worst[1]);
    }

    /**
     * The implicit integrators at steps far beyond the critical one: with the volume terms' Gauss-Newton stiffness
     * in their systems, a beam at nu = 0.45 hanging under a small gravity settles, stably, where statics puts it.
     */
    @Test
    void implicitIntegratorsTakeLargeStepsWithTheVolumeTerms() {
        for (String integrator : new String[] {"implicit-euler", "bdf2"}) {
            double h = 0.01;
            double g = 0.02;
            Topology t = new Topology();
            VolumeBody.build(t, BoxSurface.of(8 * h, 2 * h, 2 * h, h), VolumeParameters.of(h, 1e3, 0.45, 300)
                    .withFit(SpringFit.VOLUMETRIC).withFillSamples(1));
            boolean[] fixed = new boolean[3 * t.nodeCount()];
            double[] f = new double[3 * t.nodeCount()];
            for (org.tensim.model.Node n : t.nodes()) {
                if (n.position().x() < 1e-9) {
                    n.fix();
                }
                f[3 * n.id() + 2] = -g * n.mass();
                for (int a = 0; a < 3; a++) {
                    fixed[3 * n.id() + a] = n.isFixed();
                }
            }
            t.setGravity(new org.tensim.model.Vec3(0, 0, -g));
            t.setViscousDamping(12 * t.totalMass() / t.nodeCount());
            double[] u = org.tensim.analysis.LinearStatics.solve(t, fixed, f, 1e-12).displacementM();
            SystemState s = SystemState.compile(t);
            double critical = s.criticalTimeStep().stepSeconds();
            Simulation sim = new Simulation(s, Integrators.create(integrator));
            double dt = 0.02;
            sim.runUntil(8, dt);
            double staticTip = 0;
            double tip = 0;
            for (int k = 2; k < u.length; k += 3) {
                staticTip = Math.min(staticTip, u[k]);
                tip = Math.min(tip, s.x[k] - s.x0[k]);
            }
            System.out.printf("%s, volumetric beam at nu 0.45: lowest sag %.6g m after 8 s in steps of %.0f ms (%.1f"
                    + " critical steps), statics %.6g m%n", integrator, tip, dt * 1e3, dt / critical, staticTip);
            assertTrue(dt > 4 * critical, "a step beyond the explicit limit: critical " + critical);
            assertEquals(staticTip, tip, 0.005 * Math.abs(staticTip), integrator + ": the sag at rest");
        }
    }

    @Test
    void theVolumetricFitRefusesPoissonRatiosBelowAQuarterAndTets() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> VolumeParameters.of(0.01, 1e3, 0.2, 300).withFit(SpringFit.VOLUMETRIC));
        assertEquals("volume Poisson ratio must be in [0.25, 0.5) for the volumetric spring fit, got 0.2 (it adds a"
                + " volume term to springs whose own ratio is 1/4, and cannot take one away)", e.getMessage());
        assertEquals(SpringFit.VOLUMETRIC, SpringFit.parse("Volumetric"));
        // nu = 1/4: the springs alone hold it; no volume term is added.
        Topology t = new Topology();
        VolumeBody.build(t, BoxSurface.of(0.02, 0.02, 0.02, 0.01),
                VolumeParameters.of(0.01, 1e3, 0.25, 300).withFit(SpringFit.VOLUMETRIC));
        assertEquals(0, t.volumeElements().size());
        e = assertThrows(IllegalArgumentException.class, () -> VolumeBody.buildTets(new Topology(),
                BoxTets.of(0.02, 0.02, 0.02, 2, 2, 2, BoxTets.Split.FIVE),
                VolumeParameters.of(0.01, 1e3, 0.4, 300).withFit(SpringFit.VOLUMETRIC), "box"));
        assertTrue(e.getMessage().startsWith("box: the volumetric spring fit needs a lattice's cells"), e.getMessage());
    }
}

package org.tensim.scene.volume;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.tensim.analysis.LinearStatics;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/**
 * A volume runs in every integrator: a beam of lattice, or of tets, or of lattice with the volumetric fit's volume
 * elements, hanging under a small gravity comes to rest, in each, where small-displacement statics puts it, its
 * surface with it.
 */
class VolumeDynamicsTest {
    private static final double H = 0.01;
    /** A small gravity, m/s^2: the sag (0.8 mm on 80 mm) stays in the small-displacement range. */
    private static final double G = 0.02;

    static List<String> names() {
        return Integrators.names();
    }

    private static Topology beam(VolumeBody[] out, boolean tets, SpringFit fit) {
        Topology t = new Topology();
        VolumeParameters p = VolumeParameters.of(H, 1e3, fit == SpringFit.VOLUMETRIC ? 0.4 : 0.25, 300)
                .withDampingTime(2e-3).withFillSamples(1).withFit(fit);
        out[0] = tets ? VolumeBody.buildTets(t, BoxTets.of(8 * H, 2 * H, 2 * H, 8, 2, 2, BoxTets.Split.FIVE), p,
                "the beam") : VolumeBody.build(t, BoxSurface.of(8 * H, 2 * H, 2 * H, H), p);
        for (Node n : t.nodes()) {
            if (n.position().x() < 1e-9) {
                n.fix();
            }
        }
        t.setGravity(new Vec3(0, 0, -G));
        // about critical damping of the first bending mode (5.8 rad/s): the beam settles within a few seconds
        t.setViscousDamping(12 * t.totalMass() / t.nodeCount());
        return t;
    }

    @ParameterizedTest
    @MethodSource("names")
    void aHangingBeamSettlesWhereStaticsPutsIt(String integrator) {
        settles(integrator, false);
    }

    /** The same beam as a tetrahedral mesh (five tets a cube): a caller runs both variants alike. */
    @ParameterizedTest
    @MethodSource("names")
    void aHangingTetBeamSettlesWhereStaticsPutsIt(String integrator) {
        settles(integrator, true);
    }

    /**
     * The lattice beam with the volumetric fit at nu = 0.4: its volume elements' forces, and in the implicit
     * integrators their Gauss-Newton stiffness, take it where statics (with their stiffness at rest) puts it.
     */
    @ParameterizedTest
    @MethodSource("names")
    void aHangingVolumetricBeamSettlesWhereStaticsPutsIt(String integrator) {
        settles(integrator, false, SpringFit.VOLUMETRIC);
    }

    private static void settles(String integrator, boolean tets) {
        settles(integrator, tets, SpringFit.ISOTROPIC);
    }

    private static void settles(String integrator, boolean tets, SpringFit fit) {
        VolumeBody[] body = new VolumeBody[1];
        Topology t = beam(body, tets, fit);
        assertEquals(fit == SpringFit.VOLUMETRIC ? 32 : 0, t.volumeElements().size(), "volume elements");
        double[] f = new double[3 * t.nodeCount()];
        boolean[] fixed = new boolean[3 * t.nodeCount()];
        for (Node n : t.nodes()) {
            f[3 * n.id() + 2] = -G * n.mass();
            for (int a = 0; a < 3; a++) {
                fixed[3 * n.id() + a] = n.isFixed();
            }
        }
        double[] u = LinearStatics.solve(t, fixed, f, 1e-12).displacementM();
        double[] staticSurface = new double[3 * body[0].surfaceMapping().pointCount()];
        body[0].surfaceMapping().apply(u, staticSurface);
        Simulation sim = new Simulation(SystemState.compile(t), Integrators.create(integrator));
        // The volumetric beam's fastest mode is 1.34 times the isotropic one's (C11 15E/7 against 6E/5): w about
        // 600 rad/s, its damping ratio beta w / 2 = 0.6. At 2 ms symplectic Euler is then unstable (stable to
        // h w = 2 (sqrt(1 + zeta^2) - zeta) = 1.17), which the undamped critical step (3.35 ms) does not foresee;
        // 1.5 ms keeps it stable, and explicit Euler too (stable to h w = 2 zeta).
        double cap = fit == SpringFit.VOLUMETRIC ? 1.5e-3 : 2e-3;
        double dt = Math.min(cap, sim.recommendedTimeStep().seconds());
        sim.runUntil(6, dt);
        double[] x = sim.state().x;
        double[] x0 = sim.state().x0;
        double[] moved = new double[x.length];
        for (int i = 0; i < x.length; i++) {
            moved[i] = x[i] - x0[i];
        }
        double[] surface = new double[staticSurface.length];
        body[0].surfaceMapping().apply(moved, surface);
        double tip = lowest(staticSurface);
        double reached = lowest(surface);
        System.out.printf("%s%s: lowest surface sag at rest %.6g m, statics %.6g m (%d steps of %.3g ms)%n",
                integrator, tets ? " (tets)" : fit == SpringFit.VOLUMETRIC ? " (volumetric)" : "", reached, tip,
                sim.steps(), dt * 1e3);
        assertTrue(tip < -1e-4, "the beam sags: " + tip);
        assertEquals(tip, reached, 0.002 * Math.abs(tip), integrator + ": the surface's lowest sag at rest, m");
    }

    private static double lowest(double[] u) {
        double m = 0;
        for (int i = 2; i < u.length; i += 3) {
            m = Math.min(m, u[i]);
        }
        return m;
    }
}

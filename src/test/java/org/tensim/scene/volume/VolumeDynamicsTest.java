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
 * A volume is springs only, so it runs in every integrator: a beam of lattice, or of tets, hanging under a small
 * gravity comes to rest, in each, where small-displacement statics puts it, its surface with it.
 */
class VolumeDynamicsTest {
    private static final double H = 0.01;
    /** A small gravity, m/s^2: the sag (0.8 mm on 80 mm) stays in the small-displacement range. */
    private static final double G = 0.02;

    static List<String> names() {
        return Integrators.names();
    }

    private static Topology beam(VolumeBody[] out, boolean tets) {
        Topology t = new Topology();
        VolumeParameters p = VolumeParameters.of(H, 1e3, 0.25, 300).withDampingTime(2e-3).withFillSamples(1);
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

    private static void settles(String integrator, boolean tets) {
        VolumeBody[] body = new VolumeBody[1];
        Topology t = beam(body, tets);
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
        double dt = Math.min(2e-3, sim.recommendedTimeStep().seconds());
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
                integrator, tets ? " (tets)" : "", reached, tip, sim.steps(), dt * 1e3);
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

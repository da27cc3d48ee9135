package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/**
 * A force's {@code total}: split over the region's nodes, its shares sum to the total; at rest the fixed nodes'
 * reaction balances it (the paper's cube, its top face loaded, damped to equilibrium); {@code split: mass} gives
 * each node a share proportional to its mass (a volume, whose face nodes carry a half or a quarter cell).
 */
class TotalForceSceneTest {
    @TempDir
    Path dir;

    /** The nodal forces the topology applies at time t, 3 per node, N. */
    private static double[] applied(Topology t, double time) {
        double[] f = new double[3 * t.nodeCount()];
        for (Topology.NodalForce nf : t.forces()) {
            nf.law().addTo(time, f, 3 * nf.node());
        }
        return f;
    }

    @Test
    void theFixedNodesReactionEqualsTheTotal() {
        Scene s = SceneFiles.load(dir, "c.yaml", "version: 1\n"
                + "bodies:\n  c: {type: cube, side: 10 m, node_mass: 1 kg, stiffness: 100 N/m, damping: 20 N*s/m,"
                + " element: mass-spring}\n"
                + "regions:\n  bottom: {box: {min: [0, 0, 0], max: [1, 0, 1], frame: relative}}\n"
                + "  top: {box: {min: [0, 1, 0], max: [1, 1, 1], frame: relative}}\n"
                + "conditions:\n  - {type: fixed, region: bottom}\n"
                + "  - {type: force, region: top, direction: [0.6, -0.8, 0], total: 30 N}\n"
                + "run: {integrator: rk2, dt: 1 ms, duration: 1 ms}\n");
        Topology t = s.bodies().get("c").topology();
        double[] f0 = applied(t, 0);
        double[] sum = new double[3];
        int loaded = 0;
        for (int i = 0; i < t.nodeCount(); i++) {
            for (int a = 0; a < 3; a++) {
                sum[a] += f0[3 * i + a];
            }
            loaded += f0[3 * i] != 0 ? 1 : 0;
        }
        assertEquals(6, loaded, "the top face's 6 nodes");
        assertEquals(18, sum[0], 1e-12);
        assertEquals(-24, sum[1], 1e-12);
        SystemState state = SystemState.compile(t);
        Simulation sim = new Simulation(state, Integrators.create("rk2"));
        sim.runUntil(20, 1e-3);
        double[] f = new double[3 * t.nodeCount()];
        sim.forces().computeForces(sim.time(), state.x, state.v, f);
        double[] reaction = new double[3];
        double residual = 0;
        for (Node n : t.nodes()) {
            for (int a = 0; a < 3; a++) {
                if (n.isFixed()) {
                    reaction[a] -= f[3 * n.id() + a]; // the support holds the node against its springs' pull
                } else {
                    residual = Math.max(residual, Math.abs(f[3 * n.id() + a]));
                }
            }
        }
        System.out.printf("total (18, -24, 0) N: reaction (%.6f, %.6f, %.6f) N, largest free-node residual %.2g N%n",
                reaction[0], reaction[1], reaction[2], residual);
        assertTrue(residual < 1e-6, "at rest: " + residual);
        assertEquals(-18, reaction[0], 1e-5, "the reaction balances the total");
        assertEquals(24, reaction[1], 1e-5, "the reaction balances the total");
        assertEquals(0, reaction[2], 1e-5);
    }

    @Test
    void splitByMassGivesEachNodeItsMassShare() {
        Scene s = SceneFiles.load(dir, "b.yaml", "version: 1\nunits: {length: mm}\n"
                + "bodies:\n  b: {type: volume, box: [20, 20, 20], cell: 5, material: {E: 1 kPa}}\n"
                + "regions:\n  top: {box: {min: [0, 1, 0], max: [1, 1, 1], frame: relative}}\n"
                + "conditions:\n  - {type: force, region: top, direction: [0, -1, 0], total: 4 mN, split: mass}\n"
                + "run: {dt: 1 ms, duration: 1 ms}\n");
        Topology t = s.bodies().get("b").topology();
        double[] f = applied(t, 0);
        double total = 0;
        double topMass = 0;
        double least = Double.MAX_VALUE;
        double most = 0;
        for (Topology.NodalForce nf : t.forces()) {
            topMass += t.node(nf.node()).mass();
        }
        for (Topology.NodalForce nf : t.forces()) {
            double fy = f[3 * nf.node() + 1];
            double m = t.node(nf.node()).mass();
            total += fy;
            assertEquals(-4e-3 * m / topMass, fy, 1e-15, "node " + nf.node() + ": its mass share");
            least = Math.min(least, m);
            most = Math.max(most, m);
        }
        assertEquals(-4e-3, total, 1e-15, "the shares sum to the total");
        assertTrue(most > 1.5 * least, "the face's nodes differ in mass (corners, edges, middle): " + least + " "
                + most);
    }
}

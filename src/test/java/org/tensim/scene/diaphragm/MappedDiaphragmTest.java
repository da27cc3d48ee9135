package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.model.LinearMapping;
import org.tensim.solver.Simulation;
import org.tensim.solver.integrators.Integrators;

/**
 * A diaphragm scene carried by a coarser one ({@link MappedDiaphragm}): the carried nodes (diaphragm and cage) follow
 * an affine motion of the coarse scene exactly, and one inspiration run on the coarse mechanics, measured on the fine
 * nodes, gives the fine model's dome descents within the field's own measured error against the full fine run.
 * Coarse settings: 8 rings carrying 12, the real-time setup at 25 ms.
 */
class MappedDiaphragmTest {
    private static DiaphragmScene scene(int rings) throws Exception {
        DiaphragmSpec spec = DiaphragmSpec.defaults().withMesh(DiaphragmSpec.Mesh.defaults().withRings(rings));
        return DiaphragmSetup.build(spec).scene();
    }

    @Test
    void theCarriedNodesFollowAnAffineMotionOfTheMechanicsExactly() throws Exception {
        DiaphragmScene coarse = scene(8);
        DiaphragmScene fine = scene(12);
        MappedDiaphragm m = MappedDiaphragm.of(coarse, fine);
        LinearMapping map = m.mapping();
        assertEquals(fine.simulatedNodes(), map.pointCount(), "every drawn node of the fine scene, cage included");
        assertEquals(fine.diaphragmNodes(), m.drawnNodes());
        assertEquals(coarse.diaphragmNodes(), m.mechanicalNodes());
        Simulation mech = coarse.newSimulation();
        Simulation carried = m.newCarried(mech);
        double[] rest = carried.state().x0.clone();
        double c = Math.cos(0.2);
        double s = Math.sin(0.2);
        double[][] a = {{1.05 * c, -s, 0.03}, {s, 0.95 * c, 0}, {0.01, 0.04, 1.1}};
        double[] b = {0.004, -0.01, 0.02};
        double[] x = mech.state().x;
        for (int i = 0; i < coarse.simulatedNodes(); i++) {
            double[] p = {mech.state().x0[3 * i], mech.state().x0[3 * i + 1], mech.state().x0[3 * i + 2]};
            for (int r = 0; r < 3; r++) {
                x[3 * i + r] = b[r] + a[r][0] * p[0] + a[r][1] * p[1] + a[r][2] * p[2];
            }
        }
        m.follow(mech, carried);
        for (int i = 0; i < map.pointCount(); i++) {
            for (int r = 0; r < 3; r++) {
                double want = b[r] + a[r][0] * rest[3 * i] + a[r][1] * rest[3 * i + 1] + a[r][2] * rest[3 * i + 2];
                assertEquals(want, carried.state().x[3 * i + r], 1e-12, "node " + i);
            }
        }
        // the cage is carried one to one: its nodes are where the coarse scene's are
        for (int k = 0; k < fine.simulatedNodes() - fine.diaphragmNodes(); k++) {
            for (int r = 0; r < 3; r++) {
                assertEquals(x[3 * (coarse.diaphragmNodes() + k) + r],
                        carried.state().x[3 * (fine.diaphragmNodes() + k) + r], 0, "cage node " + k);
            }
        }
        // where the shell turns over at the rim, a fine node is carried on the face: its offset is left out, within
        // half a coarse element
        var mesh = coarse.surfaces().mesh();
        double element = Math.sqrt(2 * mesh.totalArea() / mesh.triangleCount());
        assertTrue(m.maxResidualM() < 0.5 * element, "the fine mesh lies in the coarse shell to " + m.maxResidualM()
                + " m, elements of " + element + " m");
    }

    @Test
    void oneInspirationOnTheMechanicsGivesTheFineDomesWithinTheFieldsError() throws Exception {
        DiaphragmScene coarse = scene(8);
        DiaphragmScene fine = scene(12);
        MappedDiaphragm m = MappedDiaphragm.of(coarse, fine);
        double seconds = fine.cycle().inspirationS();
        double dt = Integrators.REAL_TIME_STEP_S;
        Simulation full = fine.newSimulation();
        full.setIntegrator(Integrators.create(Integrators.REAL_TIME));
        full.runUntil(seconds, dt);
        Simulation mech = coarse.newSimulation();
        mech.setIntegrator(Integrators.create(Integrators.REAL_TIME));
        Simulation carried = m.newCarried(mech);
        carried.setIntegrator(m.carrier(mech));
        carried.runUntil(seconds, dt);
        assertEquals(full.steps(), mech.steps(), "one mechanics step per carried step");
        assertEquals(full.time(), carried.time(), 1e-12);

        // the end-inspiration field on the fine upper nodes, carried against full: its relative RMS error
        double num = 0;
        double den = 0;
        for (int i = 0; i < fine.diaphragmNodes(); i++) {
            if (!fine.surfaces().isUpper(i)) {
                continue;
            }
            for (int r = 0; r < 3; r++) {
                double uf = full.state().x[3 * i + r] - full.state().x0[3 * i + r];
                double um = carried.state().x[3 * i + r] - carried.state().x0[3 * i + r];
                num += (um - uf) * (um - uf);
                den += uf * uf;
            }
        }
        double error = Math.sqrt(num / den);
        assertTrue(error > 1e-4 && error < 0.25, "8 rings carrying 12: relative RMS error " + error);
        DomeHeights tops = MeasuringSites.domeHeights(fine, MeasuringSites.DOME_TOP_RADIUS_M);
        for (int d = 0; d < 2; d++) {
            double descentFull = tops.top(full.state().x0, d) - tops.top(full.state().x, d);
            double descentMapped = tops.top(carried.state().x0, d) - tops.top(carried.state().x, d);
            assertTrue(descentFull > 0.005, "dome " + d + " descends: " + descentFull + " m");
            assertEquals(descentFull, descentMapped, error * descentFull, "dome " + d + ": mapped "
                    + descentMapped + " m against full " + descentFull + " m, field error " + error);
        }
    }
}

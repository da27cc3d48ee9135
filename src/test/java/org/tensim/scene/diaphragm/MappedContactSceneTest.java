package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.solver.Simulation;
import org.tensim.solver.integrators.Integrators;

/**
 * A diaphragm among bone surfaces (the parametric cage's, {@code --cage surfaces}) with its mechanics on a coarser
 * model: the fine surface is what touches, the coarse model's own pairs are gone, and the carried nodes measure the
 * same contact the mechanics feel.
 */
class MappedContactSceneTest {
    @Test
    void theFineSurfaceTouchesAndTheCarriedNodesMeasureWhatTheMechanicsFeel() throws Exception {
        DiaphragmSpec d = DiaphragmSpec.defaults();
        DiaphragmSpec spec = d.withMesh(DiaphragmSpec.Mesh.defaults().withRings(12))
                .withCage(d.cage().withSurfaces(true));
        DiaphragmSetup.Inputs in = DiaphragmSetup.read(spec); // the bones' distances built once for both
        DiaphragmScene fine = DiaphragmSetup.build(in, spec, spec.newControls()).scene();
        DiaphragmSetup.Inputs coarseIn = new DiaphragmSetup.Inputs(new DiaphragmSetup.Surfaces(
                DiaphragmSetup.generatedSurfaces(8), DiaphragmSetup.SurfaceMode.SHELL), null, in.boxes(), in.bones(),
                null, "8 rings");
        DiaphragmScene coarse = DiaphragmSetup.build(coarseIn, spec, fine.controls()).scene();
        int finePairs = fine.topology().contacts().size();
        assertTrue(finePairs > 0 && !coarse.topology().contacts().isEmpty(), "both scenes touch the bones");
        MappedDiaphragm m = MappedDiaphragm.of(coarse, fine);
        assertEquals(0, coarse.topology().contacts().size(), "the coarse model's own pairs are removed");
        assertNotNull(m.contact());
        assertEquals(finePairs, m.contact().pairCount(), "the fine surface's pairs act on the mechanics");

        Simulation mech = m.newMechanics();
        assertTrue(mech.forces().terms().contains(m.contact()));
        mech.setIntegrator(Integrators.create(Integrators.CONTACT_REAL_TIME));
        Simulation carried = m.newCarried(mech);
        assertEquals(finePairs, carried.state().contacts.count(), "the carried nodes hold the fine pairs");
        // the diaphragm's nodes spread by 4 % about its centre: the sheet presses into the chest wall
        double[] x = mech.state().x;
        int n = coarse.diaphragmNodes();
        double[] c = new double[3];
        for (int i = 0; i < n; i++) {
            for (int a = 0; a < 3; a++) {
                c[a] += x[3 * i + a] / n;
            }
        }
        for (int i = 0; i < n; i++) {
            for (int a = 0; a < 2; a++) {
                x[3 * i + a] = c[a] + 1.04 * (x[3 * i + a] - c[a]);
            }
        }
        m.follow(mech, carried);
        double t = 0;
        assertTrue(m.contact().activeCount(t, x) > 0, "some fine points touch");
        double[] onMechanics = m.contact().maxPenetrationPastGap(t, x);
        double[] onCarried = carried.state().contacts.maxPenetrationPastGap(t, carried.state().x);
        assertArrayEquals(onCarried, onMechanics, 1e-12, "the same pairs on the same fine points");
        double[] pushed = m.contact().totalForceN(t, x);
        double[] measured = carried.state().contacts.totalForceN(t, carried.state().x);
        assertTrue(Math.abs(measured[0]) + Math.abs(measured[1]) > 0, "the wall pushes back");
        assertArrayEquals(measured, pushed, 1e-9 * (1 + Math.abs(measured[0]) + Math.abs(measured[1])));
        // and the nodes receive that total through the transpose
        double[] f = new double[x.length];
        m.contact().addForces(t, x, mech.state().v, f);
        double[] sum = new double[3];
        for (int i = 0; i < f.length / 3; i++) {
            for (int a = 0; a < 3; a++) {
                sum[a] += f[3 * i + a];
            }
        }
        assertArrayEquals(measured, sum, 1e-9 * (1 + Math.abs(measured[0]) + Math.abs(measured[1])));
    }
}

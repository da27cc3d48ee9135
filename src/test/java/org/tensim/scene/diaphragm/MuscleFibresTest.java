package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.FlatMeshes;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.ActiveFibre;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.shell.SurfaceGeometry;
import org.tensim.solver.Simulation;

/**
 * The muscle's fibres ({@link MuscleFibres}): they cover exactly the muscle's area (a triangle cut by
 * the tendon plane by its muscle share), run radially to the tendon's centre on a flat sheet and up the
 * steep walls of the dome, and their tension pulls the dome down.
 */
class MuscleFibresTest {
    private static final double T = 2.5e-3;

    private static Vec3 direction(Topology t, ActiveFibre f) {
        Vec3[] y = new Vec3[3];
        for (int k = 0; k < 3; k++) {
            y[k] = t.node(f.p(k)).position().plus(t.node(f.q(k)).position()).times(0.5);
        }
        return y[1].minus(y[0]).times(f.c(1)).plus(y[2].minus(y[0]).times(f.c(2)));
    }

    @Test
    void aCutTrianglesMuscleShareIsItsAreaBelowThePlane() {
        assertEquals(0.25, MuscleFibres.muscleFraction(new double[] {-1, 1, 1}), 1e-15);
        assertEquals(0.75, MuscleFibres.muscleFraction(new double[] {1, -1, -1}), 1e-15);
        // corner 0 alone on the tendon side, cut at 3/4 and 3/5 of its edges: 1 - (3/4)(3/5) is muscle
        assertEquals(1 - 0.75 * 0.6, MuscleFibres.muscleFraction(new double[] {3, -1, -2}), 1e-15);
        assertEquals(1, MuscleFibres.muscleFraction(new double[] {-1, -2, -3}));
        assertEquals(0, MuscleFibres.muscleFraction(new double[] {0, 2, 3}));
    }

    @Test
    void fibresCoverTheMusclesAreaAndRunRadiallyToTheTendonOnAFlatSheet() {
        double cut = 0.013;
        for (int n : new int[] {10, 25}) {
            TriangleMesh m = FlatMeshes.square(0.1, n);
            Topology t = new Topology();
            boolean[] tendon = new boolean[m.vertexCount()];
            for (int v = 0; v < m.vertexCount(); v++) {
                t.addNode(m.coord(v, 0), m.coord(v, 1), m.coord(v, 2), 1);
                tendon[v] = m.coord(v, 0) >= cut;
            }
            double[] area = SurfaceGeometry.vertexAreas(m);
            ActionLines lines = new ActionLines(List.of(new ActionLines.Line(0, 0, 0.05)), BreathingCycle.quiet(),
                    new DiaphragmControls(1, 1000));
            double[] height = new double[m.vertexCount()];
            for (int v = 0; v < height.length; v++) {
                height[v] = m.coord(v, 0) - cut; // the tendon plane x = cut, normal +x
            }
            int added = MuscleFibres.add(t, m, height, tendon, area, T, lines, null);
            assertEquals(t.fibres().size(), added);
            double volume = 0;
            double cx = 0; // the tendon's centre: the area-weighted mean of its vertices
            double cy = 0;
            double w = 0;
            for (int v = 0; v < m.vertexCount(); v++) {
                cx += tendon[v] ? area[v] * m.coord(v, 0) : 0;
                cy += tendon[v] ? area[v] * m.coord(v, 1) : 0;
                w += tendon[v] ? area[v] : 0;
            }
            cx /= w;
            cy /= w;
            for (ActiveFibre f : t.fibres()) {
                volume += f.volumeM3();
                Vec3 d = direction(t, f);
                assertEquals(1, d.norm(), 1e-12, "the fibre direction is a unit vector");
                assertEquals(0, d.z(), 1e-12, "in the sheet's plane");
                Vec3 g = t.node(f.p(0)).position().plus(t.node(f.p(1)).position()).plus(t.node(f.p(2)).position())
                        .times(1.0 / 3);
                Vec3 r = new Vec3(g.x() - cx, g.y() - cy, 0).normalized();
                assertEquals(0, d.x() * r.y() - d.y() * r.x(), 1e-9, n + " squares: radial from the tendon's centre");
            }
            // half per face: t/2 times the muscle's area (x < cut), exactly, cut triangles included
            assertEquals(0.5 * T * (cut + 0.1) * 0.2, volume, 1e-12, n + " x " + n + " squares");
        }
    }

    @Test
    void onTheDomeTheFibresClimbTheWallsAndPullTheTendonDown() throws Exception {
        BoundaryConditions bc = BoundaryConditions.defaults().withMuscleLoad(BoundaryConditions.MuscleLoad.FIBRES);
        DiaphragmScene scene = SceneFixture.coarse(8, 0, DiaphragmSetup.DEFAULT_FIBRE_STRESS_PA, bc);
        Topology t = scene.topology();
        assertTrue(t.fibres().size() > 0, "muscle triangles carry fibres");
        assertTrue(t.forces().isEmpty(), "no nodal muscle forces beside the fibres");
        int steep = 0;
        for (ActiveFibre f : t.fibres()) {
            boolean allTendon = true;
            for (int k = 0; k < 3; k++) {
                allTendon &= scene.isTendon(f.p(k));
            }
            assertTrue(!allTendon, "no fibre on the tendon");
            Vec3 a = t.node(f.p(1)).position().minus(t.node(f.p(0)).position());
            Vec3 b = t.node(f.p(2)).position().minus(t.node(f.p(0)).position());
            double nz = Math.abs(a.x() * b.y() - a.y() * b.x()) / cross(a, b).norm();
            if (nz < 0.2) { // a steep wall: the fibre runs (almost) vertically
                steep++;
                assertTrue(Math.abs(direction(t, f).z()) > 0.9, "a wall's fibre runs up the wall");
            }
        }
        assertTrue(steep > 0, "the coarse dome has steep walls");
        Simulation sim = scene.newSimulation();
        int apex = scene.apexNode();
        sim.runUntil(0.5, scene.recommendedTimeStep());
        double descent = sim.state().x0[3 * apex + 2] - sim.state().x[3 * apex + 2];
        assertTrue(descent > 0.002, "the contracting fibres pull the dome down (ribs still): " + descent + " m");
    }

    private static Vec3 cross(Vec3 a, Vec3 b) {
        return new Vec3(a.y() * b.z() - a.z() * b.y(), a.z() * b.x() - a.x() * b.z(), a.x() * b.y() - a.y() * b.x());
    }
}

package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.analysis.FlatMeshes;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.ObjWriter;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.ActiveFibre;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.solver.SystemState;

/**
 * The {@code fibres} condition on shells read from scene files: along a strip, the fibres' pull on each clamped end
 * is the tension times the width, {@code sigma t w}, and nothing acts across the fibre; towards a point about an
 * axis, the fibres of a disc run radially, whichever axis the disc lies across; a clamped strip contracts to the
 * uniaxial balance of its membrane against its fibres; a law scales the stress and a
 * negative one gives none; bad directions and regions are refused naming the key.
 */
class FibreScenesTest {
    private static final double SIGMA = 10e3;
    private static final double THICKNESS = 2.5e-3;
    private static final double LENGTH = 0.04;

    @TempDir
    Path dir;

    private String shell(String name, TriangleMesh m, String model) throws IOException {
        return shell(name, m, model, "0.3333333333333333");
    }

    private String shell(String name, TriangleMesh m, String model, String nu) throws IOException {
        ObjWriter.write(dir.resolve(name + ".obj"), m, MeshUnits.M, List.of("a flat test surface"), 15);
        return "version: 1\n"
                + "bodies:\n"
                + "  sheet:\n"
                + "    type: shell\n"
                + "    surface: {file: " + name + ".obj, units: m}\n"
                + "    thickness: 2.5 mm\n"
                + "    material: {E: 40 kPa, nu: " + nu + ", density: 1060 kg/m^3}\n"
                + "    tissue_model: " + model + "\n"
                + "laws:\n"
                + "  wave: {type: sine, frequency: 0.25 Hz}\n"
                + "regions:\n"
                + "  all: {box: {min: [0, 0, 0], max: [1, 1, 1], frame: relative}}\n";
    }

    private Topology load(String yaml) {
        return SceneFiles.load(dir, "scene.yaml", yaml + "run: {dt: 1 ms, duration: 1 ms}\n").bodies().get("sheet")
                .topology();
    }

    /** The fibres' forces at rest at time t, N (3 per node). */
    private static double[] fibreForces(Topology t, double time) {
        SystemState s = SystemState.compile(t);
        double[] f = new double[3 * t.nodeCount()];
        s.fibres.forces(time, s.x0, f);
        return f;
    }

    private static TriangleMesh strip() {
        return FlatMeshes.rectangle(FlatMeshes.Pattern.RIGHT, 8, LENGTH, 0.01, 0);
    }

    private String stripScene(String condition) throws IOException {
        return shell("strip", strip(), "material") + "conditions:\n  - " + condition + "\n";
    }

    @Test
    void alongAStripEachEndIsPulledBySigmaTimesThicknessTimesWidthAndNothingActsAcross() throws IOException {
        Topology t = load(stripScene("{type: fibres, region: all, stress: 10 kPa, along: [2, 0, 0]}"));
        double width = 0;
        for (int i = 0; i < t.nodeCount(); i++) {
            width = Math.max(width, t.node(i).position().y());
        }
        double[] f = fibreForces(t, 0);
        double pull = SIGMA * THICKNESS * width;
        double[] end0 = new double[3];
        double[] end1 = new double[3];
        double interior = 0;
        double across = 0;
        double[] total = new double[3];
        double[] moment = new double[3];
        for (int i = 0; i < t.nodeCount(); i++) {
            Vec3 x = t.node(i).position();
            double[] at = x.x() < 1e-9 ? end0 : x.x() > LENGTH - 1e-9 ? end1 : null;
            for (int a = 0; a < 3; a++) {
                total[a] += f[3 * i + a];
                if (at != null) {
                    at[a] += f[3 * i + a];
                }
            }
            Vec3 fi = new Vec3(f[3 * i], f[3 * i + 1], f[3 * i + 2]);
            Vec3 m = x.cross(fi);
            moment[0] += m.x();
            moment[1] += m.y();
            moment[2] += m.z();
            interior = at == null ? Math.max(interior, fi.norm()) : interior;
            across = Math.max(across, Math.hypot(fi.y(), fi.z()));
        }
        System.out.printf("fibres along a strip: end pulls %.12g and %.12g N, sigma t w %.12g N; largest interior"
                + " force %.3g N, across %.3g N%n", end0[0], -end1[0], pull, interior, across);
        assertTrue(t.fibres().size() >= 2 * 2 * 8 * 2, "fibres on both faces' triangles (and the mid-surface's): "
                + t.fibres().size());
        assertEquals(pull, end0[0], 1e-12 * pull, "the end at x = 0 is pulled towards +x by sigma t w");
        assertEquals(-pull, end1[0], 1e-12 * pull, "the end at x = L towards -x");
        assertEquals(0, interior, 1e-12 * pull, "a uniform tension: every interior node in balance");
        assertEquals(0, across, 1e-12 * pull, "no force across the fibre");
        for (int a = 0; a < 3; a++) {
            assertEquals(0, total[a], 1e-12 * pull, "total force (Newton's third law), axis " + a);
            assertEquals(0, moment[a], 1e-12 * pull * LENGTH, "total moment, axis " + a);
        }
    }

    /**
     * A strip clamped at x = 0 (nu = 0: no lateral strain, so the clamp holds nothing across) contracts under its
     * fibres until the membrane's uniaxial St Venant-Kirchhoff stress balances the active one,
     * {@code E lambda (1 - lambda^2) / 2 = sigma f_L(lambda)} (as ActiveStripTest on two bare triangles): the
     * shell's other parts (shear between the faces, the columns across the thickness) are not strained by a uniform
     * in-plane contraction.
     */
    @Test
    void aClampedStripContractsUntilTheMembraneBalancesTheFibres() throws IOException {
        double e = 40e3;
        double sigma = 4e3;
        java.util.function.DoubleUnaryOperator net = l -> e * l * (1 - l * l) / 2
                - sigma * org.tensim.model.ForceLength.value(l);
        double lo = 1 / Math.sqrt(3);
        double hi = 1;
        for (int i = 0; i < 100; i++) {
            double mid = 0.5 * (lo + hi);
            if (net.applyAsDouble(mid) > 0) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        double expected = 0.5 * (lo + hi);
        Topology t = load(shell("strip", strip(), "material", "0")
                + "  clamp: {box: {min: [-1, -1, -1], max: [0, 1, 1], frame: absolute}}\n"
                + "conditions:\n  - {type: fixed, region: clamp}\n"
                + "  - {type: fibres, region: all, stress: 4 kPa, along: [1, 0, 0]}\n");
        // Damping of time constant m / c = 5 ms per node (the nodes' mass is about 20 mg): settled within 2 s. (With
        // 50 ms the strip reached the balance by 0.6 s, then drifted off it from about 1.2 s on.)
        t.setViscousDamping(t.totalMass() / t.nodeCount() / 0.005);
        org.tensim.solver.Simulation sim = org.tensim.solver.Simulation.of(t);
        sim.apply(sim.settings().withEnergyCheck(Double.POSITIVE_INFINITY, sim.settings().energyCheckInterval()));
        double dt = Math.min(1e-4, 0.5 * sim.recommendedTimeStep().seconds());
        sim.runUntil(2, dt);
        SystemState st = sim.state();
        double tip = 0;
        double speed = 0;
        int n = 0;
        for (int i = 0; i < t.nodeCount(); i++) {
            if (t.node(i).position().x() > LENGTH - 1e-9) {
                tip += st.x[3 * i] / LENGTH;
                speed = Math.max(speed, Math.abs(st.v[3 * i]));
                n++;
            }
        }
        tip /= n;
        System.out.printf("clamped strip under fibres: stretch %.9f, uniaxial balance %.9f, tip speed %.2g m/s%n",
                tip, expected, speed);
        assertTrue(expected < 0.95 && expected > 0.7, "a clear contraction: " + expected);
        assertEquals(expected, tip, 1e-6, "the tip's stretch");
        assertEquals(0, speed, 1e-9, "at rest");
    }

    @Test
    void theLawScalesTheStressAndANegativeLawGivesNoTension() throws IOException {
        Topology t = load(stripScene("{type: fibres, region: all, stress: 10 kPa, law: wave, along: [1, 0, 0]}"));
        double[] peak = fibreForces(t, 1); // sin(pi / 2)
        double[] half = fibreForces(t, 0.5); // sin(pi / 4)
        double[] trough = fibreForces(t, 3); // sin(3 pi / 2) = -1: no push
        double largest = 0;
        double pull = 0;
        double width = 0;
        for (int i = 0; i < t.nodeCount(); i++) {
            largest = Math.max(largest, new Vec3(peak[3 * i], peak[3 * i + 1], peak[3 * i + 2]).norm());
            pull += t.node(i).position().x() < 1e-9 ? peak[3 * i] : 0;
            width = Math.max(width, t.node(i).position().y());
        }
        assertEquals(SIGMA * THICKNESS * width, pull, 1e-12 * pull, "the peak pulls by sigma t w");
        for (int i = 0; i < peak.length; i++) {
            assertEquals(Math.sin(Math.PI / 4) * peak[i], half[i], 1e-12 * largest);
            assertEquals(0, trough[i]);
        }
    }

    /** Each fibre's rest direction f0 = c1 (Y1 - Y0) + c2 (Y2 - Y0) and its triangle's centroid, m. */
    private static Vec3[] directionAndCentroid(Topology t, ActiveFibre f) {
        Vec3[] y = new Vec3[3];
        for (int k = 0; k < 3; k++) {
            y[k] = t.node(f.p(k)).position().plus(t.node(f.q(k)).position()).times(0.5);
        }
        Vec3 d = y[1].minus(y[0]).times(f.c(1)).plus(y[2].minus(y[0]).times(f.c(2)));
        return new Vec3[] {d, y[0].plus(y[1]).plus(y[2]).times(1.0 / 3)};
    }

    @Test
    void towardsAPointAboutAnAxisTheFibresOfADiscRunRadiallyWhicheverAxisItLiesAcross() throws IOException {
        TriangleMesh flat = FlatMeshes.disc(6, 0.05);
        // The same disc across z and, its y and z swapped, across y.
        double[] xz = new double[3 * flat.vertexCount()];
        for (int v = 0; v < flat.vertexCount(); v++) {
            xz[3 * v] = flat.coord(v, 0);
            xz[3 * v + 1] = flat.coord(v, 2);
            xz[3 * v + 2] = flat.coord(v, 1);
        }
        int[] tris = new int[3 * flat.triangleCount()];
        for (int tr = 0; tr < flat.triangleCount(); tr++) {
            tris[3 * tr] = flat.corner(tr, 0);
            tris[3 * tr + 1] = flat.corner(tr, 2); // mirrored: keep the faces' orientation
            tris[3 * tr + 2] = flat.corner(tr, 1);
        }
        TriangleMesh upright = new TriangleMesh(xz, tris);
        String[][] cases = {{"across-z", "[0, 0, 1]"}, {"across-y", "[0, 3, 0]"}};
        for (String[] c : cases) {
            TriangleMesh m = c[0].equals("across-z") ? flat : upright;
            Vec3 axis = c[0].equals("across-z") ? new Vec3(0, 0, 1) : new Vec3(0, 1, 0);
            Topology t = load(shell(c[0], m, "material") + "conditions:\n  - {type: fibres, region: all, stress:"
                    + " 10 kPa, towards: [0, 0, 0], axis: " + c[1] + "}\n");
            assertEquals(t.triangles().size(), t.fibres().size(), c[0] + ": every membrane triangle has a fibre");
            double worst = 0;
            for (ActiveFibre f : t.fibres()) {
                Vec3[] dg = directionAndCentroid(t, f);
                Vec3 g = dg[1];
                Vec3 radial = g.minus(axis.times(g.dot(axis))).normalized();
                assertEquals(1, dg[0].norm(), 1e-12, "a unit direction");
                worst = Math.max(worst, dg[0].cross(radial).norm());
            }
            System.out.printf("fibres towards the centre of a disc %s: largest |f0 x r| %.3g%n", c[0], worst);
            assertEquals(0, worst, 1e-12, c[0] + ": radial");
        }
    }

    @Test
    void badDirectionsAndRegionsAreRefusedNamingTheKey() throws IOException {
        String[][] cases = {
            {"{type: fibres, region: all, stress: 10 kPa}", "conditions[0]", "give exactly one fibre direction"},
            {"{type: fibres, region: all, stress: 10 kPa, along: [1, 0, 0], towards: [0, 0, 0], axis: [0, 0, 1]}",
                "conditions[0]", "give exactly one fibre direction"},
            {"{type: fibres, region: all, stress: 10 kPa, towards: [0, 0, 0]}", "conditions[0].towards",
                "towards needs axis"},
            {"{type: fibres, region: all, stress: 10 kPa, along: [1, 0, 0], axis: [0, 0, 1]}", "conditions[0].axis",
                "axis goes with towards"},
            {"{type: fibres, region: all, stress: 10 kPa, along: [0, 0, 0]}", "conditions[0].along",
                "must not be the zero vector"},
            {"{type: fibres, region: all, stress: 10 kPa, along: [0, 0, 1]}", "conditions[0].along",
                "defined on none of the"},
            {"{type: fibres, region: all, stress: -1 kPa, along: [1, 0, 0]}", "conditions[0].stress", ">= 0"},
        };
        for (String[] c : cases) {
            SceneException e = assertThrows(SceneException.class, () -> load(stripScene(c[0])), c[0]);
            assertTrue(e.getMessage().contains("scene.yaml:") && e.getMessage().contains(c[1] + ": ")
                    && e.getMessage().contains(c[2]), c[0] + " -> " + e.getMessage());
        }
        // A shell of the paper's springs has no membrane triangle to carry fibres.
        SceneException e = assertThrows(SceneException.class, () -> load(shell("springs", strip(), "paper")
                + "conditions:\n  - {type: fibres, region: all, stress: 10 kPa, along: [1, 0, 0]}\n"));
        assertTrue(e.getMessage().contains("conditions[0].region: ")
                && e.getMessage().contains("covers no membrane triangle of body 'sheet'"), e.getMessage());
    }
}

package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.analysis.FlatMeshes;
import org.tensim.analysis.LinearStatics;
import org.tensim.model.LinearMapping;
import org.tensim.model.Spring;
import org.tensim.model.Topology;
import org.tensim.scene.shell.ShellMaterial;
import org.tensim.scene.shell.StandaloneShell;
import org.tensim.scene.shell.TissueModel;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * A fine shell carried by a coarse one: the wedge coordinates reproduce the fine nodes and any affine motion of the
 * coarse shell, the transpose conserves force and moment, a point load carried by it meets the supports' reaction,
 * and the paper's 43-ring mesh lies in the 20-ring shell.
 */
class ShellMappingTest {
    private static final ShellMaterial MUSCLE = new ShellMaterial(40e3, 1.0 / 3, 0.0025, 1060);

    private static TwoSurfaces dome(int rings) {
        return TwoSurfaces.split(DoubleDomeGenerator.shell(DoubleDomeGenerator.Shape.adult().withRings(rings)));
    }

    private static double[] rest(TwoSurfaces s) {
        return s.mesh().coordinates();
    }

    /** x -> A x + b on 3-per-node coordinates. */
    private static double[] affine(double[] x, double[][] a, double[] b) {
        double[] y = new double[x.length];
        for (int i = 0; i < x.length / 3; i++) {
            for (int r = 0; r < 3; r++) {
                y[3 * i + r] = b[r] + a[r][0] * x[3 * i] + a[r][1] * x[3 * i + 1] + a[r][2] * x[3 * i + 2];
            }
        }
        return y;
    }

    @Test
    void theFineNodesAndAnAffineMotionOfTheCoarseShellAreReproducedExactly() {
        TwoSurfaces coarse = dome(10);
        TwoSurfaces fine = dome(14);
        ShellMapping sm = ShellMapping.of(coarse, fine);
        LinearMapping m = sm.mapping();
        assertEquals(fine.mesh().vertexCount(), m.pointCount());
        double[] p = fine.mesh().coordinates();
        double[] mapped = new double[p.length];
        m.apply(rest(coarse), mapped);
        // a stretch, a shear and a rotation of 0.3 rad about z, and a shift of centimetres
        double c = Math.cos(0.3);
        double s = Math.sin(0.3);
        double[][] a = {{1.1 * c, -s, 0.05}, {s, 0.9 * c, 0}, {0.02, 0.1, 1.2}};
        double[] b = {0.01, -0.02, 0.03};
        double[] moved = new double[p.length];
        m.apply(affine(rest(coarse), a, b), moved);
        double[] expected = affine(p, a, b);
        int inWedge = 0;
        for (int i = 0; i < m.pointCount(); i++) {
            if (sm.residualM(i) > 1e-9) {
                continue; // carried on the face: checked by the band test's count
            }
            inWedge++;
            for (int k = 0; k < 3; k++) {
                // exact to the Newton tolerance (1e-10 of a wedge's size, 2e-12 m here)
                assertEquals(p[3 * i + k], mapped[3 * i + k], 1e-11, "rest, point " + i);
                assertEquals(expected[3 * i + k], moved[3 * i + k], 1e-11, "moved, point " + i);
            }
        }
        assertTrue(inWedge > 0.99 * m.pointCount(), inWedge + " of " + m.pointCount() + " points in a wedge");
    }

    @Test
    void theTransposeConservesForceAndMoment() {
        ShellMapping sm = ShellMapping.of(dome(10), dome(14));
        LinearMapping m = sm.mapping();
        double[] x = rest(dome(10));
        double[] p = new double[3 * m.pointCount()];
        m.apply(x, p);
        Random r = new Random(3);
        double[] f = new double[p.length];
        for (int i = 0; i < f.length; i++) {
            f[i] = r.nextGaussian();
        }
        double[] nodeF = new double[x.length];
        m.addTranspose(f, nodeF);
        double[] sumP = sum(f);
        double[] sumN = sum(nodeF);
        double[] momP = moment(p, f);
        double[] momN = moment(x, nodeF);
        for (int k = 0; k < 3; k++) {
            assertEquals(sumP[k], sumN[k], 1e-9, "force component " + k);
            assertEquals(momP[k], momN[k], 1e-9, "moment component " + k);
        }
        assertTrue(Math.abs(sumP[0]) + Math.abs(momP[0]) > 1, "a test load with a force and a moment");
    }

    /**
     * A point force on a fine upper-face node of a clamped disc carried by a coarse one: the coarse shell's supports
     * (the rim, both faces fixed) meet the force and its moment about the origin taken where the fine node is, as
     * they would meet the load itself (small-displacement statics, springs at rest: internal forces carry no net
     * force or moment).
     */
    @Test
    void aFineSurfacePointLoadMeetsTheSameReactionOnTheCoarseShell() {
        double radius = 0.1;
        TwoSurfaces coarse = TwoSurfaces.offset(FlatMeshes.disc(4, radius), MUSCLE.thicknessM());
        TwoSurfaces fine = TwoSurfaces.offset(FlatMeshes.disc(9, radius), MUSCLE.thicknessM());
        Topology t = StandaloneShell.of(coarse, MUSCLE, TissueModel.PAPER, 1);
        ShellMapping sm = ShellMapping.of(coarse, fine);
        int load = -1;
        for (int v = 0; v < fine.mesh().vertexCount() && load < 0; v++) {
            double rr = Math.hypot(fine.mesh().coord(v, 0) - 0.03, fine.mesh().coord(v, 1) - 0.02);
            load = fine.isUpper(v) && rr < 0.012 && sm.residualM(v) < 1e-9 ? v : -1;
        }
        assertTrue(load >= 0, "a fine upper node near (30, 20) mm");
        double[] f = new double[3 * fine.mesh().vertexCount()];
        double[] force = {0.3, -0.2, -1.0};
        System.arraycopy(force, 0, f, 3 * load, 3);
        int nv = coarse.mesh().vertexCount();
        double[] nodeF = new double[3 * nv];
        sm.mapping().addTranspose(f, nodeF);
        boolean[] fixed = new boolean[3 * nv];
        for (int v = 0; v < nv; v++) {
            if (Math.hypot(coarse.mesh().coord(v, 0), coarse.mesh().coord(v, 1)) > radius * (1 - 1e-9)) {
                fixed[3 * v] = fixed[3 * v + 1] = fixed[3 * v + 2] = true;
            }
        }
        double[] u = LinearStatics.solve(t, fixed, nodeF, 1e-12).displacementM();
        double[] ku = stiffnessTimes(t, u);
        double[] reaction = new double[3 * nv];
        for (int i = 0; i < reaction.length; i++) {
            reaction[i] = fixed[i] ? ku[i] - nodeF[i] : 0;
            if (!fixed[i]) {
                assertEquals(nodeF[i], ku[i], 1e-8, "equilibrium of free dof " + i);
            }
        }
        double[] x = rest(coarse);
        double[] p = {fine.mesh().coord(load, 0), fine.mesh().coord(load, 1), fine.mesh().coord(load, 2)};
        double[] sumR = sum(reaction);
        double[] momR = moment(x, reaction);
        double[] momLoad = moment(p, force);
        for (int k = 0; k < 3; k++) {
            assertEquals(-force[k], sumR[k], 1e-7, "the supports meet the load, component " + k);
            assertEquals(-momLoad[k], momR[k], 1e-8, "and its moment about the origin, component " + k);
        }
    }

    /**
     * The paper's mesh (43 rings) carried by a 20-ring shell: every node's weights sum to 1, and it lies in the
     * thickness band or just outside (the coarse faces are chords of the curved fine ones), within a bound printed.
     * Measured 2026-12-01: 11,354 nodes; in wedges 11,327, farthest 3.97 mm outside the band (thickness 2.50 mm);
     * 27 (23 on the rim where the shell turns over) carried at the closest point of a face, the farthest 5.63 mm
     * from where it is carried; lowest weight -0.96.
     */
    @Test
    void thePapersMeshLiesInTheTwentyRingShell() {
        TwoSurfaces coarse = dome(20);
        TwoSurfaces fine = dome(43);
        ShellMapping sm = ShellMapping.of(coarse, fine);
        LinearMapping m = sm.mapping();
        double maxOutside = 0;
        double maxResidual = 0;
        boolean[] rim = fine.ownRim();
        int offRim = 0;
        double minWeight = 1;
        int onFace = 0;
        for (int i = 0; i < m.pointCount(); i++) {
            double sum = 0;
            for (int k = 0; k < m.entries(i); k++) {
                sum += m.weight(i, k);
            }
            assertEquals(1, sum, 1e-12, "weights of fine node " + i);
            boolean inWedge = sm.residualM(i) <= 1e-9;
            maxOutside = inWedge ? Math.max(maxOutside, sm.outsideM(i)) : maxOutside;
            maxResidual = inWedge ? maxResidual : Math.max(maxResidual, sm.residualM(i));
            minWeight = Math.min(minWeight, sm.minWeight(i));
            onFace += inWedge ? 0 : 1;
            offRim += inWedge || rim[i] ? 0 : 1;
        }
        System.out.printf("43 rings on 20: %d nodes, %d carried on a face (%d of them off the rim), farthest outside"
                + " the thickness band in a wedge %.3f mm (thickness %.3f mm), farthest from the face on it %.3f mm,"
                + " lowest weight %.3f%n", m.pointCount(), onFace, offRim, maxOutside * 1e3,
                coarse.thicknessM() * 1e3, maxResidual * 1e3, minWeight);
        assertTrue(maxOutside < 2 * coarse.thicknessM(), "farthest outside the band: " + maxOutside + " m");
        assertTrue(onFace < 0.005 * m.pointCount() && offRim <= onFace / 5, onFace + " nodes carried on a face, "
                + offRim + " off the rim");
        assertTrue(maxResidual < 3 * coarse.thicknessM(), "farthest from the face: " + maxResidual + " m");
        assertTrue(minWeight >= -ShellMapping.MAX_EXTRAPOLATION, "lowest weight " + minWeight);
    }

    /** K u of a spring network at rest (no prestress): {@code f_b = k n n^T (u_b - u_a) = -f_a}. */
    private static double[] stiffnessTimes(Topology t, double[] u) {
        double[] y = new double[3 * t.nodeCount()];
        for (Spring s : t.springs()) {
            double[] d = {t.node(s.b()).position().x() - t.node(s.a()).position().x(),
                t.node(s.b()).position().y() - t.node(s.a()).position().y(),
                t.node(s.b()).position().z() - t.node(s.a()).position().z()};
            double len2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            double du = 0;
            for (int k = 0; k < 3; k++) {
                du += d[k] * (u[3 * s.b() + k] - u[3 * s.a() + k]);
            }
            for (int k = 0; k < 3; k++) {
                double fk = s.stiffness() * du * d[k] / len2;
                y[3 * s.b() + k] += fk;
                y[3 * s.a() + k] -= fk;
            }
        }
        return y;
    }

    private static double[] sum(double[] f) {
        double[] s = new double[3];
        for (int i = 0; i < f.length / 3; i++) {
            for (int k = 0; k < 3; k++) {
                s[k] += f[3 * i + k];
            }
        }
        return s;
    }

    private static double[] moment(double[] x, double[] f) {
        double[] m = new double[3];
        for (int i = 0; i < f.length / 3; i++) {
            double px = x[3 * i];
            double py = x[3 * i + 1];
            double pz = x[3 * i + 2];
            m[0] += py * f[3 * i + 2] - pz * f[3 * i + 1];
            m[1] += pz * f[3 * i] - px * f[3 * i + 2];
            m[2] += px * f[3 * i + 1] - py * f[3 * i];
        }
        return m;
    }
}

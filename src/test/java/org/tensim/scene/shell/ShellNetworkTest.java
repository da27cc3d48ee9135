package org.tensim.scene.shell;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.tensim.analysis.FlatMeshes;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Topology;
import org.tensim.scene.diaphragm.DoubleDomeGenerator;
import org.tensim.solver.ForceModel;
import org.tensim.solver.SystemState;

/** The shell's springs and triangles are objective: rigid motions change neither its energy nor its balance. */
class ShellNetworkTest {
    @ParameterizedTest
    @EnumSource(TissueModel.class)
    void energyIsInvariantUnderRigidMotionsAndForcesBalance(TissueModel model) {
        TwoSurfaces s = TwoSurfaces.split(DoubleDomeGenerator.shell(DoubleDomeGenerator.Shape.adult().withRings(5)));
        Topology t = StandaloneShell.of(s, new ShellMaterial(40e3, 0.45, s.thicknessM(), 1060), model, 1);
        assertTrue(t.springs().size() + t.triangles().size() + t.shears().size() > 3 * s.mesh().vertexCount(),
                "a connected network: " + t.springs().size() + " springs, " + t.triangles().size() + " triangles, "
                        + t.shears().size() + " shear elements");
        ForceModel fm = new ForceModel(SystemState.compile(t));
        double[] x = SystemState.compile(t).x.clone();
        Random rnd = new Random(7);
        for (int k = 0; k < x.length; k++) {
            x[k] += 0.3 * s.thicknessM() * rnd.nextGaussian();
        }
        double e = fm.elasticEnergy(x);
        assertTrue(e > 0, "a deformed shell stores energy");
        // A rotation of 0.9 rad about an oblique axis through an arbitrary point, then a translation.
        double[] axis = {0.3, -0.5, 0.81};
        double n = Math.sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
        double c = Math.cos(0.9);
        double sn = Math.sin(0.9);
        double[] y = new double[x.length];
        for (int v = 0; v < x.length / 3; v++) {
            double[] p = {x[3 * v] - 0.1, x[3 * v + 1] + 0.2, x[3 * v + 2] - 1.0};
            double[] a = {axis[0] / n, axis[1] / n, axis[2] / n};
            double dot = a[0] * p[0] + a[1] * p[1] + a[2] * p[2];
            double[] cr = {a[1] * p[2] - a[2] * p[1], a[2] * p[0] - a[0] * p[2], a[0] * p[1] - a[1] * p[0]};
            for (int d = 0; d < 3; d++) {
                y[3 * v + d] = p[d] * c + cr[d] * sn + a[d] * dot * (1 - c) + 0.05 * (d + 1);
            }
        }
        assertEquals(e, fm.elasticEnergy(y), 1e-9 * e, "energy after a rigid motion");
        // Internal forces: no net force and no net torque (linear and angular momentum kept).
        double[] f = new double[x.length];
        fm.springs(y, f);
        fm.triangles(y, f);
        fm.state().shears.forces(y, f);
        double[] sum = new double[3];
        double[] torque = new double[3];
        double scale = 0;
        for (int v = 0; v < x.length / 3; v++) {
            double fx = f[3 * v];
            double fy = f[3 * v + 1];
            double fz = f[3 * v + 2];
            sum[0] += fx;
            sum[1] += fy;
            sum[2] += fz;
            torque[0] += y[3 * v + 1] * fz - y[3 * v + 2] * fy;
            torque[1] += y[3 * v + 2] * fx - y[3 * v] * fz;
            torque[2] += y[3 * v] * fy - y[3 * v + 1] * fx;
            scale += Math.abs(fx) + Math.abs(fy) + Math.abs(fz);
        }
        for (int d = 0; d < 3; d++) {
            assertEquals(0, sum[d], 1e-12 * scale, "net force " + d);
            assertEquals(0, torque[d], 1e-11 * scale, "net torque " + d);
        }
    }

    /**
     * Sliding the upper face over the lower one by gamma t (the columns tilted by gamma) costs
     * Mindlin-Reissner's {@code kappa G t gamma^2 / 2} per unit area, on any triangulation, in any
     * direction: the shear elements are exact for a uniform shear strain (cotangent identity).
     */
    @ParameterizedTest
    @EnumSource(FlatMeshes.Pattern.class)
    void aUniformSlidingOfTheFacesCostsTheMindlinShearEnergy(FlatMeshes.Pattern pattern) {
        ShellMaterial m = new ShellMaterial(40e3, 0.45, 0.0025, 1060);
        for (boolean disc : new boolean[] {false, true}) {
            TriangleMesh flat = disc ? FlatMeshes.disc(6, 0.05) : FlatMeshes.rectangle(pattern, 7, 0.1, 0.05, 3);
            TwoSurfaces s = TwoSurfaces.offset(flat, m.thicknessM());
            Topology t = StandaloneShell.of(s, m, TissueModel.MATERIAL, 1);
            assertEquals(flat.triangleCount(), t.shears().size(), "one shear element per upper triangle");
            SystemState st = SystemState.compile(t);
            double area = 0;
            for (int tr = 0; tr < flat.triangleCount(); tr++) {
                area += flat.area(tr);
            }
            double gamma = 1e-3;
            double kappaG = ShellNetwork.SHEAR_CORRECTION * m.youngPa() / (2 * (1 + m.poisson()));
            double expected = 0.5 * kappaG * m.thicknessM() * gamma * gamma * area;
            for (double angle : new double[] {0, 0.7, Math.PI / 2}) {
                double[] x = st.x.clone();
                for (int v = 0; v < flat.vertexCount(); v++) {
                    x[3 * v] += gamma * m.thicknessM() * Math.cos(angle);
                    x[3 * v + 1] += gamma * m.thicknessM() * Math.sin(angle);
                }
                double w = st.shears.energy(x);
                assertEquals(expected, w, 1e-6 * expected, (disc ? "disc" : pattern) + ", sliding at " + angle
                        + " rad: shear energy");
            }
        }
    }

    /**
     * Faces meshed apart (a real mesh's): the lower face is the upper one shifted along the face by 0.3
     * thicknesses, so no pair lies on a normal, yet within {@link ShellNetwork#SHEAR_PAIR_OFFSET}: every
     * upper triangle gets a shear element and a uniform sliding costs exactly Mindlin-Reissner's
     * {@code kappa G t gamma^2 / 2} per unit area (the lever arm is the faces' distance, not the slanted
     * pair's length).
     */
    @Test
    void facesShiftedAlongTheFaceCostTheMindlinShearEnergy() {
        double l = 0.01;
        double t = 0.0025;
        TriangleMesh face = org.tensim.io.mesh.FlatMeshes.square(l, 6);
        TwoSurfaces s = TwoSurfaces.of(stack(face, face, t, 0.3 * t), upperFlags(face, face));
        ShellMaterial m = new ShellMaterial(40e3, 0.45, t, 1060);
        Topology top = StandaloneShell.of(s, m, TissueModel.MATERIAL, 1);
        assertEquals(face.triangleCount(), top.shears().size(), "a shear element on every upper triangle");
        SystemState st = SystemState.compile(top);
        double gamma = 1e-3;
        double kappaG = ShellNetwork.SHEAR_CORRECTION * m.youngPa() / (2 * (1 + m.poisson()));
        // kappa G t with the shell's thickness as the network takes it (the median distance of paired
        // vertices, here above t: slanted pairs), the strain with the faces' distance t.
        double expected = 0.5 * kappaG * s.thicknessM() * gamma * gamma * 4 * l * l;
        for (double angle : new double[] {0, 0.7, Math.PI / 2}) {
            double[] x = st.x.clone();
            for (int v = 0; v < face.vertexCount(); v++) {
                x[3 * v] += gamma * t * Math.cos(angle);
                x[3 * v + 1] += gamma * t * Math.sin(angle);
            }
            assertEquals(expected, st.shears.energy(x), 1e-6 * expected, "sliding at " + angle + " rad: shear energy");
        }
    }

    /**
     * Faces of different resolutions (the lower twice as coarse): most upper corners share a partner off
     * their normal and carry no column, so most triangles get no shear element (it would lock in bending);
     * both ends of every upper edge without one carry the prisms' diagonals (or a column) instead, so no part of the shell slides
     * freely (a BodyParts3D shell whose triangles lacked both collapsed under the muscle's load).
     */
    @Test
    void everyUpperEdgeResistsSlidingOnFacesOfDifferentResolutions() {
        double t = 0.0025;
        TriangleMesh up = org.tensim.io.mesh.FlatMeshes.square(0.01, 8);
        TriangleMesh low = org.tensim.io.mesh.FlatMeshes.square(0.01, 4);
        TwoSurfaces s = TwoSurfaces.of(stack(up, low, t, 0), upperFlags(up, low));
        Topology top = StandaloneShell.of(s, new ShellMaterial(40e3, 0.45, t, 1060), TissueModel.MATERIAL, 1);
        java.util.Set<Long> covered = new java.util.HashSet<>();
        for (var e : top.shears()) {
            for (int k = 0; k < 3; k++) {
                covered.add(ShellNetwork.key(e.node(k), e.node((k + 1) % 3)));
            }
        }
        java.util.Set<Integer> diagonalEnds = new java.util.HashSet<>();
        for (var sp : top.springs()) {
            if (s.isUpper(sp.a()) != s.isUpper(sp.b())) {
                diagonalEnds.add(s.isUpper(sp.a()) ? sp.a() : sp.b());
            }
        }
        for (var link : top.rigidLinks()) { // a column is a diagonal's rigid side where partners are shared
            diagonalEnds.add(s.isUpper(link.a()) ? link.a() : link.b());
        }
        assertTrue(top.shears().size() < up.triangleCount() / 2, top.shears().size() + " shear elements");
        int uncovered = 0;
        for (int tr = 0; tr < up.triangleCount(); tr++) {
            for (int k = 0; k < 3; k++) {
                int a = up.corner(tr, k);
                int b = up.corner(tr, (k + 1) % 3);
                if (!covered.contains(ShellNetwork.key(a, b))) {
                    uncovered++;
                    assertTrue(diagonalEnds.contains(a) && diagonalEnds.contains(b),
                            "upper edge " + a + "-" + b + " has neither a shear element nor diagonals ");
                }
            }
        }
        assertTrue(uncovered > 0, "the case without elements was exercised");
    }

    /** The upper face at height t over the lower one shifted by dx (lower face facing down), m. */
    private static TriangleMesh stack(TriangleMesh up, TriangleMesh low, double t, double dx) {
        int nu = up.vertexCount();
        double[] xyz = new double[3 * (nu + low.vertexCount())];
        int[] tri = new int[3 * (up.triangleCount() + low.triangleCount())];
        for (int v = 0; v < nu + low.vertexCount(); v++) {
            TriangleMesh m = v < nu ? up : low;
            int w = v < nu ? v : v - nu;
            xyz[3 * v] = m.coord(w, 0) + (v < nu ? 0 : dx);
            xyz[3 * v + 1] = m.coord(w, 1);
            xyz[3 * v + 2] = v < nu ? t : 0;
        }
        for (int k = 0; k < up.triangleCount(); k++) {
            for (int c = 0; c < 3; c++) {
                tri[3 * k + c] = up.corner(k, c);
            }
        }
        for (int k = 0; k < low.triangleCount(); k++) {
            for (int c = 0; c < 3; c++) {
                tri[3 * (up.triangleCount() + k) + c] = nu + low.corner(k, 2 - c);
            }
        }
        return new TriangleMesh(xyz, tri);
    }

    private static boolean[] upperFlags(TriangleMesh up, TriangleMesh low) {
        boolean[] f = new boolean[up.vertexCount() + low.vertexCount()];
        java.util.Arrays.fill(f, 0, up.vertexCount(), true);
        return f;
    }
}

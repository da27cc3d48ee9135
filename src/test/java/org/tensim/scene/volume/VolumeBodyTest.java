package org.tensim.scene.volume;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.MeshLoader;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.LinearMapping;
import org.tensim.model.Spring;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.thorax.TestMeshes;
import org.tensim.testsupport.SharedData;

/** The volume body: its lattice, masses, identification and embedding, and the surfaces it refuses. */
class VolumeBodyTest {
    private static final double R = 0.05;
    private static final VolumeParameters TISSUE = VolumeParameters.of(0.02, 1e3, 0.4, 300);

    private static TriangleMesh sphere() {
        return TestMeshes.icosphere(new double[] {0.01, -0.02, 0.03}, R, 3);
    }

    private static double[] positions(Topology t) {
        double[] x = new double[3 * t.nodeCount()];
        for (int n = 0; n < t.nodeCount(); n++) {
            Vec3 p = t.node(n).position();
            x[3 * n] = p.x();
            x[3 * n + 1] = p.y();
            x[3 * n + 2] = p.z();
        }
        return x;
    }

    @Test
    void theEmbeddedSurfaceSitsWhereItWasAndFollowsAnAffineMotionOfTheLatticeExactly() {
        TriangleMesh s = sphere();
        Topology t = new Topology();
        t.addNode(5, 5, 5, 1); // a node before the volume: the volume's ids start after it
        VolumeBody body = VolumeBody.build(t, s, TISSUE);
        assertEquals(1, body.firstNode());
        assertEquals(t.nodeCount() - 1, body.nodeCount());
        LinearMapping m = body.surfaceMapping();
        assertEquals(s.vertexCount(), m.pointCount());
        double[] rest = m.restPoints(t);
        for (int v = 0; v < s.vertexCount(); v++) {
            for (int a = 0; a < 3; a++) {
                assertEquals(s.coord(v, a), rest[3 * v + a], 1e-15, "vertex " + v);
            }
        }
        double[][] a = {{1.1, 0.2, -0.3}, {0.05, 0.9, 0.4}, {-0.2, 0.1, 1.3}};
        double[] b = {0.3, -0.1, 0.2};
        double[] x = positions(t);
        double[] moved = new double[x.length];
        for (int n = 0; n < t.nodeCount(); n++) {
            for (int r = 0; r < 3; r++) {
                moved[3 * n + r] = b[r] + a[r][0] * x[3 * n] + a[r][1] * x[3 * n + 1] + a[r][2] * x[3 * n + 2];
            }
        }
        double[] p = new double[3 * m.pointCount()];
        m.apply(moved, p);
        for (int v = 0; v < s.vertexCount(); v++) {
            for (int r = 0; r < 3; r++) {
                double expected = b[r] + a[r][0] * s.coord(v, 0) + a[r][1] * s.coord(v, 1) + a[r][2] * s.coord(v, 2);
                assertEquals(expected, p[3 * v + r], 1e-14, "vertex " + v + " axis " + r);
            }
        }
    }

    @Test
    void surfaceForcesCarriedToTheLatticeKeepTheirSumAndMoment() {
        TriangleMesh s = sphere();
        Topology t = new Topology();
        VolumeBody body = VolumeBody.build(t, s, TISSUE);
        Random r = new Random(3);
        double[] f = new double[3 * s.vertexCount()];
        for (int i = 0; i < f.length; i++) {
            f[i] = r.nextGaussian();
        }
        double[] fn = new double[3 * t.nodeCount()];
        body.surfaceMapping().addTranspose(f, fn);
        double[] x = positions(t);
        double[] vx = s.coordinates();
        double[] total = new double[3];
        double[] moment = new double[3];
        for (int i = 0; i < f.length / 3; i++) {
            add(total, moment, vx, f, i, 1);
        }
        for (int n = 0; n < fn.length / 3; n++) {
            add(total, moment, x, fn, n, -1);
        }
        for (int a = 0; a < 3; a++) {
            assertEquals(0, total[a], 1e-11, "force " + a);
            assertEquals(0, moment[a], 1e-12, "moment " + a);
        }
    }

    private static void add(double[] total, double[] moment, double[] x, double[] f, int i, int sign) {
        double px = x[3 * i], py = x[3 * i + 1], pz = x[3 * i + 2];
        double fx = f[3 * i], fy = f[3 * i + 1], fz = f[3 * i + 2];
        total[0] += sign * fx;
        total[1] += sign * fy;
        total[2] += sign * fz;
        moment[0] += sign * (py * fz - pz * fy);
        moment[1] += sign * (pz * fx - px * fz);
        moment[2] += sign * (px * fy - py * fx);
    }

    @Test
    void massesSumToDensityTimesLatticeVolumeWhichConvergesToTheEnclosedVolume() {
        TriangleMesh s = sphere();
        double enclosed = s.signedVolume();
        double previous = Double.POSITIVE_INFINITY;
        for (double h : new double[] {R / 2, R / 4, R / 8}) {
            Topology t = new Topology();
            VolumeBody body = VolumeBody.build(t, s, TISSUE.withCellSize(h));
            VolumeReport rep = body.report();
            assertEquals(300 * rep.latticeVolumeM3(), t.totalMass(), 1e-12 * t.totalMass());
            assertEquals(rep.massKg(), t.totalMass(), 1e-12 * t.totalMass());
            assertEquals(enclosed, rep.surfaceVolumeM3(), 1e-15);
            double error = Math.abs(rep.latticeVolumeM3() / enclosed - 1);
            System.out.printf("sphere at h = R/%.0f: lattice volume %.5g m^3 against %.5g (%.2f %%)%n", R / h,
                    rep.latticeVolumeM3(), enclosed, 100 * error);
            assertTrue(error < previous, "h " + h + ": volume error " + error + " after " + previous);
            previous = error;
        }
        assertTrue(previous < 0.01, "lattice volume at R/8 within 1 % of the enclosed volume: " + previous);
    }

    /**
     * The identification: under any homogeneous strain eps the lattice's spring energy sum k (n . (u_b - u_a))^2 / 2
     * equals the cubic material's V eps:C:eps / 2 with C11, C12 = C44, exactly, for both fits.
     */
    @Test
    void aHomogeneousStrainStoresTheEnergyOfTheTargetElasticityTensor() {
        double h = 0.01;
        TriangleMesh box = BoxSurface.of(3 * h, 2 * h, 4 * h, h);
        Random r = new Random(5);
        for (SpringFit fit : SpringFit.values()) {
            VolumeParameters p = TISSUE.withCellSize(h).withFit(fit);
            Topology t = new Topology();
            VolumeBody.build(t, box, p);
            LatticeMaterial m = p.material();
            for (int trial = 0; trial < 5; trial++) {
                double[][] e = new double[3][3];
                for (int i = 0; i < 3; i++) {
                    for (int j = i; j < 3; j++) {
                        e[i][j] = e[j][i] = 1e-3 * r.nextGaussian();
                    }
                }
                double lattice = 0;
                for (Spring sp : t.springs()) {
                    Vec3 d = t.node(sp.b()).position().minus(t.node(sp.a()).position());
                    double[] dv = {d.x(), d.y(), d.z()};
                    double stretch = 0;
                    for (int i = 0; i < 3; i++) {
                        for (int j = 0; j < 3; j++) {
                            stretch += dv[i] * e[i][j] * dv[j];
                        }
                    }
                    stretch /= d.norm();
                    lattice += 0.5 * sp.stiffness() * stretch * stretch;
                }
                // The volumetric fit's volume elements store K V (tr eps)^2 / 2 to first order in eps.
                double trace = e[0][0] + e[1][1] + e[2][2];
                for (org.tensim.model.VolumeElement v : t.volumeElements()) {
                    lattice += 0.5 * v.modulusPa() * v.restVolumeM3() * trace * trace;
                }
                assertEquals(fit == SpringFit.VOLUMETRIC ? 24 : 0, t.volumeElements().size(), fit + " elements");
                double c11 = m.c11Pa();
                double c12 = m.c12Pa();
                double c44 = m.c44Pa();
                double density = 0.5 * c11 * (e[0][0] * e[0][0] + e[1][1] * e[1][1] + e[2][2] * e[2][2])
                        + c12 * (e[0][0] * e[1][1] + e[1][1] * e[2][2] + e[2][2] * e[0][0])
                        + 2 * c44 * (e[0][1] * e[0][1] + e[1][2] * e[1][2] + e[0][2] * e[0][2]);
                double continuum = density * 24 * h * h * h;
                assertEquals(continuum, lattice, 1e-9 * continuum, fit + " trial " + trial);
            }
        }
        LatticeMaterial iso = TISSUE.withFit(SpringFit.ISOTROPIC).material();
        assertEquals(0.25, iso.modelPoisson(), 1e-15);
        assertEquals(1e3, iso.youngAlongPa(1, 1, 1), 1e-9, "isotropic: E in every direction");
        LatticeMaterial axial = TISSUE.withFit(SpringFit.AXIAL).material();
        assertEquals(0.4, axial.modelPoisson(), 1e-12);
        assertEquals(1e3, axial.youngAlongPa(0, 0, 1), 1e-9);
        assertEquals(1e3 / (3 * (1 - 0.8)), axial.bulkModulusPa(), 1e-9, "axial: the bulk modulus of (E, nu)");
        LatticeMaterial vol = TISSUE.withFit(SpringFit.VOLUMETRIC).material();
        assertEquals(0.4, vol.modelPoisson(), 1e-12);
        assertEquals(1e3, vol.youngAlongPa(1, 1, 1), 1e-9, "volumetric: E in every direction");
        assertEquals(1e3 / 2.8, vol.shearModulusPa(), 1e-9, "volumetric: mu = E / (2 (1 + nu))");
        assertEquals(1e3 / (3 * (1 - 0.8)), vol.bulkModulusPa(), 1e-9, "volumetric: the bulk modulus of (E, nu)");
    }

    @Test
    void aBoxOfWholeCellsIsFilledByExactlyItsCells() {
        double h = 0.01;
        Topology t = new Topology();
        VolumeBody body = VolumeBody.build(t, BoxSurface.of(3 * h, 2 * h, h, h / 2), TISSUE.withCellSize(h));
        VolumeReport r = body.report();
        assertEquals(6, r.cells());
        assertEquals(24, r.nodes());
        // isotropic: 46 edges and 58 face diagonals, no body diagonals
        assertEquals(46 + 58, r.springs());
        assertEquals(6 * h * h * h, r.latticeVolumeM3(), 1e-18);
        assertEquals(0, r.boundaryEdges());
        assertFalse(r.inwardWound());
        double edge = 0;
        for (Spring sp : t.springs()) {
            Vec3 p = t.node(sp.a()).position();
            Vec3 q = t.node(sp.b()).position();
            if (Math.abs(p.x() - q.x()) > h / 2 && p.y() == q.y() && p.z() == q.z() && p.y() == h && p.z() == 0) {
                edge = sp.stiffness(); // an x edge inside the y = h line on the bottom face: shared by 2 cells
            }
        }
        assertEquals(2 * 1e3 * h / 10, edge, 1e-15, "E h / 10 a cell, two cells");
    }

    @Test
    void anInwardWoundSurfaceIsFilledAndReported() {
        TriangleMesh s = sphere();
        int[] tri = s.triangles();
        for (int k = 0; k < tri.length; k += 3) {
            int swap = tri[k + 1];
            tri[k + 1] = tri[k + 2];
            tri[k + 2] = swap;
        }
        Topology t = new Topology();
        VolumeReport r = VolumeBody.build(t, new TriangleMesh(s.coordinates(), tri), TISSUE).report();
        assertTrue(r.inwardWound(), r.describe());
        Topology u = new Topology();
        assertEquals(VolumeBody.build(u, s, TISSUE).report().cells(), r.cells());
    }

    @Test
    void aSheetThatEnclosesNothingIsRefused() {
        double[] xyz = {0, 0, 0, 0.1, 0, 0, 0.1, 0.1, 0, 0, 0.1, 0};
        TriangleMesh sheet = new TriangleMesh(xyz, new int[] {0, 1, 2, 0, 2, 3});
        Topology t = new Topology();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> VolumeBody.build(t, sheet, TISSUE, "sheet.obj"));
        assertTrue(e.getMessage().startsWith("sheet.obj encloses nothing") && e.getMessage().contains("4 boundary"),
                e.getMessage());
        assertEquals(0, t.nodeCount(), "nothing added");
    }

    @Test
    void anOpenSurfaceIsRefusedWithItsWindingNumber() {
        TriangleMesh s = sphere();
        TriangleMesh bowl = keep(s, (x, y, z) -> z < 0.03 + 0.2 * R);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> VolumeBody.build(new Topology(), bowl, TISSUE.withCellSize(R / 5), "bowl.obj"));
        assertTrue(e.getMessage().startsWith("bowl.obj is open: its winding number is"), e.getMessage());
        double d = 0.04;
        TriangleMesh lidless = keep(BoxSurface.of(d, d, d, d / 4), (x, y, z) -> z < d * 0.99);
        IllegalArgumentException f = assertThrows(IllegalArgumentException.class,
                () -> VolumeBody.build(new Topology(), lidless, TISSUE.withCellSize(d / 8), "lidless.obj"));
        assertTrue(f.getMessage().startsWith("lidless.obj is open") && f.getMessage().contains("16 boundary edges"),
                f.getMessage());
    }

    /** The triangles whose three corners pass. */
    private static TriangleMesh keep(TriangleMesh s, Where w) {
        int[] tri = s.triangles();
        int[] out = new int[tri.length];
        int n = 0;
        for (int k = 0; k < tri.length; k += 3) {
            boolean all = true;
            for (int c = 0; c < 3; c++) {
                all &= w.test(s.coord(tri[k + c], 0), s.coord(tri[k + c], 1), s.coord(tri[k + c], 2));
            }
            if (all) {
                System.arraycopy(tri, k, out, n, 3);
                n += 3;
            }
        }
        return new TriangleMesh(s.coordinates(), java.util.Arrays.copyOf(out, n));
    }

    @FunctionalInterface
    private interface Where {
        boolean test(double x, double y, double z);
    }

    @Test
    void theSharedLiverWithItsFewHolesIsFilledAndItsHolesReported() throws Exception {
        Path liver = SharedData.THORAX.resolve("liver.obj");
        assumeTrue(Files.isRegularFile(liver), liver + " not found");
        TriangleMesh mesh = MeshLoader.load(liver, MeshUnits.MM).mesh();
        Topology t = new Topology();
        VolumeBody body = VolumeBody.build(t, mesh, VolumeParameters.of(0.01, 1e3, 0.4, 300), "liver.obj");
        VolumeReport r = body.report();
        System.out.println(r.describe());
        assertTrue(r.boundaryEdges() > 0, "the shared liver has a few boundary edges: " + r.boundaryEdges());
        assertTrue(r.maxWindingDeviation() < LatticeClip.WINDING_TOLERANCE, r.describe());
        assertEquals(mesh.vertexCount(), body.surfaceMapping().pointCount());
        assertEquals(1, r.latticeVolumeM3() / r.surfaceVolumeM3(), 0.03, r.describe());
    }
}

package org.tensim.scene.volume;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.TetMesh;
import org.tensim.io.mesh.TetMeshReaders;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.LinearMapping;
import org.tensim.model.Spring;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;

/** The tetrahedral volume: the springs' identification, the masses, the carried surface (docs/volume.md). */
class TetVolumeTest {
    private static final VolumeParameters TISSUE = VolumeParameters.of(0.02, 1e3, 0.4, 300);
    private static final double E = 1e3;

    /** A random tet of fair shape (no angle flatter than a sliver), positively oriented, about 1 cm across. */
    private static double[] randomTet(Random r) {
        while (true) {
            double[] x = new double[12];
            for (int i = 0; i < 12; i++) {
                x[i] = 0.01 * r.nextGaussian();
            }
            double v = TetSprings.volume(x);
            if (v < 0) {
                for (int a = 0; a < 3; a++) {
                    double s = x[3 + a];
                    x[3 + a] = x[6 + a];
                    x[6 + a] = s;
                }
                v = -v;
            }
            double longest = 0;
            for (int[] e : TetSprings.EDGES) {
                longest = Math.max(longest, length(x, e));
            }
            // a regular tet has V / l^3 = 0.118
            if (v > 0.03 * longest * longest * longest) {
                return x;
            }
        }
    }

    private static double length(double[] x, int[] e) {
        double s = 0;
        for (int a = 0; a < 3; a++) {
            double d = x[3 * e[1] + a] - x[3 * e[0] + a];
            s += d * d;
        }
        return Math.sqrt(s);
    }

    /** The springs' energy {@code sum k (d . eps . d / |d|)^2 / 2} of one tet under the homogeneous strain eps. */
    private static double energy(double[] x, double[] k, double[][] eps) {
        double w = 0;
        for (int e = 0; e < 6; e++) {
            double[] d = new double[3];
            for (int a = 0; a < 3; a++) {
                d[a] = x[3 * TetSprings.EDGES[e][1] + a] - x[3 * TetSprings.EDGES[e][0] + a];
            }
            w += 0.5 * k[e] * Math.pow(stretch(d, eps), 2);
        }
        return w;
    }

    private static double stretch(double[] d, double[][] eps) {
        double s = 0;
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                s += d[i] * eps[i][j] * d[j];
            }
        }
        return s / Math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    }

    /** Frobenius misfit |C_t - C|^2 of a tet's spring tensor against the isotropic (E, 1/4), Pa^2. */
    private static double misfit(double[] x, double[] k) {
        double v = TetSprings.volume(x);
        double lambda = 0.4 * E;
        double s = 0;
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                for (int p = 0; p < 3; p++) {
                    for (int q = 0; q < 3; q++) {
                        double c = lambda * ((i == j ? 1 : 0) * (p == q ? 1 : 0) + (i == p ? 1 : 0) * (j == q ? 1 : 0)
                                + (i == q ? 1 : 0) * (j == p ? 1 : 0));
                        double ct = 0;
                        for (int e = 0; e < 6; e++) {
                            double l = length(x, TetSprings.EDGES[e]);
                            double[] n = new double[3];
                            for (int a = 0; a < 3; a++) {
                                n[a] = (x[3 * TetSprings.EDGES[e][1] + a] - x[3 * TetSprings.EDGES[e][0] + a]) / l;
                            }
                            ct += k[e] * l * l / v * n[i] * n[j] * n[p] * n[q];
                        }
                        s += (ct - c) * (ct - c);
                    }
                }
            }
        }
        return s;
    }

    @Test
    void aRegularTetGetsSixEqualSpringsOfTwoRootTwoElOverTwentyFive() {
        double[] x = {1, 1, 1, -1, -1, 1, -1, 1, -1, 1, -1, -1};
        for (int i = 0; i < 12; i++) {
            x[i] *= 0.005;
        }
        assertTrue(TetSprings.volume(x) > 0);
        double l = 0.01 * Math.sqrt(2);
        double[] k = new TetSprings(E).stiffness(x);
        for (double ke : k) {
            assertEquals(2 * Math.sqrt(2) * E * l / 25, ke, 1e-12 * ke);
        }
    }

    /**
     * The least-squares identification: its normal equations say that a uniaxial strain along any edge stores the
     * target's energy {@code V (lambda + 2 mu) / 2} exactly, and any change of one spring worsens the fit.
     */
    @Test
    void aUniaxialStrainAlongAnyEdgeStoresTheTargetsEnergyAndTheFitIsLeastSquares() {
        Random r = new Random(3);
        TetSprings fit = new TetSprings(E);
        int checked = 0;
        double worst = 0;
        for (int trial = 0; trial < 200; trial++) {
            double[] x = randomTet(r);
            int before = fit.negativeDropped();
            double[] k = fit.stiffness(x);
            if (fit.negativeDropped() > before) {
                continue;
            }
            checked++;
            double v = TetSprings.volume(x);
            for (int[] e : TetSprings.EDGES) {
                double l = length(x, e);
                double[][] eps = new double[3][3];
                for (int i = 0; i < 3; i++) {
                    for (int j = 0; j < 3; j++) {
                        eps[i][j] = (x[3 * e[1] + i] - x[3 * e[0] + i]) * (x[3 * e[1] + j] - x[3 * e[0] + j]) / (l * l);
                    }
                }
                assertEquals(0.5 * v * 1.2 * E, energy(x, k, eps), 1e-9 * v * E, "trial " + trial);
            }
            double best = misfit(x, k);
            for (int e = 0; e < 6; e++) {
                for (double f : new double[] {0.99, 1.01}) {
                    double[] kk = k.clone();
                    kk[e] *= f;
                    assertTrue(misfit(x, kk) > best, "trial " + trial + ": spring " + e + " times " + f);
                }
            }
            worst = Math.max(worst, Math.sqrt(best) / (1.2 * E));
        }
        System.out.printf("%d of 200 random tets without a negative share; largest misfit |C_t - C| / (lambda + 2 mu)"
                + " %.3f%n", checked, worst);
        assertTrue(checked > 100, "most fair tets need no dropped spring: " + checked);
    }

    /**
     * The assembly: under any homogeneous strain the network's energy is the sum of its tets' (the shares of an edge
     * summed), and its masses sum to rho times the mesh's volume, each node's rho V_t / 4 from its tets.
     */
    @Test
    void theNetworkStoresItsTetsEnergiesAndMassesSumToDensityTimesVolume() {
        double h = 0.01;
        for (BoxTets.Split split : BoxTets.Split.values()) {
            TetMesh mesh = BoxTets.of(3 * h, 2 * h, 2 * h, 3, 2, 2, split);
            Topology t = new Topology();
            VolumeBody body = VolumeBody.buildTets(t, mesh, TISSUE.withDampingTime(0.01), "the box");
            assertEquals(0, body.droppedEdges(), split + ": no negative share in the structured mesh");
            assertEquals(12 * h * h * h, mesh.totalVolume(), 1e-18);
            double mass = 0;
            double[] expected = new double[mesh.nodeCount()];
            for (int tet = 0; tet < mesh.tetCount(); tet++) {
                for (int c = 0; c < 4; c++) {
                    expected[mesh.corner(tet, c)] += 300 * mesh.volume(tet) / 4;
                }
            }
            for (int i = 0; i < body.nodeCount(); i++) {
                mass += t.node(body.firstNode() + i).mass();
                assertEquals(expected[i], t.node(body.firstNode() + i).mass(), 1e-15);
            }
            assertEquals(300 * 12 * h * h * h, mass, 1e-15, split + ": masses sum to rho V");
            assertEquals(mass, body.report().massKg(), 1e-15);
            for (Spring sp : t.springs()) {
                assertEquals(0.01 * sp.stiffness(), sp.damping(), 1e-15, "c = beta k");
            }
            Random r = new Random(7);
            TetSprings fit = new TetSprings(E);
            for (int trial = 0; trial < 5; trial++) {
                double[][] eps = new double[3][3];
                for (int i = 0; i < 3; i++) {
                    for (int j = i; j < 3; j++) {
                        eps[i][j] = eps[j][i] = 1e-3 * r.nextGaussian();
                    }
                }
                double network = 0;
                for (Spring sp : t.springs()) {
                    Vec3 d = t.node(sp.b()).position().minus(t.node(sp.a()).position());
                    network += 0.5 * sp.stiffness() * Math.pow(stretch(new double[] {d.x(), d.y(), d.z()}, eps), 2);
                }
                double tets = 0;
                double[] x = new double[12];
                for (int tet = 0; tet < mesh.tetCount(); tet++) {
                    for (int c = 0; c < 4; c++) {
                        for (int a = 0; a < 3; a++) {
                            x[3 * c + a] = mesh.coord(mesh.corner(tet, c), a);
                        }
                    }
                    tets += energy(x, fit.stiffness(x), eps);
                }
                assertEquals(tets, network, 1e-9 * tets, split + " trial " + trial);
            }
        }
    }

    @Test
    void theBoundarySurfaceIsCarriedByItsOwnNodes() throws Exception {
        Path cube = Path.of(TetVolumeTest.class.getResource("/org/tensim/io/mesh/cube5.msh").toURI());
        TetMesh mesh = TetMeshReaders.read(cube, MeshUnits.MM).mesh();
        Topology t = new Topology();
        t.addNode(1, 1, 1, 1); // a node before the volume's
        VolumeBody body = VolumeBody.buildTets(t, mesh, TISSUE, "cube5.msh");
        assertEquals(1, body.firstNode());
        assertEquals(300 * 1e-6, body.report().massKg(), 1e-15);
        assertEquals(5, body.report().cells());
        LinearMapping m = body.surfaceMapping();
        TriangleMesh s = body.surface();
        assertEquals(s.vertexCount(), m.pointCount());
        double[] x = new double[3 * t.nodeCount()];
        for (int i = 0; i < t.nodeCount(); i++) {
            Vec3 p = t.node(i).position();
            // an affine motion: a shear and a translation
            x[3 * i] = p.x() + 0.3 * p.y() + 0.001;
            x[3 * i + 1] = p.y();
            x[3 * i + 2] = p.z() - 0.2 * p.x();
        }
        double[] pts = new double[3 * m.pointCount()];
        m.apply(x, pts);
        for (int v = 0; v < s.vertexCount(); v++) {
            assertEquals(s.coord(v, 0) + 0.3 * s.coord(v, 1) + 0.001, pts[3 * v], 1e-15);
            assertEquals(s.coord(v, 2) - 0.2 * s.coord(v, 0), pts[3 * v + 2], 1e-15);
        }
        double[] f = new double[3 * m.pointCount()];
        f[3 * 2 + 1] = 2.5;
        double[] nodal = new double[3 * t.nodeCount()];
        m.addTranspose(f, nodal);
        assertEquals(2.5, nodal[3 * (body.firstNode() + mesh.boundaryNode(2)) + 1], 0, "weight 1 on its own node");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> VolumeBody.buildTets(new Topology(), mesh, TISSUE.withFit(SpringFit.AXIAL), "cube5.msh"));
        assertTrue(e.getMessage().startsWith("cube5.msh: the axial spring fit needs a lattice's axes"),
                e.getMessage());
    }

    /** A jittered box keeps its boundary and, the mesh conforming, its volume exactly; its inner nodes move. */
    @Test
    void aJitteredBoxKeepsItsBoundaryAndVolume() {
        double h = 0.01;
        TetMesh box = BoxTets.of(4 * h, 3 * h, 3 * h, 4, 3, 3, BoxTets.Split.FIVE);
        TetMesh j = BoxTets.jittered(box, h, 0.15, 1);
        assertEquals(36 * h * h * h, j.totalVolume(), 1e-9 * 36 * h * h * h);
        int moved = 0;
        for (int v = 0; v < box.nodeCount(); v++) {
            double d = 0;
            for (int a = 0; a < 3; a++) {
                double delta = j.coord(v, a) - box.coord(v, a);
                assertTrue(Math.abs(delta) <= 0.15 * h, "node " + v + " moved " + delta);
                d += Math.abs(delta);
            }
            moved += d > 0 ? 1 : 0;
        }
        assertEquals(3 * 2 * 2, moved, "the 3 x 2 x 2 interior nodes move, the boundary's do not");
        assertEquals(box.boundary().triangleCount(), j.boundary().triangleCount());
        TetMesh big = BoxTets.jittered(BoxTets.of(16 * h, 16 * h, 16 * h, 16, 16, 16, BoxTets.Split.FIVE), h, 0.15, 1);
        VolumeBody body = VolumeBody.buildTets(new Topology(), big, TISSUE, "the jittered box");
        System.out.printf("jittered 16^3 five-tet box: %d of %d tet edges dropped%n", body.droppedEdges(),
                6 * big.tetCount());
        // measured 113 of 122,880
        assertTrue(body.droppedEdges() > 0 && body.droppedEdges() < 0.002 * 6 * big.tetCount(), "dropped shares");
        assertThrows(IllegalArgumentException.class, () -> BoxTets.jittered(box, h, 0.2, 1));
    }
}

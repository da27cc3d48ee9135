package org.tensim.scene.thorax;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.tensim.io.mesh.TriangleMesh;

/** Closed test surfaces with known signed distances, wound counter-clockwise seen from outside. */
public final class TestMeshes {
    private TestMeshes() {
    }

    /** An icosahedron subdivided {@code levels} times, vertices on the sphere of radius r about c, m. */
    public static TriangleMesh icosphere(double[] c, double r, int levels) {
        double p = (1 + Math.sqrt(5)) / 2;
        List<double[]> v = new ArrayList<>(List.of(new double[] {-1, p, 0}, new double[] {1, p, 0},
                new double[] {-1, -p, 0}, new double[] {1, -p, 0}, new double[] {0, -1, p}, new double[] {0, 1, p},
                new double[] {0, -1, -p}, new double[] {0, 1, -p}, new double[] {p, 0, -1}, new double[] {p, 0, 1},
                new double[] {-p, 0, -1}, new double[] {-p, 0, 1}));
        int[] f = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
            3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
        for (double[] q : v) {
            normalise(q);
        }
        for (int l = 0; l < levels; l++) {
            Map<Long, Integer> mid = new HashMap<>();
            int[] g = new int[4 * f.length];
            for (int t = 0; t < f.length / 3; t++) {
                int a = f[3 * t], b = f[3 * t + 1], cc = f[3 * t + 2];
                int ab = midpoint(v, mid, a, b), bc = midpoint(v, mid, b, cc), ca = midpoint(v, mid, cc, a);
                int[] four = {a, ab, ca, b, bc, ab, cc, ca, bc, ab, bc, ca};
                System.arraycopy(four, 0, g, 12 * t, 12);
            }
            f = g;
        }
        double[] xyz = new double[3 * v.size()];
        for (int i = 0; i < v.size(); i++) {
            for (int a = 0; a < 3; a++) {
                xyz[3 * i + a] = c[a] + r * v.get(i)[a];
            }
        }
        return new TriangleMesh(xyz, f);
    }

    private static int midpoint(List<double[]> v, Map<Long, Integer> mid, int a, int b) {
        long key = (long) Math.min(a, b) << 32 | Math.max(a, b);
        return mid.computeIfAbsent(key, k -> {
            double[] m = new double[3];
            for (int i = 0; i < 3; i++) {
                m[i] = (v.get(a)[i] + v.get(b)[i]) / 2;
            }
            normalise(m);
            v.add(m);
            return v.size() - 1;
        });
    }

    private static void normalise(double[] q) {
        double n = Math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
        for (int i = 0; i < 3; i++) {
            q[i] /= n;
        }
    }

    /** The box lo..hi, m, as 12 triangles. */
    public static TriangleMesh box(double[] lo, double[] hi) {
        double[] xyz = new double[24];
        for (int i = 0; i < 8; i++) {
            xyz[3 * i] = (i & 1) == 0 ? lo[0] : hi[0];
            xyz[3 * i + 1] = (i & 2) == 0 ? lo[1] : hi[1];
            xyz[3 * i + 2] = (i & 4) == 0 ? lo[2] : hi[2];
        }
        int[] t = {0, 2, 3, 0, 3, 1, // z = lo, normal -z
            4, 5, 7, 4, 7, 6, // z = hi, +z
            0, 1, 5, 0, 5, 4, // y = lo, -y
            2, 6, 7, 2, 7, 3, // y = hi, +y
            0, 4, 6, 0, 6, 2, // x = lo, -x
            1, 3, 7, 1, 7, 5}; // x = hi, +x
        return new TriangleMesh(xyz, t);
    }

    /** The mesh without the triangles for which {@code drop} is true of their centroid. */
    static TriangleMesh without(TriangleMesh m, java.util.function.Predicate<double[]> drop) {
        List<Integer> kept = new ArrayList<>();
        for (int t = 0; t < m.triangleCount(); t++) {
            double[] c = new double[3];
            for (int k = 0; k < 3; k++) {
                for (int a = 0; a < 3; a++) {
                    c[a] += m.coord(m.corner(t, k), a) / 3;
                }
            }
            if (!drop.test(c)) {
                kept.add(t);
            }
        }
        int[] tri = new int[3 * kept.size()];
        for (int i = 0; i < kept.size(); i++) {
            for (int k = 0; k < 3; k++) {
                tri[3 * i + k] = m.corner(kept.get(i), k);
            }
        }
        return new TriangleMesh(m.coordinates(), tri);
    }

    /** Area-weighted vertex normals, unit, 3 per vertex. */
    static double[] vertexNormals(TriangleMesh m) {
        double[] n = new double[3 * m.vertexCount()];
        double[] fn = new double[3];
        for (int t = 0; t < m.triangleCount(); t++) {
            m.normal(t, fn);
            for (int k = 0; k < 3; k++) {
                for (int a = 0; a < 3; a++) {
                    n[3 * m.corner(t, k) + a] += fn[a];
                }
            }
        }
        for (int v = 0; v < m.vertexCount(); v++) {
            double l = Math.sqrt(n[3 * v] * n[3 * v] + n[3 * v + 1] * n[3 * v + 1] + n[3 * v + 2] * n[3 * v + 2]);
            for (int a = 0; a < 3; a++) {
                n[3 * v + a] = l > 0 ? n[3 * v + a] / l : 0;
            }
        }
        return n;
    }
}

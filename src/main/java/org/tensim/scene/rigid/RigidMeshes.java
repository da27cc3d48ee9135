package org.tensim.scene.rigid;

import org.tensim.io.mesh.TriangleMesh;
import org.tensim.scene.volume.BoxSurface;

/** Triangle meshes that draw the built-in rigid surfaces (m, counter-clockwise seen from outside). */
public final class RigidMeshes {
    private RigidMeshes() {
    }

    /** The box [min, max], each face two triangles. */
    public static TriangleMesh box(double[] min, double[] max) {
        double lx = max[0] - min[0];
        double ly = max[1] - min[1];
        double lz = max[2] - min[2];
        TriangleMesh m = BoxSurface.of(lx, ly, lz, Math.max(lx, Math.max(ly, lz)));
        double[] xyz = m.coordinates().clone();
        for (int i = 0; i < xyz.length; i++) {
            xyz[i] += min[i % 3];
        }
        return new TriangleMesh(xyz, m.triangles().clone());
    }

    /** A latitude-longitude sphere of 12 bands and 24 sectors. */
    public static TriangleMesh sphere(double[] centre, double radius) {
        int bands = 12;
        int sectors = 24;
        int n = 2 + (bands - 1) * sectors;
        double[] xyz = new double[3 * n];
        xyz[2] = radius;
        xyz[3 * (n - 1) + 2] = -radius;
        for (int b = 1; b < bands; b++) {
            double theta = Math.PI * b / bands;
            for (int s = 0; s < sectors; s++) {
                double phi = 2 * Math.PI * s / sectors;
                int v = 1 + (b - 1) * sectors + s;
                xyz[3 * v] = radius * Math.sin(theta) * Math.cos(phi);
                xyz[3 * v + 1] = radius * Math.sin(theta) * Math.sin(phi);
                xyz[3 * v + 2] = radius * Math.cos(theta);
            }
        }
        for (int i = 0; i < n; i++) {
            for (int a = 0; a < 3; a++) {
                xyz[3 * i + a] += centre[a];
            }
        }
        int[] tri = new int[3 * 2 * sectors * (bands - 1)];
        int k = 0;
        for (int s = 0; s < sectors; s++) {
            int s1 = (s + 1) % sectors;
            tri[k++] = 0;
            tri[k++] = 1 + s;
            tri[k++] = 1 + s1;
            int base = 1 + (bands - 2) * sectors;
            tri[k++] = n - 1;
            tri[k++] = base + s1;
            tri[k++] = base + s;
            for (int b = 1; b < bands - 1; b++) {
                int a0 = 1 + (b - 1) * sectors;
                int a1 = 1 + b * sectors;
                tri[k++] = a0 + s;
                tri[k++] = a1 + s;
                tri[k++] = a1 + s1;
                tri[k++] = a0 + s;
                tri[k++] = a1 + s1;
                tri[k++] = a0 + s1;
            }
        }
        return new TriangleMesh(xyz, tri);
    }

    /**
     * A square of half-side h (m) on the plane through p with unit normal n, centred on p, its two triangles facing
     * along n.
     */
    public static TriangleMesh square(double[] p, double[] n, double h) {
        // Two unit vectors in the plane: u across the smallest component of n, w = n x u.
        double[] e = Math.abs(n[0]) < 0.9 ? new double[] {1, 0, 0} : new double[] {0, 1, 0};
        double d = e[0] * n[0] + e[1] * n[1] + e[2] * n[2];
        double[] u = {e[0] - d * n[0], e[1] - d * n[1], e[2] - d * n[2]};
        double lu = Math.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        for (int a = 0; a < 3; a++) {
            u[a] /= lu;
        }
        double[] w = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
        double[] xyz = new double[12];
        double[][] corners = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (int c = 0; c < 4; c++) {
            for (int a = 0; a < 3; a++) {
                xyz[3 * c + a] = p[a] + h * (corners[c][0] * u[a] + corners[c][1] * w[a]);
            }
        }
        return new TriangleMesh(xyz, new int[] {0, 1, 2, 0, 2, 3});
    }
}

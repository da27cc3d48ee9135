package org.tensim.analysis;

import java.util.Random;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Check;
import org.tensim.scene.diaphragm.DoubleDomeGenerator;

/** Flat triangle meshes in the plane z = 0 for the static accuracy scenes, metres. */
public final class FlatMeshes {
    /** Triangulations of a rectangle. */
    public enum Pattern {
        /** Rows of equilateral triangles (the rectangle's width is rounded to whole rows). */
        EQUILATERAL,
        /** Squares cut along one diagonal (right isosceles triangles). */
        RIGHT,
        /** {@link #RIGHT} with every interior vertex moved by up to 0.2 of the spacing (seeded). */
        JITTERED
    }

    private FlatMeshes() {
    }

    /**
     * A disc of radius {@code radiusM}: {@code rings} equally spaced rings around a centre vertex,
     * triangulated as the double dome ({@link DoubleDomeGenerator#ringTriangles}); element size
     * {@code radiusM / rings}.
     */
    public static TriangleMesh disc(int rings, double radiusM) {
        Check.atLeast("disc rings", rings, 1);
        Check.positive("disc radius", "m", radiusM);
        int nv = DoubleDomeGenerator.faceVertices(rings);
        double[] xyz = new double[3 * nv];
        int v = 1;
        for (int i = 1; i <= rings; i++) {
            for (int j = 0; j < 6 * i; j++) {
                double th = 2 * Math.PI * j / (6 * i);
                xyz[3 * v] = radiusM * i / rings * Math.cos(th);
                xyz[3 * v + 1] = radiusM * i / rings * Math.sin(th);
                v++;
            }
        }
        return new TriangleMesh(xyz, DoubleDomeGenerator.ringTriangles(rings));
    }

    /**
     * A rectangle {@code [0, lengthM] x [0, ~widthM]} with {@code cells} elements along its length.
     *
     * @param seed random seed of {@link Pattern#JITTERED}
     */
    public static TriangleMesh rectangle(Pattern pattern, int cells, double lengthM, double widthM, long seed) {
        Check.atLeast("rectangle cells", cells, 2);
        Check.positive("rectangle length", "m", lengthM);
        Check.positive("rectangle width", "m", widthM);
        double h = lengthM / cells;
        boolean eq = pattern == Pattern.EQUILATERAL;
        double dy = eq ? h * Math.sqrt(3) / 2 : h;
        int rows = Math.max(2, (int) Math.round(widthM / dy));
        // Equilateral rows alternate between cells + 1 vertices (even rows) and cells + 2 (odd rows,
        // shifted by h/2, clipped at both ends) so that both sides stay straight.
        int[] start = new int[rows + 2];
        for (int r = 0; r <= rows; r++) {
            start[r + 1] = start[r] + rowCount(eq, r, cells);
        }
        double[] xyz = new double[3 * start[rows + 1]];
        Random rnd = new Random(seed);
        for (int r = 0; r <= rows; r++) {
            for (int c = 0; c < rowCount(eq, r, cells); c++) {
                double x = eq && r % 2 == 1 ? Math.min(lengthM, Math.max(0, (c - 0.5) * h)) : c * h;
                double y = r * dy;
                boolean interior = r > 0 && r < rows && c > 0 && c < cells;
                if (pattern == Pattern.JITTERED && interior) {
                    x += 0.2 * h * (2 * rnd.nextDouble() - 1);
                    y += 0.2 * h * (2 * rnd.nextDouble() - 1);
                }
                int v = start[r] + c;
                xyz[3 * v] = x;
                xyz[3 * v + 1] = y;
            }
        }
        int[] tri = new int[3 * 2 * (cells + 1) * rows];
        int k = 0;
        for (int r = 0; r < rows; r++) {
            int a = start[r];
            int b = start[r + 1];
            if (!eq) {
                for (int c = 0; c < cells; c++) {
                    k = put(tri, k, a + c, a + c + 1, b + c + 1);
                    k = put(tri, k, a + c, b + c + 1, b + c);
                }
            } else if (r % 2 == 0) { // lower row plain (cells + 1), upper shifted (cells + 2)
                for (int c = 0; c < cells; c++) {
                    k = put(tri, k, a + c, a + c + 1, b + c + 1);
                    k = put(tri, k, a + c, b + c + 1, b + c);
                }
                k = put(tri, k, a + cells, b + cells + 1, b + cells);
            } else { // lower row shifted, upper plain
                for (int c = 0; c < cells; c++) {
                    k = put(tri, k, a + c, a + c + 1, b + c);
                    k = put(tri, k, a + c + 1, b + c + 1, b + c);
                }
                k = put(tri, k, a + cells, a + cells + 1, b + cells);
            }
        }
        return new TriangleMesh(xyz, java.util.Arrays.copyOf(tri, k));
    }

    private static int rowCount(boolean eq, int row, int cells) {
        return eq && row % 2 == 1 ? cells + 2 : cells + 1;
    }

    private static int put(int[] tri, int k, int a, int b, int c) {
        tri[k] = a;
        tri[k + 1] = b;
        tri[k + 2] = c;
        return k + 3;
    }
}

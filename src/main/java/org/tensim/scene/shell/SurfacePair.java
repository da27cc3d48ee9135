package org.tensim.scene.shell;

import java.util.Arrays;
import org.tensim.io.mesh.TriangleMesh;

/** The paper's two boundary surfaces given apart (two files) made into one {@link TwoSurfaces}. */
public final class SurfacePair {
    private SurfacePair() {
    }

    /**
     * Two boundary surfaces given apart, as the paper defines its objects: {@code upper}'s vertices first, then
     * {@code lower}'s, each vertex paired with its nearest on the other surface. The lower surface's triangles are
     * wound against the upper's (reversed when the two files wind them the same way, as the area-weighted normals
     * say), so that the shell's faces point outwards on both sides, as {@link TwoSurfaces#offset}'s do.
     */
    public static TwoSurfaces of(TriangleMesh upper, TriangleMesh lower) {
        int nu = upper.vertexCount();
        int nl = lower.vertexCount();
        double[] xyz = new double[3 * (nu + nl)];
        System.arraycopy(upper.coordinates(), 0, xyz, 0, 3 * nu);
        System.arraycopy(lower.coordinates(), 0, xyz, 3 * nu, 3 * nl);
        double[] a = areaNormal(upper);
        double[] b = areaNormal(lower);
        boolean reverse = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] > 0;
        int tu = upper.triangleCount();
        int tl = lower.triangleCount();
        int[] tri = new int[3 * (tu + tl)];
        for (int t = 0; t < tu; t++) {
            for (int k = 0; k < 3; k++) {
                tri[3 * t + k] = upper.corner(t, k);
            }
        }
        for (int t = 0; t < tl; t++) {
            tri[3 * (tu + t)] = nu + lower.corner(t, 0);
            tri[3 * (tu + t) + 1] = nu + lower.corner(t, reverse ? 2 : 1);
            tri[3 * (tu + t) + 2] = nu + lower.corner(t, reverse ? 1 : 2);
        }
        boolean[] up = new boolean[nu + nl];
        Arrays.fill(up, 0, nu, true);
        return TwoSurfaces.of(new TriangleMesh(xyz, tri), up);
    }

    /** The sum of a mesh's triangles' normals times their areas (twice the vector area). */
    private static double[] areaNormal(TriangleMesh m) {
        double[] sum = new double[3];
        double[] n = new double[3];
        for (int t = 0; t < m.triangleCount(); t++) {
            m.normal(t, n);
            double area = m.area(t);
            for (int k = 0; k < 3; k++) {
                sum[k] += area * n[k];
            }
        }
        return sum;
    }
}

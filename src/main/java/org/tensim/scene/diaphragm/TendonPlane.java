package org.tensim.scene.diaphragm;

import java.util.Arrays;
import org.tensim.model.Vec3;
import org.tensim.scene.shell.SurfaceGeometry;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * The paper's tendon rule: the central tendon is the cap of the mesh on the side of a plane its unit normal n
 * points to, the vertices v with {@code n . x_v >= c}. Without a given point the offset c is placed so that the
 * tendon covers a share of the upper surface's area (each upper vertex weighted by its third of its triangles'
 * areas): the upper vertices are taken highest first along n until their area reaches the share, and c is the
 * last one's height. The scene builder uses it, and the GUI moves the plane from there.
 */
public final class TendonPlane {
    private TendonPlane() {
    }

    /**
     * The plane's offset c, m, that leaves {@code share} of the upper surface's area on the tendon's side.
     *
     * @param normal the plane's normal (normalised here)
     * @param share  the tendon's share of the upper surface's area, in (0, 1)
     */
    public static double offsetForShare(TwoSurfaces s, Vec3 normal, double share) {
        return offsetForShare(s, SurfaceGeometry.vertexAreas(s.mesh()), normal.normalized(), share);
    }

    static double offsetForShare(TwoSurfaces s, double[] area, Vec3 n, double share) {
        if (!(share > 0 && share < 1)) {
            throw new IllegalArgumentException("tendon area share must be in (0, 1), got " + share);
        }
        int nv = s.mesh().vertexCount();
        Integer[] order = new Integer[nv];
        double total = 0;
        int k = 0;
        for (int v = 0; v < nv; v++) {
            if (s.isUpper(v)) {
                order[k++] = v;
                total += area[v];
            }
        }
        if (k == 0) {
            throw new IllegalArgumentException("the mesh has no upper surface to place the tendon plane on");
        }
        Integer[] up = Arrays.copyOf(order, k);
        Arrays.sort(up, (a, b) -> Double.compare(height(s, n, b), height(s, n, a)));
        double acc = 0;
        double cut = height(s, n, up[0]);
        for (Integer v : up) {
            acc += area[v];
            cut = height(s, n, v);
            if (acc >= share * total) {
                break;
            }
        }
        return cut;
    }

    /** Height of vertex v along n, m. */
    static double height(TwoSurfaces s, Vec3 n, int v) {
        return n.x() * s.mesh().coord(v, 0) + n.y() * s.mesh().coord(v, 1) + n.z() * s.mesh().coord(v, 2);
    }
}

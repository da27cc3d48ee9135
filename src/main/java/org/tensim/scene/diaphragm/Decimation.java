package org.tensim.scene.diaphragm;

import java.util.Locale;
import org.tensim.io.mesh.QuadricDecimation;
import org.tensim.model.Check;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * How the resolution study coarsens a two-surface shell, both with the two faces kept apart and each vertex
 * keeping its face, and the coarse model carrying the given mesh's free rim ({@link TwoSurfaces#withRimOf}).
 */
public enum Decimation {
    /**
     * Vertex clustering in cubes of the given size ({@link TwoSurfaces#decimated}); opens holes and folds the
     * given mesh does not have.
     */
    CLUSTERING,
    /**
     * Quadric-error edge collapse ({@link QuadricDecimation}) down to the triangles that equilateral ones of
     * the given edge would need to cover the mesh's area, A / (sqrt(3)/4 h^2); keeps a 2-manifold one, and
     * each face's rim on its course.
     */
    QUADRIC;

    /**
     * @param sizeM clustering cell or target edge length, m (> 0)
     */
    public TwoSurfaces coarsen(TwoSurfaces s, double sizeM) {
        Check.positive(name().toLowerCase(Locale.ROOT) + " size", "m", sizeM);
        if (this == CLUSTERING) {
            return s.decimated(sizeM);
        }
        int target = (int) Math.round(s.mesh().totalArea() / (Math.sqrt(3) / 4 * sizeM * sizeM));
        return quadric(s, target);
    }

    /** The shell decimated by quadric-error edge collapse to about {@code targetTriangles} (at least 4). */
    public static TwoSurfaces quadric(TwoSurfaces s, int targetTriangles) {
        int[] groups = new int[s.mesh().vertexCount()];
        for (int v = 0; v < groups.length; v++) {
            groups[v] = s.isUpper(v) ? 1 : 0;
        }
        QuadricDecimation.Result r = QuadricDecimation.simplify(s.mesh(), groups, Math.max(4, targetTriangles));
        boolean[] up = new boolean[r.groups().length];
        for (int v = 0; v < up.length; v++) {
            up[v] = r.groups()[v] == 1;
        }
        return TwoSurfaces.of(r.mesh(), up).withRimOf(s);
    }
}

package org.tensim.scene.diaphragm;

import java.util.ArrayList;
import java.util.List;
import org.tensim.scene.shell.TwoSurfaces;

/** Where the muscle's action lines go when none are given: one through each dome's top. */
public final class DefaultActionLines {
    private DefaultActionLines() {
    }

    /**
     * Two action lines through the highest points of the right and left halves of the
     * upper surface (the domes), each with a radius of action of 0.3 times the
     * mesh's transverse width. The highest points are taken on a quadratic fitted to the
     * surface around the highest vertices ({@link DomeTops}), not at the vertices, whose place on
     * a flat top changes with the mesh.
     */
    public static List<ActionLines.Line> of(TwoSurfaces s) {
        double[] bounds = s.mesh().bounds();
        double cx = 0.5 * (bounds[0] + bounds[3]);
        double radius = 0.3 * (bounds[3] - bounds[0]);
        List<ActionLines.Line> l = new ArrayList<>();
        for (double[] top : DomeTops.tops(s, cx)) {
            if (top != null) {
                l.add(new ActionLines.Line(top[0], top[1], radius));
            }
        }
        return l;
    }
}

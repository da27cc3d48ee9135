package org.tensim.scene.diaphragm;

import org.tensim.io.mesh.VertexLabel;
import org.tensim.scene.shell.TwoSurfaces;

/** The labels of a built diaphragm scene's mesh vertices, as a label file holds them. */
final class SceneVertexLabels {
    private SceneVertexLabels() {
    }

    /**
     * The labels of the mesh's vertices as the scene has them, for a label file ({@code VertexLabelsFile}): tendon
     * or muscle as built (by the rule and its share or plane, or a label file); the origins of the label file the
     * scene was built from, or else its attached nodes, each named by its nearest origin bone (a vertebra: lumbar;
     * the sternum or xiphoid: sternal; a rib or cartilage, or a cage without bone surfaces: costal). Read back, a
     * file's origins are widened by the insertion's width as any label file's are.
     */
    static VertexLabel[] of(DiaphragmScene scene) {
        int n = scene.diaphragmNodes();
        int[] labels = scene.labels();
        VertexLabel[] file = scene.fileLabels();
        VertexLabel[] out = new VertexLabel[n];
        double[] g = new double[3];
        for (int v = 0; v < n; v++) {
            VertexLabel l = labels[v] == DiaphragmScene.TENDON ? VertexLabel.TENDON : VertexLabel.MUSCLE;
            if (file != null) {
                if (file[v].isOrigin()) {
                    l = file[v];
                }
            } else if (scene.isAttached(v)) {
                l = originNear(scene, v, g);
            }
            out[v] = l;
        }
        return out;
    }

    /** The origin label of attached node v by its nearest origin bone. */
    private static VertexLabel originNear(DiaphragmScene scene, int v, double[] g) {
        Bones bones = scene.bones();
        if (bones == null) {
            return VertexLabel.ORIGIN_COSTAL;
        }
        TwoSurfaces surfaces = scene.surfaces();
        double x = surfaces.mesh().coord(v, 0);
        double y = surfaces.mesh().coord(v, 1);
        double z = surfaces.mesh().coord(v, 2);
        Bones.Kind nearest = null;
        double best = Double.POSITIVE_INFINITY;
        for (int i = 0; i < bones.all().size(); i++) {
            if (!bones.all().get(i).origin()) {
                continue;
            }
            double d = Math.abs(bones.field(i).distance(x, y, z, g, 0));
            if (d < best) {
                best = d;
                nearest = bones.all().get(i).kind();
            }
        }
        if (nearest == Bones.Kind.VERTEBRA) {
            return VertexLabel.ORIGIN_LUMBAR;
        }
        return nearest == Bones.Kind.STERNUM || nearest == Bones.Kind.XIPHOID
                ? VertexLabel.ORIGIN_STERNAL : VertexLabel.ORIGIN_COSTAL;
    }
}

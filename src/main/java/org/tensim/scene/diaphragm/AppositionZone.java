package org.tensim.scene.diaphragm;

import org.tensim.scene.shell.TwoSurfaces;

/**
 * The zone of apposition (package-private, read by the scene builder): the part of the diaphragm that lies against
 * the inner chest wall, where the abdominal pressure holds the muscle on the lower rib cage (De Troyer and Boriek,
 * Compr Physiol 2011). A lower-surface (abdominal) vertex belongs to it when it, or its partner across the thickness
 * on the upper surface, lies within {@link BoneContact#RANGE_M} of a rib, costal cartilage, sternum or xiphoid
 * surface at rest: the nodes that may touch the chest wall. The vertebrae (the crura, attached along them) and the
 * liver (a support, not the wall) do not count. The zone is a region of the surface, not a count of nodes: a finer
 * mesh of the same surface has the same zone.
 */
final class AppositionZone {
    private AppositionZone() {
    }

    /** Per vertex of {@code surfaces}' mesh, whether it is a lower-surface vertex of the zone. */
    static boolean[] lowerVertices(TwoSurfaces surfaces, Bones bones) {
        var m = surfaces.mesh();
        int nv = m.vertexCount();
        boolean[] near = new boolean[nv];
        double[] g = new double[3];
        for (int v = 0; v < nv; v++) {
            double x = m.coord(v, 0);
            double y = m.coord(v, 1);
            double z = m.coord(v, 2);
            for (int i = 0; i < bones.all().size() && !near[v]; i++) {
                Bones.Kind kind = bones.all().get(i).kind();
                if (kind == Bones.Kind.VERTEBRA || kind == Bones.Kind.LIVER
                        || !OriginAttachment.near(bones.all().get(i).mesh().bounds(), x, y, z, BoneContact.RANGE_M)) {
                    continue;
                }
                near[v] = bones.field(i).distance(x, y, z, g, 0) < BoneContact.RANGE_M;
            }
        }
        boolean[] zone = new boolean[nv];
        for (int v = 0; v < nv; v++) {
            zone[v] = !surfaces.isUpper(v) && (near[v] || near[surfaces.partner(v)]);
        }
        return zone;
    }
}

package org.tensim.scene.lungs;

import java.io.IOException;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.List;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.io.thorax.Thorax;
import org.tensim.io.thorax.ThoraxLoader;
import org.tensim.io.thorax.ThoraxPart;

/**
 * The organs' surfaces of a thorax folder, read once for {@link ThoraxOrgans#build}: the right lung's then the left's
 * merged lobes ({@link LungVolumes#surfaces}) and the liver, m, in the thorax's frame.
 *
 * @param lungs the right lung's, then the left's closed surface
 * @param liver the liver's closed surface, or null when it was not asked for
 */
public record OrganMeshes(List<TriangleMesh> lungs, TriangleMesh liver) {
    public OrganMeshes {
        lungs = List.copyOf(lungs);
    }

    /**
     * Reads the lungs (and the liver when {@code withLiver}) of the thorax at {@code dir}.
     *
     * @throws IllegalArgumentException naming the folder's parts.json when it lists no lung on a side, or no liver
     *                                  with the liver asked for
     */
    public static OrganMeshes load(Path dir, boolean withLiver) throws IOException {
        Thorax thorax = ThoraxLoader.load(dir, EnumSet.of(ThoraxPart.Group.LUNG, ThoraxPart.Group.LIVER));
        TriangleMesh liver = null;
        if (withLiver) {
            List<ThoraxPart> l = thorax.group(ThoraxPart.Group.LIVER);
            if (l.isEmpty()) {
                throw new IllegalArgumentException(thorax.partsJson() + " lists no liver part (file liver*.obj):"
                        + " expected one for the liver volume (or leave the liver out)");
            }
            liver = l.get(0).mesh();
        }
        return new OrganMeshes(LungVolumes.surfaces(thorax), liver);
    }
}

package org.tensim.scene.lungs;

import java.util.ArrayList;
import java.util.List;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.io.thorax.Thorax;
import org.tensim.io.thorax.ThoraxPart;
import org.tensim.io.thorax.ThoraxPart.Group;
import org.tensim.io.thorax.ThoraxPart.Side;
import org.tensim.model.Topology;
import org.tensim.scene.volume.SpringFit;
import org.tensim.scene.volume.VolumeBody;
import org.tensim.scene.volume.VolumeParameters;

/**
 * Both lungs of a thorax as volume bodies: the lobes of each lung (the shared thorax's right superior, middle and
 * inferior, left superior and inferior) merged into one surface, the union of their triangles, which the lattice's
 * winding number fills as one volume (inside where |w| &gt; 1/2: a point inside either lobe, or in both where
 * their surfaces overlap at a fissure, is inside the lung); the lobes do not slide on each other.
 *
 * <p>Default parenchyma ({@link #PARENCHYMA}): E = 1 kPa (the middle of the 0.7-2 kPa of docs/lungs.md),
 * nu = 0.4 by the volumetric fit (the springs alone would give 1/4), density 300 kg/m^3 (aerated lung at about
 * -700 HU on CT, density about 1 + HU/1000 g/cm^3), 12 mm cells (about 1.5-2.5 thousand nodes a lung on the
 * shared thorax). Sources and measured builds: docs/lungs.md.
 */
public final class LungVolumes {
    /** E 1 kPa, nu 0.4 (volumetric fit), 300 kg/m^3, 12 mm cells, no damping. */
    public static final VolumeParameters PARENCHYMA = VolumeParameters.of(0.012, 1e3, 0.4, 300)
            .withFit(SpringFit.VOLUMETRIC);

    /**
     * One lung as built.
     *
     * @param side         the patient's side
     * @param lobes        the lobes' part names, merged
     * @param surface      the merged surface, m
     * @param body         the volume body
     * @param buildSeconds wall time of the fill, s
     */
    public record Lung(Side side, List<String> lobes, TriangleMesh surface, VolumeBody body, double buildSeconds) {
    }

    private LungVolumes() {
    }

    /**
     * Builds the right lung, then the left, into {@code t}, from the thorax's lung parts (loaded with the
     * {@link Group#LUNG} group): those of the side, or whose file is named {@code lung-right-*} or
     * {@code lung-left-*}.
     *
     * @throws IllegalArgumentException when the thorax has no lung part on a side
     */
    public static List<Lung> build(Topology t, Thorax thorax, VolumeParameters p) {
        List<Lung> out = new ArrayList<>();
        for (Side side : new Side[] {Side.RIGHT, Side.LEFT}) {
            // The shared parts.json gives the organs no side: the file's name does (lung-right-*, lung-left-*).
            String key = "lung-" + side.name().toLowerCase(java.util.Locale.ROOT) + "-";
            List<ThoraxPart> lobes = thorax.group(Group.LUNG).stream().filter(q -> q.side() == side
                    || q.file().getFileName().toString().toLowerCase(java.util.Locale.ROOT).startsWith(key)).toList();
            if (lobes.isEmpty()) {
                throw new IllegalArgumentException(thorax.partsJson() + " lists no " + side.name().toLowerCase(
                        java.util.Locale.ROOT) + " lung part (group organ, file lung-" + side.name().toLowerCase(
                        java.util.Locale.ROOT) + "-*.obj); expected its lobes");
            }
            TriangleMesh merged = merge(lobes);
            List<String> names = lobes.stream().map(ThoraxPart::name).toList();
            long t0 = System.nanoTime();
            VolumeBody body = VolumeBody.build(t, merged, p, String.join(" + ", names));
            out.add(new Lung(side, names, merged, body, (System.nanoTime() - t0) * 1e-9));
        }
        return out;
    }

    /**
     * The right lung's then the left's merged surface (m), from the thorax's lung parts, as {@link #build} merges
     * them.
     *
     * @throws IllegalArgumentException when the thorax has no lung part on a side
     */
    public static List<TriangleMesh> surfaces(Thorax thorax) {
        List<TriangleMesh> out = new ArrayList<>();
        for (Side side : new Side[] {Side.RIGHT, Side.LEFT}) {
            String key = "lung-" + side.name().toLowerCase(java.util.Locale.ROOT) + "-";
            List<ThoraxPart> lobes = thorax.group(Group.LUNG).stream().filter(q -> q.side() == side
                    || q.file().getFileName().toString().toLowerCase(java.util.Locale.ROOT).startsWith(key)).toList();
            if (lobes.isEmpty()) {
                throw new IllegalArgumentException(thorax.partsJson() + " lists no " + side.name().toLowerCase(
                        java.util.Locale.ROOT) + " lung part (group organ, file " + key + "*.obj); expected its lobes");
            }
            out.add(merge(lobes));
        }
        return out;
    }

    /** The union of the parts' triangles, each part's vertices renumbered after the ones before. */
    static TriangleMesh merge(List<ThoraxPart> parts) {
        int nv = 0;
        int nt = 0;
        for (ThoraxPart part : parts) {
            nv += part.mesh().vertexCount();
            nt += part.mesh().triangleCount();
        }
        double[] xyz = new double[3 * nv];
        int[] tri = new int[3 * nt];
        int v = 0;
        int k = 0;
        for (ThoraxPart part : parts) {
            TriangleMesh m = part.mesh();
            System.arraycopy(m.coordinates(), 0, xyz, 3 * v, 3 * m.vertexCount());
            int[] pt = m.triangles();
            for (int i = 0; i < pt.length; i++) {
                tri[k++] = pt[i] + v;
            }
            v += m.vertexCount();
        }
        return new TriangleMesh(xyz, tri);
    }
}

package org.tensim.scene.lungs;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.util.EnumSet;
import java.util.List;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.tensim.analysis.lungs.SiProfile;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.io.thorax.Thorax;
import org.tensim.io.thorax.ThoraxLoader;
import org.tensim.io.thorax.ThoraxPart.Group;
import org.tensim.io.thorax.ThoraxPart.Side;
import org.tensim.model.Topology;
import org.tensim.scene.volume.VolumeReport;
import org.tensim.testsupport.SharedData;

/** Both lungs of the shared thorax as volume bodies of the default parenchyma, and 300 points drawn in them. */
class LungVolumesTest {
    @Test
    void theSharedLungsBuildAsVolumesWithPointsOverTheirWholeHeight() throws Exception {
        for (String f : new String[] {"parts.json", "lung-right-superior.obj", "lung-left-inferior.obj"}) {
            Assumptions.assumeTrue(Files.isRegularFile(SharedData.THORAX.resolve(f)),
                    SharedData.THORAX.resolve(f).toAbsolutePath() + " not found");
        }
        Thorax thorax = ThoraxLoader.load(SharedData.THORAX, EnumSet.of(Group.LUNG));
        Topology t = new Topology();
        List<LungVolumes.Lung> lungs = LungVolumes.build(t, thorax, LungVolumes.PARENCHYMA);
        assertEquals(2, lungs.size());
        assertEquals(Side.RIGHT, lungs.get(0).side());
        assertEquals(3, lungs.get(0).lobes().size(), "the right lung's three lobes");
        assertEquals(2, lungs.get(1).lobes().size(), "the left lung's two lobes");
        int elements = 0;
        for (LungVolumes.Lung l : lungs) {
            VolumeReport r = l.body().report();
            double lobes = 0;
            for (String name : l.lobes()) {
                lobes += Math.abs(thorax.part(name).mesh().signedVolume());
            }
            System.out.printf("%s lung (%s): %d nodes, %d springs, %d cells at %.0f mm, lattice %.1f cm^3 (lobes"
                    + " %.1f cm^3), mass %.3f kg, built in %.1f s%n", l.side(), String.join(", ", l.lobes()),
                    r.nodes(), r.springs(), r.cells(), r.cellSizeM() * 1e3, r.latticeVolumeM3() * 1e6,
                    lobes * 1e6, r.massKg(), l.buildSeconds());
            assertTrue(r.nodes() >= 1000 && r.nodes() <= 3000, l.side() + " lung nodes: " + r.nodes());
            // The merged lobes hold their volumes: the fissures' overlaps and gaps are a few per cent.
            assertEquals(lobes, r.latticeVolumeM3(), 0.05 * lobes, l.side() + " lattice volume against the lobes'");
            assertEquals(300 * r.latticeVolumeM3(), r.massKg(), 1e-9, "mass = rho V");
            elements += r.cells();
        }
        assertEquals(elements, t.volumeElements().size(), "one volume element a kept cell (volumetric fit)");
        List<TriangleMesh> surfaces = lungs.stream().map(LungVolumes.Lung::surface).toList();
        LungSamples s = LungSamples.draw(surfaces, 300, LungSamples.SEED);
        assertEquals(300, s.count());
        assertArrayEquals(s.positions(), LungSamples.draw(surfaces, 300, LungSamples.SEED).positions(),
                "a fixed seed gives the same points");
        for (int lung = 0; lung < 2; lung++) {
            final int which = lung;
            int[] idx = java.util.stream.IntStream.range(0, 300).filter(i -> s.lung()[i] == which).toArray();
            // Every fifth of the lung's height holds points (a zero displacement field has no ratios: bins only).
            SiProfile p = SiProfile.of(s.positions(), new double[900], new double[] {0, 0, 1}, idx);
            double[] b = surfaces.get(lung).bounds();
            System.out.printf("%s lung: %d points, per fifth of their height (apex to base) %s, spanning %.0f of"
                    + " the surface's %.0f mm%n", lungs.get(lung).side(), idx.length,
                    java.util.Arrays.toString(p.binCount()), p.heightM() * 1e3, (b[5] - b[2]) * 1e3);
            for (int c : p.binCount()) {
                assertTrue(c > 0, "every fifth of the height holds points: " + java.util.Arrays.toString(
                        p.binCount()));
            }
            assertTrue(p.heightM() > 0.9 * (b[5] - b[2]), "the points span the lung's height");
        }
    }
}

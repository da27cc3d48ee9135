package org.tensim.scene.lungs;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.io.thorax.ThoraxLoader;
import org.tensim.io.thorax.ThoraxPart.Group;
import org.tensim.model.LinearMapping;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.scene.shell.TwoSurfaces;
import org.tensim.testsupport.SharedData;

/**
 * The carried parietal pleura stays a surface when the diaphragm descends against the chest wall: on the shared
 * thorax (the BodyParts3D diaphragm decimated at 10 mm), every diaphragm node moved 10 mm down (the dome's quiet
 * descent, the ribs and fixed parts at rest), no triangle of either lung's pleura turns over (its normal against its
 * rest normal). Each vertex carried by its own carrier alone (blend 0), the triangles where the diaphragmatic part
 * meets the costal and fixed parts do turn over: the fold a lung's follower is then held to the wrong side of (the
 * right lung's runaway in the thorax run, docs/lungs.md).
 */
class PleuraFoldTest {
    @Test
    void thePleuraDoesNotFoldWhenTheDiaphragmDescends() throws Exception {
        Path thoraxDir = SharedData.THORAX;
        Path mesh = SharedData.BODYPARTS3D_DIAPHRAGM;
        for (Path f : new Path[] {thoraxDir.resolve("parts.json"), mesh}) {
            assumeTrue(Files.isRegularFile(f), f.toAbsolutePath() + " not found");
        }
        DiaphragmSpec spec = DiaphragmSpec.defaults().withCage(DiaphragmSpec.Cage.defaults().withThorax(thoraxDir));
        spec = spec.withMesh(spec.mesh().withFile(mesh, MeshUnits.parse("mm")));
        DiaphragmSetup.Inputs in = DiaphragmSetup.read(spec);
        TwoSurfaces s = in.surfaces().surfaces().decimated(0.010);
        List<TriangleMesh> lungs = LungVolumes.surfaces(ThoraxLoader.load(thoraxDir, EnumSet.of(Group.LUNG)));
        double descentM = 0.010;
        int[] unblended = turnedOver(s, spec, in, lungs, PleuraCarriers.Rules.defaults().withBlend(0), descentM);
        int[] blended = turnedOver(s, spec, in, lungs, PleuraCarriers.Rules.defaults(), descentM);
        System.out.printf("pleura triangles turned over by a %.0f mm descent, right/left: by each vertex's own"
                + " carrier %d/%d, blended over %.0f mm %d/%d%n", 1e3 * descentM, unblended[0], unblended[1],
                1e3 * PleuraCarriers.Rules.defaults().blendM(), blended[0], blended[1]);
        assertTrue(unblended[0] > 0 && unblended[1] > 0, "the unblended carriers fold the pleura");
        assertEquals(0, blended[0], "right pleura triangles turned over");
        assertEquals(0, blended[1], "left pleura triangles turned over");
    }

    /** Per lung, the pleura triangles whose normal has turned by more than 90 degrees. */
    private static int[] turnedOver(TwoSurfaces s, DiaphragmSpec spec, DiaphragmSetup.Inputs in,
            List<TriangleMesh> lungs, PleuraCarriers.Rules rules, double descentM) {
        DiaphragmScene scene = DiaphragmScene.build(s, spec, Map.of(), in.bones(), null, spec.newControls());
        int[] upper = scene.upperTriangles();
        var ribs = OrganGeometry.ribs(scene.topology(), scene.cage().segments());
        int[] out = new int[lungs.size()];
        for (int i = 0; i < lungs.size(); i++) {
            PleuraCarriers.Built b = PleuraCarriers.build(scene.topology(), lungs.get(i), upper, ribs, rules, 0);
            double[] x0 = OrganGeometry.restPositions(scene.topology(), scene.topology().nodeCount());
            double[] x = x0.clone();
            for (int v = 0; v < scene.diaphragmNodes(); v++) {
                x[3 * v + 2] -= descentM;
            }
            double[] n0 = normals(b.mapping(), b.surface().triangles(), x0);
            double[] n = normals(b.mapping(), b.surface().triangles(), x);
            for (int t = 0; 3 * t < n.length; t++) {
                if (n[3 * t] * n0[3 * t] + n[3 * t + 1] * n0[3 * t + 1] + n[3 * t + 2] * n0[3 * t + 2] < 0) {
                    out[i]++;
                }
            }
        }
        return out;
    }

    /** Unit normal per triangle of the mapped surface at x. */
    static double[] normals(LinearMapping m, int[] tr, double[] x) {
        double[] p = new double[3 * m.pointCount()];
        m.apply(x, p);
        double[] n = new double[tr.length];
        for (int t = 0; 3 * t < tr.length; t++) {
            int ia = 3 * tr[3 * t], ib = 3 * tr[3 * t + 1], ic = 3 * tr[3 * t + 2];
            double e1x = p[ib] - p[ia], e1y = p[ib + 1] - p[ia + 1], e1z = p[ib + 2] - p[ia + 2];
            double e2x = p[ic] - p[ia], e2y = p[ic + 1] - p[ia + 1], e2z = p[ic + 2] - p[ia + 2];
            double nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
            double l = Math.sqrt(nx * nx + ny * ny + nz * nz);
            n[3 * t] = nx / l;
            n[3 * t + 1] = ny / l;
            n[3 * t + 2] = nz / l;
        }
        return n;
    }
}

package org.tensim.scene.tunable;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.io.mesh.VertexLabel;
import org.tensim.io.mesh.VertexLabelsFile;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.scene.shell.TwoSurfaces;

/** The label brush picks the surface the eye sees first and paints a disc; the scenes built after it have its labels. */
class LabelBrushTest {
    private static final DiaphragmSpec COARSE = DiaphragmSpec.defaults()
            .withMesh(DiaphragmSpec.Mesh.defaults().withRings(8));

    @Test
    void aRayFromAbovePicksTheUpperSurfaceUnderThePointer() {
        DiaphragmScene s = ((DiaphragmViewScene) DiaphragmViewScene.factory(COARSE).create(true)).scene();
        TwoSurfaces m = s.surfaces();
        int apex = s.apexNode();
        double[] a = {m.mesh().coord(apex, 0), m.mesh().coord(apex, 1), m.mesh().coord(apex, 2)};
        int hit = LabelBrush.pick(m, new double[] {a[0], a[1], a[2] + 1}, new double[] {0, 0, -3}, 0.004);
        assertTrue(hit >= 0, "hit");
        assertTrue(m.isUpper(hit), "the upper face, which the eye above meets first, not the lower one under it");
        assertTrue(Math.hypot(m.mesh().coord(hit, 0) - a[0], m.mesh().coord(hit, 1) - a[1]) <= 0.004,
                "within the tolerance of the ray");
        // From below, the lower face; a ray beside the mesh meets nothing.
        int under = LabelBrush.pick(m, new double[] {a[0], a[1], a[2] - 1}, new double[] {0, 0, 1}, 0.004);
        assertTrue(under >= 0 && !m.isUpper(under), "from below: the lower face");
        assertEquals(-1, LabelBrush.pick(m, new double[] {a[0] + 5, a[1], a[2] + 1}, new double[] {0, 0, -1}, 0.004));
        assertThrows(IllegalArgumentException.class, () -> LabelBrush.pick(m, a, new double[3], 0.004));
    }

    @Test
    void aStrokePaintsTheDiscOnlyAndTheNextSceneIsBuiltWithIt(@TempDir Path dir) throws Exception {
        DiaphragmViewFactory f = DiaphragmViewScene.factory(COARSE, null);
        DiaphragmScene s = ((DiaphragmViewScene) f.create(true)).scene();
        TwoSurfaces m = s.surfaces();
        VertexLabel[] before = s.currentVertexLabels();
        // A muscle vertex of the upper face half-way down a dome.
        int centre = -1;
        for (int v = 0; v < before.length && centre < 0; v++) {
            if (before[v] == VertexLabel.MUSCLE && m.isUpper(v) && !s.isAttached(v)
                    && m.mesh().coord(v, 2) > m.mesh().coord(s.apexNode(), 2) - 0.04) {
                centre = v;
            }
        }
        assertTrue(centre >= 0);
        double r = 0.03;
        VertexLabel[] after = LabelBrush.paint(m, before, centre, r, VertexLabel.TENDON);
        int painted = 0;
        for (int v = 0; v < after.length; v++) {
            double d = Math.sqrt(sq(m.mesh().coord(v, 0) - m.mesh().coord(centre, 0))
                    + sq(m.mesh().coord(v, 1) - m.mesh().coord(centre, 1))
                    + sq(m.mesh().coord(v, 2) - m.mesh().coord(centre, 2)));
            assertEquals(d <= r ? VertexLabel.TENDON : before[v], after[v], "vertex " + v + " at " + d + " m");
            painted += before[v] != VertexLabel.TENDON && d <= r ? 1 : 0;
        }
        assertTrue(painted > 2, "the stroke turned some muscle into tendon: " + painted);
        Path file = dir.resolve("painted.labels");
        VertexLabelsFile.write(file, after);
        f.paintLabels(after, file);
        assertEquals(file, f.spec().mesh().labels());
        DiaphragmScene again = ((DiaphragmViewScene) f.create(true, Map.of())).scene();
        for (int v = 0; v < after.length; v++) {
            assertEquals(after[v] == VertexLabel.TENDON, again.isTendon(v), "vertex " + v);
        }
        assertTrue(again.tendonAreaFraction() > s.tendonAreaFraction(), again.tendonAreaFraction() + " against "
                + s.tendonAreaFraction());
    }

    private static double sq(double v) {
        return v * v;
    }
}

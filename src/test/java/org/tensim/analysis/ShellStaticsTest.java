package org.tensim.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tensim.scene.diaphragm.TissueModel;
import org.tensim.scene.shell.ShellMaterial;

/**
 * The shell's known answers on small meshes: the patch test (uniform stretch sigma / E) and the
 * clamped circular plate (Kirchhoff's w0 = p a^4 / (64 D)). Figures at the diaphragm's resolutions:
 * {@code ./tensim accuracy}, docs/diaphragm.md.
 */
class ShellStaticsTest {
    private static final ShellMaterial MUSCLE = new ShellMaterial(40e3, 1.0 / 3, 0.0025, 1060);

    @Test
    void patchTestGivesTheUniformStretchOnRegularMeshesOfEverySize() {
        for (FlatMeshes.Pattern p : List.of(FlatMeshes.Pattern.EQUILATERAL, FlatMeshes.Pattern.RIGHT)) {
            for (int cells : new int[] {6, 10}) {
                ShellStatics.Case c = ShellStatics.patch(MUSCLE, TissueModel.MATERIAL, p, cells, 0.1, 0.05, 100);
                assertTrue(c.relativeError() < 0.01, p + " " + cells + " cells: stretch " + c.measured()
                        + " against sigma / E = " + c.exact());
            }
        }
    }

    @Test
    void clampedPlateApproachesKirchhoffAndConvergesWithRefinement() {
        List<ShellStatics.Case> cases = new ArrayList<>();
        for (int rings : new int[] {4, 6, 9}) {
            cases.add(ShellStatics.plate(MUSCLE, TissueModel.MATERIAL, rings, 0.06, 1));
        }
        for (ShellStatics.Case c : cases) {
            assertEquals(c.exact(), c.measured(), 0.1 * c.exact(), "h = " + c.elementSizeM() + " m");
        }
        // Successive refinements change the deflection less and less (a converging sequence).
        double d1 = Math.abs(cases.get(1).measured() - cases.get(0).measured());
        double d2 = Math.abs(cases.get(2).measured() - cases.get(1).measured());
        assertTrue(d2 < d1, "changes " + d1 + " then " + d2);
        // The paper's two faces, each with half the membrane, plus its folding springs: far too stiff in bending.
        ShellStatics.Case paper = ShellStatics.plate(MUSCLE, TissueModel.PAPER, 6, 0.06, 1);
        assertTrue(paper.measured() < 0.4 * paper.exact(), "paper model: w0 = " + paper.measured()
                + " against Kirchhoff " + paper.exact());
    }
}

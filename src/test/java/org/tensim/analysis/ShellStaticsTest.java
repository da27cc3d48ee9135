package org.tensim.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tensim.scene.shell.ShellMaterial;
import org.tensim.scene.shell.TissueModel;

/**
 * The shell's known answers on small meshes: the patch test (uniform stretch sigma / E) and the
 * clamped circular plate (Kirchhoff's w0 = p a^4 / (64 D), and Mindlin's with the shear term). Figures at the diaphragm's resolutions:
 * {@code ./tensim accuracy}, docs/diaphragm.md.
 */
class ShellStaticsTest {
    private static final ShellMaterial MUSCLE = new ShellMaterial(40e3, 1.0 / 3, 0.0025, 1060);

    @Test
    void patchTestGivesTheUniformStretchOnEveryMeshAndEveryPoissonRatio() {
        for (double nu : new double[] {1.0 / 3, 0.45}) {
            for (FlatMeshes.Pattern p : FlatMeshes.Pattern.values()) {
                for (int cells : new int[] {6, 10}) {
                    ShellStatics.Case c = ShellStatics.patch(MUSCLE.withPoisson(nu), TissueModel.MATERIAL, p, cells,
                            0.1, 0.05, 100);
                    assertTrue(c.relativeError() < 0.01, "nu " + nu + ", " + p + " " + cells + " cells: stretch "
                            + c.measured() + " against sigma / E = " + c.exact());
                }
            }
        }
        // Edge springs alone (Van Gelder) are not exact on distorted triangles.
        ShellStatics.Case springs = ShellStatics.patch(MUSCLE, TissueModel.SPRINGS, FlatMeshes.Pattern.JITTERED, 10,
                0.1, 0.05, 100);
        assertTrue(springs.relativeError() > 0.03, "edge springs on a jittered mesh: " + springs.relativeError());
    }

    @Test
    void clampedPlateConvergesToMindlinAndIsWithinOnePercentOfKirchhoffAtTwentyRings() {
        double radius = ShellStudy.PLATE_RADIUS_M;
        double mindlin = ShellStatics.mindlinPlate(MUSCLE, radius, 1);
        List<ShellStatics.Case> cases = new ArrayList<>();
        for (int rings : new int[] {10, 14, 20}) {
            ShellStatics.Case c = ShellStatics.plate(MUSCLE, TissueModel.MATERIAL, rings, radius, 1);
            cases.add(new ShellStatics.Case(c.elementSizeM(), c.nodes(), c.measured(), mindlin, 0, c.iterations()));
            // The transverse shear elements: no coarse plate softer than the physical (Mindlin) one.
            assertTrue(c.measured() < mindlin * 1.001, rings + " rings: w0 " + c.measured() + " against Mindlin "
                    + mindlin);
        }
        for (int i = 1; i < cases.size(); i++) {
            assertTrue(cases.get(i).relativeError() < cases.get(i - 1).relativeError(), "error falls with h: "
                    + cases.get(i - 1).relativeError() + " then " + cases.get(i).relativeError());
        }
        double order = ShellStatics.order(cases);
        assertTrue(order > 2 && order < 4, "order " + order);
        double kirchhoff = ShellStatics.plate(MUSCLE, TissueModel.MATERIAL, 20, radius, 1).exact();
        assertEquals(kirchhoff, cases.get(2).measured(), 0.01 * kirchhoff, "20 rings against Kirchhoff");
        // The paper's two faces, each with half the membrane, plus its folding springs: far too stiff in bending.
        ShellStatics.Case paper = ShellStatics.plate(MUSCLE, TissueModel.PAPER, 6, 0.06, 1);
        assertTrue(paper.measured() < 0.4 * paper.exact(), "paper model: w0 = " + paper.measured()
                + " against Kirchhoff " + paper.exact());
    }
}

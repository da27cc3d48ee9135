package org.tensim.analysis;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import org.tensim.scene.shell.ShellMaterial;
import org.tensim.scene.shell.TissueModel;

/**
 * The shell's static accuracy against element size, for a tissue model: the patch test on three
 * triangulations of a 100 x 50 mm membrane, and the clamped circular plate of radius 120 mm (the
 * double dome's transverse semi-axis, so that n rings have the double dome's element size at n
 * rings). Material: the diaphragm muscle's E = 40 kPa, t = 2.5 mm and nu = 0.45 (the diaphragm's
 * default; the edge-spring model, whose network has nu = 1/3 whatever the material's, is thereby
 * measured against the material it is meant to represent).
 */
public final class ShellStudy {
    /** The material of the study. */
    public static final ShellMaterial MATERIAL = new ShellMaterial(40e3, 0.45, 0.0025, 1060);
    /** Plate radius, m. */
    public static final double PLATE_RADIUS_M = 0.120;
    /** Default ring counts of the plate (43: the default diaphragm's). */
    public static final int[] PLATE_RINGS = {6, 10, 14, 20, 28, 43};
    /** Elements along the patch. */
    public static final int[] PATCH_CELLS = {8, 16, 32};

    /**
     * @param patch       patch-test cases by triangulation, coarsest first
     * @param plate       plate cases, coarsest first
     * @param plateOrder  slope of log(error against Kirchhoff) over log(h)
     * @param selfOrder   slope of log|w(h) - w(h_next)| over log(h): the order at which the deflection settles
     */
    public record Result(TissueModel model, Map<FlatMeshes.Pattern, List<ShellStatics.Case>> patch,
            List<ShellStatics.Case> plate, double plateOrder, double selfOrder) {
    }

    private ShellStudy() {
    }

    /** Runs the study, reporting each case through {@code log}. */
    public static Result run(TissueModel model, int[] plateRings, Consumer<String> log) {
        Map<FlatMeshes.Pattern, List<ShellStatics.Case>> patch = new LinkedHashMap<>();
        for (FlatMeshes.Pattern p : FlatMeshes.Pattern.values()) {
            List<ShellStatics.Case> cases = new ArrayList<>();
            for (int cells : PATCH_CELLS) {
                ShellStatics.Case c = ShellStatics.patch(MATERIAL, model, p, cells, 0.1, 0.05, 100);
                cases.add(c);
                log.accept(String.format("patch %-11s h %.2f mm: stretch %.5e, sigma/E %.5e, error %.2f %%, "
                        + "largest element deviation %.1f %%", p.name().toLowerCase(), 1e3 * c.elementSizeM(),
                        c.measured(), c.exact(), 100 * c.relativeError(), 100 * c.spread()));
            }
            patch.put(p, cases);
        }
        List<ShellStatics.Case> plate = new ArrayList<>();
        for (int rings : plateRings) {
            ShellStatics.Case c = ShellStatics.plate(MATERIAL, model, rings, PLATE_RADIUS_M, 1);
            plate.add(c);
            log.accept(String.format("plate %2d rings, h %.2f mm: w0 %.5e m, Kirchhoff %.5e m, error %.2f %% (%d CG "
                    + "iterations)", rings, 1e3 * c.elementSizeM(), c.measured(), c.exact(), 100 * c.relativeError(),
                    c.iterations()));
        }
        List<ShellStatics.Case> steps = new ArrayList<>();
        for (int i = 0; i + 1 < plate.size(); i++) {
            ShellStatics.Case a = plate.get(i);
            double change = Math.abs(a.measured() - plate.get(i + 1).measured());
            steps.add(new ShellStatics.Case(a.elementSizeM(), a.nodes(), a.exact() + change, a.exact(), 0, 0));
        }
        return new Result(model, patch, plate, ShellStatics.order(plate), ShellStatics.order(steps));
    }
}

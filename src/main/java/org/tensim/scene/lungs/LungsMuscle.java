package org.tensim.scene.lungs;

import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.DiaphragmSpec;

/**
 * The muscle's default active fibre stress with the lungs in place.
 *
 * <p>The thorax scene's default, {@code DiaphragmSetup.DEFAULT_FIBRE_STRESS_PA} (19 kPa), was fitted on the
 * diaphragm alone, whose load is its own tissue, the abdominal pressure and the apposition pressure. With the lungs in
 * the cavity the muscle also carries their elastic recoil: the lungs must expand with the pleura, and their bulk
 * modulus {@code E / (3 (1 - 2 nu))}, 1.7 kPa at the parenchyma's E 1 kPa and nu 0.4, matches quiet breathing's lung
 * compliance (about 0.2 L/cmH2O for about 3 L: a bulk stiffness of about 1.5 kPa). At 19 kPa the domes then descend
 * 6.3 / 9.9 mm, below the thorax scene's 9-19 / 10-20 mm (docs/lungs.md, "Why the lungs hold the domes back"). The
 * recoil is a real load of the inspiratory muscles, so the muscle's stress is raised to carry it, not the lungs
 * softened: {@link #FIBRE_STRESS_PA}, measured on the thorax with the lungs (docs/lungs.md, "The muscle with the lungs
 * in place").
 */
public final class LungsMuscle {
    /**
     * The default peak active fibre stress with the lungs in place, Pa: 36 kPa, the stress at which the two domes'
     * mean descent is the middle of the thorax scene's ranges (9-19 and 10-20 mm: 14.5 mm) with the lungs in place
     * (docs/lungs.md, "The muscle with the lungs in place"). A sixth or less of skeletal muscle's maximal active
     * stress (of the order of 200-300 kPa).
     */
    public static final double FIBRE_STRESS_PA = 36_000;

    private LungsMuscle() {
    }

    /**
     * The muscle action a view's controls start at with the lungs in place, Pa: {@link #FIBRE_STRESS_PA} under the
     * fibres' active tension, null under the pressure loads (their own default: not measured with the lungs).
     */
    public static Double startingPa(BoundaryConditions.MuscleLoad load) {
        return load == BoundaryConditions.MuscleLoad.FIBRES ? FIBRE_STRESS_PA : null;
    }

    /**
     * The spec with the lungs' default muscle action where the spec leaves the muscle action to its load's default
     * and the load is the fibres' active tension; any other spec unchanged (a muscle action given is the user's, and
     * the pressure loads were not measured with the lungs).
     */
    public static DiaphragmSpec applyTo(DiaphragmSpec spec) {
        Double pa = startingPa(spec.boundary().muscleLoad());
        return spec.breathing().musclePa() != null || pa == null ? spec
                : spec.withBreathing(spec.breathing().withMusclePa(pa));
    }
}

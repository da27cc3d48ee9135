package org.tensim.scene.diaphragm;

import org.tensim.model.Check;
import org.tensim.model.Vec3;
import org.tensim.scene.shell.TissueModel;

/**
 * Tissue, structure and attachment parameters of the diaphragm scene, SI units.
 * Sources and the reasons for each default are in {@code docs/diaphragm.md}.
 *
 * @param densityKgPerM3       tissue density, kg/m^3 (soft tissue about 1060)
 * @param muscleYoungPa        Young's modulus of the muscle, Pa (resting diaphragm: shear modulus of some
 *                             10-15 kPa by shear-wave elastography, E = 3 mu about 30-45 kPa)
 * @param tendonYoungPa        Young's modulus given to the tendon's springs, Pa (see docs: the real central
 *                             tendon is far stiffer; its rigidity comes from the rigid links)
 * @param highDampingRatio     damping ratio of the highest mode from axial (stiffness-proportional) spring damping
 * @param viscousPerS          global viscous damping per unit mass, 1/s (surrounding organs; c = this times the
 *                             mean node mass)
 * @param tendonAreaFraction   share of the upper surface's area given to the tendon, used to place the
 *                             separating plane along its normal when no point is given (adults: 0.10-0.15)
 * @param tendonNormal         normal of the muscle/tendon plane; the tendon is on the side it points to
 * @param tendonPoint          a point of the plane, m; null to place the plane by {@code tendonAreaFraction}
 * @param attachThresholdM     diaphragm nodes closer than this to ribs, cartilage or sternum are attached, m
 * @param structureStiffness   stiffness of the sternum and cartilage springs, N/m ("very low elasticity")
 * @param structureNodeMassKg  mass of each sternum node, kg
 * @param attachStiffness      stiffness of a spring tying a diaphragm node to cartilage or sternum, N/m
 * @param ribQuietFraction     quiet-breathing rib rotation as a fraction of the rotation from relaxed
 *                             expiration to full inspiration measured by Wilson et al. (1987)
 * @param ribTranslationM      translation of each rib along its helical axis at end-inspiration, m
 * @param abdominalSupportPaPerM stiffness per unit area of the abdominal contents under the diaphragm, Pa/m
 *                             (an elastic foundation: each free node of the lower surface is tied to its rest
 *                             position by a spring of stiffness K A_i); 0 turns it off
 * @param bendingFactor        stiffness of the bending springs (across each edge, between the opposite
 *                             vertices) relative to the membrane formula, in the paper's tissue model only;
 *                             0 turns them off
 * @param poissonRatio         Poisson's ratio of muscle and tendon, in (-1, 0.5) (soft tissue 0.45-0.49); sets the
 *                             faces' share of the membrane in the material model
 * @param tissueModel          how the springs are derived from the tissue ({@link TissueModel})
 */
public record DiaphragmParameters(double densityKgPerM3, double muscleYoungPa, double tendonYoungPa,
        double highDampingRatio, double viscousPerS, double tendonAreaFraction, Vec3 tendonNormal, Vec3 tendonPoint,
        double attachThresholdM, double structureStiffness, double structureNodeMassKg, double attachStiffness,
        double ribQuietFraction, double ribTranslationM, double abdominalSupportPaPerM, double bendingFactor,
        double poissonRatio, TissueModel tissueModel) {
    public DiaphragmParameters {
        Check.positive("tissue density", "kg/m^3", densityKgPerM3);
        Check.positive("muscle Young's modulus", "Pa", muscleYoungPa);
        Check.positive("tendon Young's modulus", "Pa", tendonYoungPa);
        Check.positive("high-mode damping ratio", "", highDampingRatio);
        if (highDampingRatio > 1) {
            throw new IllegalArgumentException("high-mode damping ratio must be in (0, 1], got " + highDampingRatio);
        }
        Check.nonNegative("viscous damping per unit mass", "1/s", viscousPerS);
        if (!(tendonAreaFraction > 0 && tendonAreaFraction < 1)) {
            throw new IllegalArgumentException("tendon area fraction must be in (0, 1), got " + tendonAreaFraction);
        }
        if (tendonNormal == null) {
            throw new IllegalArgumentException("tendon plane normal must not be null");
        }
        tendonNormal = tendonNormal.normalized();
        Check.positive("attachment threshold", "m", attachThresholdM);
        Check.positive("sternum and cartilage stiffness", "N/m", structureStiffness);
        Check.positive("sternum node mass", "kg", structureNodeMassKg);
        Check.positive("attachment spring stiffness", "N/m", attachStiffness);
        Check.nonNegative("quiet-breathing rib fraction", "", ribQuietFraction);
        Check.finite("rib translation", "m", ribTranslationM);
        Check.nonNegative("abdominal support stiffness", "Pa/m", abdominalSupportPaPerM);
        Check.nonNegative("bending spring factor", "", bendingFactor);
        if (!(poissonRatio > -1 && poissonRatio < 0.5)) {
            throw new IllegalArgumentException("Poisson's ratio nu must be in (-1, 0.5) (dimensionless), got "
                    + poissonRatio);
        }
        if (tissueModel == null) {
            throw new IllegalArgumentException("tissue model must be material, springs or paper, got null");
        }
    }

    /**
     * Default stiffness per unit area of the abdominal support, Pa/m: without it the dome snaps through under the
     * muscle's load (docs/diaphragm.md, "Parameters"); how it moves the thorax's answer: docs/thorax.md, "Resolution".
     */
    public static final double DEFAULT_ABDOMINAL_SUPPORT_PA_PER_M = 50e3;

    /** The defaults (docs/diaphragm.md). */
    public static DiaphragmParameters defaults() {
        return new DiaphragmParameters(1060, 40e3, 160e3, 0.9, 60, 0.12, new Vec3(0, 0, 1), null, 0.020, 2e5,
                0.02, 100, 0.3, 0.0005, DEFAULT_ABDOMINAL_SUPPORT_PA_PER_M, 1, 0.45, TissueModel.MATERIAL);
    }

    public DiaphragmParameters withAttachThreshold(double m) {
        return new DiaphragmParameters(densityKgPerM3, muscleYoungPa, tendonYoungPa, highDampingRatio, viscousPerS,
                tendonAreaFraction, tendonNormal, tendonPoint, m, structureStiffness, structureNodeMassKg,
                attachStiffness, ribQuietFraction, ribTranslationM, abdominalSupportPaPerM,
                bendingFactor, poissonRatio, tissueModel);
    }

    public DiaphragmParameters withDamping(double zetaHigh, double viscousPerS) {
        return new DiaphragmParameters(densityKgPerM3, muscleYoungPa, tendonYoungPa, zetaHigh, viscousPerS,
                tendonAreaFraction, tendonNormal, tendonPoint, attachThresholdM, structureStiffness,
                structureNodeMassKg, attachStiffness, ribQuietFraction, ribTranslationM, abdominalSupportPaPerM,
                bendingFactor, poissonRatio, tissueModel);
    }

    public DiaphragmParameters withViscous(double perS) {
        return new DiaphragmParameters(densityKgPerM3, muscleYoungPa, tendonYoungPa, highDampingRatio, perS,
                tendonAreaFraction, tendonNormal, tendonPoint, attachThresholdM, structureStiffness,
                structureNodeMassKg, attachStiffness, ribQuietFraction, ribTranslationM, abdominalSupportPaPerM,
                bendingFactor, poissonRatio, tissueModel);
    }

    public DiaphragmParameters withTendonPlane(Vec3 normal, Vec3 point) {
        return new DiaphragmParameters(densityKgPerM3, muscleYoungPa, tendonYoungPa, highDampingRatio, viscousPerS,
                tendonAreaFraction, normal, point, attachThresholdM, structureStiffness, structureNodeMassKg,
                attachStiffness, ribQuietFraction, ribTranslationM, abdominalSupportPaPerM,
                bendingFactor, poissonRatio, tissueModel);
    }

    public DiaphragmParameters withAbdominalSupport(double paPerM) {
        return new DiaphragmParameters(densityKgPerM3, muscleYoungPa, tendonYoungPa, highDampingRatio, viscousPerS,
                tendonAreaFraction, tendonNormal, tendonPoint, attachThresholdM, structureStiffness,
                structureNodeMassKg, attachStiffness, ribQuietFraction, ribTranslationM, paPerM,
                bendingFactor, poissonRatio, tissueModel);
    }

    /** The same parameters with another tendon area fraction (places the plane when no point is given). */
    public DiaphragmParameters withTendonAreaFraction(double fraction) {
        return new DiaphragmParameters(densityKgPerM3, muscleYoungPa, tendonYoungPa, highDampingRatio, viscousPerS,
                fraction, tendonNormal, tendonPoint, attachThresholdM, structureStiffness, structureNodeMassKg,
                attachStiffness, ribQuietFraction, ribTranslationM, abdominalSupportPaPerM,
                bendingFactor, poissonRatio, tissueModel);
    }

    /** The same parameters with another sternum node mass, kg. */
    public DiaphragmParameters withStructureNodeMass(double kg) {
        return new DiaphragmParameters(densityKgPerM3, muscleYoungPa, tendonYoungPa, highDampingRatio, viscousPerS,
                tendonAreaFraction, tendonNormal, tendonPoint, attachThresholdM, structureStiffness, kg,
                attachStiffness, ribQuietFraction, ribTranslationM, abdominalSupportPaPerM,
                bendingFactor, poissonRatio, tissueModel);
    }

    public DiaphragmParameters withMuscleYoung(double pa) {
        return new DiaphragmParameters(densityKgPerM3, pa, tendonYoungPa, highDampingRatio, viscousPerS,
                tendonAreaFraction, tendonNormal, tendonPoint, attachThresholdM, structureStiffness,
                structureNodeMassKg, attachStiffness, ribQuietFraction, ribTranslationM, abdominalSupportPaPerM,
                bendingFactor, poissonRatio, tissueModel);
    }

    /** The same parameters with another tissue model. */
    public DiaphragmParameters withTissueModel(TissueModel model) {
        return new DiaphragmParameters(densityKgPerM3, muscleYoungPa, tendonYoungPa, highDampingRatio, viscousPerS,
                tendonAreaFraction, tendonNormal, tendonPoint, attachThresholdM, structureStiffness,
                structureNodeMassKg, attachStiffness, ribQuietFraction, ribTranslationM, abdominalSupportPaPerM,
                bendingFactor, poissonRatio, model);
    }

    /** The same parameters with the muscle's Young's modulus, Pa, and the tendon's scaled to keep its ratio to it. */
    public DiaphragmParameters withTissueYoung(double musclePa) {
        Check.positive("muscle Young's modulus", "Pa", musclePa);
        return withMuscleYoung(musclePa).withTendonYoung(tendonYoungPa * musclePa / muscleYoungPa);
    }

    public DiaphragmParameters withTendonYoung(double pa) {
        return new DiaphragmParameters(densityKgPerM3, muscleYoungPa, pa, highDampingRatio, viscousPerS,
                tendonAreaFraction, tendonNormal, tendonPoint, attachThresholdM, structureStiffness,
                structureNodeMassKg, attachStiffness, ribQuietFraction, ribTranslationM, abdominalSupportPaPerM, bendingFactor,
                poissonRatio, tissueModel);
    }
}

package org.tensim.scene.diaphragm;

import java.nio.file.Path;
import java.util.List;
import org.tensim.io.mesh.MeshCleaner;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.model.Check;
import org.tensim.scene.shell.TissueModel;

/**
 * The one definition of a diaphragm scene: every input, grouped, with named defaults
 * ({@link #defaults()}), built by one function ({@link DiaphragmSetup#build}). The command
 * line, the GUI and the specs of sweeps and calibrations all fill one of these; a built scene
 * keeps it ({@link DiaphragmScene#spec()}), so a rebuild changes only what was changed.
 *
 * @param mesh        where the diaphragm's surfaces come from
 * @param tissue      tissue, tendon plane and structure parameters ({@link DiaphragmParameters})
 * @param boundary    attachment and muscle-load models ({@link BoundaryConditions})
 * @param breathing   the breathing cycle and the two live controls' starting values
 * @param cage        the bones: the parametric cage, BodyParts3D's boxes, or a thorax of bone surfaces
 * @param actionLines the muscle's action lines (pressure and paper-nodes loads); null for one through each dome
 * @param tendonRule  how the tendon is found without a label file (null: {@link #DEFAULT_TENDON_RULE})
 */
public record DiaphragmSpec(Mesh mesh, DiaphragmParameters tissue, BoundaryConditions boundary,
        Breathing breathing, Cage cage, List<ActionLines.Line> actionLines, TendonRule tendonRule) {

    /** Rings per face of the generated double dome at the paper's resolution (11,354 nodes). */
    public static final int PAPER_RINGS = 43;
    /**
     * How the tendon is found without a label file, by default: grown along the surface around the dome tops
     * ({@link TendonRule#GEODESIC}), central as the real trefoil is whichever dome stands higher. The paper's plane
     * cut ({@link #paper()} keeps it) puts the tendon on the higher dome of a real, asymmetric diaphragm
     * (docs/thorax.md, "Where the tendon lies").
     */
    public static final TendonRule DEFAULT_TENDON_RULE = TendonRule.GEODESIC;
    /** Thickness given to a single-surface mesh, m (the diaphragm's muscle: 2-4 mm). */
    public static final double DEFAULT_OFFSET_THICKNESS_M = 0.0025;

    public DiaphragmSpec {
        if (mesh == null || tissue == null || boundary == null || breathing == null || cage == null) {
            throw new IllegalArgumentException("a diaphragm spec needs its mesh, tissue, boundary, breathing and cage"
                    + " groups (use DiaphragmSpec.defaults() and its with... methods)");
        }
        actionLines = actionLines == null || actionLines.isEmpty() ? null : List.copyOf(actionLines);
        tendonRule = tendonRule == null ? DEFAULT_TENDON_RULE : tendonRule;
        if (actionLines != null && boundary.muscleLoad() == BoundaryConditions.MuscleLoad.FIBRES) {
            throw new IllegalArgumentException("action lines place the traction of the muscle loads pressure and"
                    + " paper-nodes; the muscle load 'fibres' (the active fibre tension) has none");
        }
    }

    /**
     * The diaphragm's mesh: the project's generated double dome at {@code rings} (when {@code file} is null)
     * or a file, read in {@code units}, cleaned, split into its two faces or offset by the thickness.
     *
     * @param file             OBJ, STL or OFF; null for the generated double dome
     * @param rings            rings per face of the generated double dome (4 or more)
     * @param units            units of the file
     * @param cleaning         welding and small-piece settings of the mesh cleaner
     * @param offsetThicknessM thickness given to a single-surface mesh, m
     * @param labels           a per-vertex label file (tendon, muscle, origins); null to derive the labels by rule
     */
    public record Mesh(Path file, int rings, MeshUnits units, MeshCleaner.Options cleaning, double offsetThicknessM,
            Path labels) {
        public Mesh {
            if (rings < 4) {
                throw new IllegalArgumentException("rings per face of the double dome must be 4 or more, got " + rings);
            }
            if (units == null || cleaning == null) {
                throw new IllegalArgumentException("mesh units and cleaning options must be given");
            }
            Check.positive("single-surface mesh thickness", "m", offsetThicknessM);
        }

        /** The generated double dome at the paper's resolution. */
        public static Mesh defaults() {
            return new Mesh(null, PAPER_RINGS, MeshUnits.parse("mm"), MeshCleaner.Options.defaults(),
                    DEFAULT_OFFSET_THICKNESS_M, null);
        }

        public Mesh withFile(Path f, MeshUnits u) {
            return new Mesh(f, rings, u, cleaning, offsetThicknessM, labels);
        }

        public Mesh withRings(int r) {
            return new Mesh(file, r, units, cleaning, offsetThicknessM, labels);
        }

        public Mesh withCleaning(MeshCleaner.Options c) {
            return new Mesh(file, rings, units, c, offsetThicknessM, labels);
        }

        public Mesh withOffsetThickness(double m) {
            return new Mesh(file, rings, units, cleaning, m, labels);
        }

        public Mesh withLabels(Path l) {
            return new Mesh(file, rings, units, cleaning, offsetThicknessM, l);
        }

        /** Whether the mesh is the generated double dome. */
        public boolean generated() {
            return file == null;
        }

        /** What the mesh is, for summaries. */
        public String describe() {
            return file == null ? "generated double dome, " + rings + " rings" : file.toString();
        }
    }

    /**
     * The breathing cycle and the starting values of the two live controls ({@link DiaphragmControls}).
     *
     * @param periodS         breathing period, s
     * @param expirationRatio r in I:E = 1:r
     * @param ribAmplitude    factor on the quiet-breathing rib rotations, 0..3
     * @param musclePa        peak muscle action, Pa (active fibre stress or pressure); null for the muscle load's
     *                        default ({@link DiaphragmSetup#defaultMusclePa})
     * @param abdominalPressurePa rise of the abdominal pressure on the diaphragm's lower face at end-inspiration, Pa
     *                        (&gt;= 0; 0: none, the default): it follows the breathing level and presses the zone of
     *                        apposition on the chest wall ({@link AbdominalPressure}; docs/thorax.md)
     * @param pauseShare      the end-expiratory pause, a share of the expiration in [0, 1) ({@link BreathingCycle};
     *                        default {@link BreathingCycle#QUIET_PAUSE_SHARE})
     */
    public record Breathing(double periodS, double expirationRatio, double ribAmplitude, Double musclePa,
            double abdominalPressurePa, double pauseShare) {
        /** Most abdominal pressure rise accepted, Pa (about 50 cmH2O, a maximal expulsive effort's order). */
        public static final double MAX_ABDOMINAL_PRESSURE_PA = 5000;

        public Breathing {
            new BreathingCycle(periodS, expirationRatio, pauseShare); // validates
            new DiaphragmControls(ribAmplitude, musclePa == null ? 0 : musclePa); // validates
            if (!(abdominalPressurePa >= 0 && abdominalPressurePa <= MAX_ABDOMINAL_PRESSURE_PA)) {
                throw new IllegalArgumentException("abdominal pressure rise must be 0.." + MAX_ABDOMINAL_PRESSURE_PA
                        + " Pa, got " + abdominalPressurePa);
            }
        }

        /** With the quiet law's end-expiratory pause ({@link BreathingCycle#QUIET_PAUSE_SHARE}). */
        public Breathing(double periodS, double expirationRatio, double ribAmplitude, Double musclePa,
                double abdominalPressurePa) {
            this(periodS, expirationRatio, ribAmplitude, musclePa, abdominalPressurePa,
                    BreathingCycle.QUIET_PAUSE_SHARE);
        }

        /** Without an abdominal pressure rise, with the quiet law's end-expiratory pause. */
        public Breathing(double periodS, double expirationRatio, double ribAmplitude, Double musclePa) {
            this(periodS, expirationRatio, ribAmplitude, musclePa, 0);
        }

        /**
         * Quiet breathing: 4 s, I:E 1:2 with the end-expiratory pause, the quiet rib motion and the load's default
         * muscle action.
         */
        public static Breathing defaults() {
            return new Breathing(4, 2, 1, null);
        }

        public BreathingCycle cycle() {
            return new BreathingCycle(periodS, expirationRatio, pauseShare);
        }

        public Breathing withPeriod(double s) {
            return new Breathing(s, expirationRatio, ribAmplitude, musclePa, abdominalPressurePa, pauseShare);
        }

        public Breathing withExpirationRatio(double r) {
            return new Breathing(periodS, r, ribAmplitude, musclePa, abdominalPressurePa, pauseShare);
        }

        public Breathing withRibAmplitude(double a) {
            return new Breathing(periodS, expirationRatio, a, musclePa, abdominalPressurePa, pauseShare);
        }

        public Breathing withMusclePa(Double pa) {
            return new Breathing(periodS, expirationRatio, ribAmplitude, pa, abdominalPressurePa, pauseShare);
        }

        public Breathing withAbdominalPressure(double pa) {
            return new Breathing(periodS, expirationRatio, ribAmplitude, musclePa, pa, pauseShare);
        }

        public Breathing withPauseShare(double p) {
            return new Breathing(periodS, expirationRatio, ribAmplitude, musclePa, abdominalPressurePa, p);
        }
    }

    /**
     * The bones the diaphragm is attached to and lies against.
     *
     * @param boxes                rib and sternum boxes (mm, BodyParts3D's form); null for the parametric cage
     * @param thorax               a folder of bone surfaces with a {@code parts.json}; null for none (then the
     *                             cage is the parametric one or the boxes)
     * @param contact              whether the muscle slides on the bones' surfaces (frictionless, one-sided) where
     *                             it is not attached; needs bone surfaces
     * @param contactStiffnessPaPerM penalty stiffness of the contact per unit area of diaphragm, Pa/m
     * @param liverSupportPaPerM   stiffness per unit area of the liver's compliant support under the right
     *                             hemidiaphragm, Pa/m (a thorax with a liver, contact on); 0 turns it off
     * @param surfaces             the parametric cage (or the boxes' cage) as bone surfaces swept along its lines
     *                             ({@code --cage surfaces}): attached at the origins and in contact elsewhere, as in
     *                             a thorax, instead of the attachment band on its segments; a thorax has surfaces
     *                             whatever this says
     * @param appositionPressurePa rise of the abdominal pressure on the zone of apposition at end-inspiration, Pa
     *                             (bone surfaces, contact on; 0 turns it off): it presses the muscle that lies against
     *                             the ribs, cartilages and sternum onto them ({@link AppositionZone}), following the
     *                             breathing level and, as the dome's descent that raises it, the muscle's live action
     *                             (this rise at the muscle load's default amplitude, none with the muscle off)
     */
    public record Cage(Path boxes, Path thorax, boolean contact, double contactStiffnessPaPerM,
            double liverSupportPaPerM, boolean surfaces, double appositionPressurePa) {
        /**
         * Default contact stiffness, Pa/m: twice the attachment band's. A penalty's penetration is the local
         * pressure over it; at the band's 2.5e7 the BodyParts3D diaphragm went 0.78 mm past its start into rib 11
         * at end-inspiration, at 5e7 0.47 mm (docs/thorax.md), inside the 0.5 mm a user can trust, with the
         * same dome descent (10.3 mm right) and the converged bdf2 step unchanged.
         */
        public static final double DEFAULT_CONTACT_PA_PER_M = 5e7;

        /**
         * Default stiffness per unit area of the liver's support under the right hemidiaphragm (a thorax with a
         * liver, contact on), Pa/m: the liver as an elastic layer pressed along its height, a Winkler foundation of
         * modulus {@code E / h}, with E = 5.5 kPa (the healthy liver's Young's modulus by transient elastography:
         * 5.49 +/- 1.59 kPa in 429 subjects, Roulot et al., J Hepatol 48:606, 2008) over h = 0.158 m (the shared
         * thorax's liver from its top under the dome to its lowest point): 3.5e4 Pa/m, on top of the abdominal
         * support's 5e4 under every free node (docs/thorax.md).
         */
        public static final double DEFAULT_LIVER_PA_PER_M = 3.5e4;

        /**
         * Default rise of the abdominal pressure on the zone of apposition at end-inspiration, Pa (about 3 cmH2O):
         * as the dome descends it compresses the abdomen, and the pressure on the muscle's abdominal face holds
         * the zone of apposition on the lower rib cage (De Troyer and Boriek, Compr Physiol 2011). The abdominal
         * support's ties stand for that pressure under the domes; they cannot press the muscle on the wall (they
         * pull each node to its rest point from both sides). The value is chosen, not measured here: with it the
         * BodyParts3D diaphragm's sheet stays on the wall by the costal margins, its half-resolution model comes
         * within 10 % of it, and the left dome still descends more than the right (1 kPa takes the right past the
         * left; docs/thorax.md, "The zone of apposition").
         */
        public static final double DEFAULT_APPOSITION_PA = 300;

        public Cage {
            if (boxes != null && thorax != null) {
                throw new IllegalArgumentException("give rib boxes (--boxes " + boxes + ") or a thorax (--thorax "
                        + thorax + "), not both");
            }
            Check.positive("contact stiffness", "Pa/m", contactStiffnessPaPerM);
            Check.nonNegative("liver support stiffness", "Pa/m", liverSupportPaPerM);
            if (!(appositionPressurePa >= 0 && appositionPressurePa <= Breathing.MAX_ABDOMINAL_PRESSURE_PA)) {
                throw new IllegalArgumentException("abdominal pressure rise on the zone of apposition must be 0.."
                        + Breathing.MAX_ABDOMINAL_PRESSURE_PA + " Pa, got " + appositionPressurePa);
            }
        }

        /** The project's parametric cage, contact on wherever there are bone surfaces. */
        public static Cage defaults() {
            return new Cage(null, null, true, DEFAULT_CONTACT_PA_PER_M, DEFAULT_LIVER_PA_PER_M, false,
                    DEFAULT_APPOSITION_PA);
        }

        public Cage withBoxes(Path b) {
            return new Cage(b, thorax, contact, contactStiffnessPaPerM, liverSupportPaPerM, surfaces,
                    appositionPressurePa);
        }

        public Cage withThorax(Path dir) {
            return new Cage(boxes, dir, contact, contactStiffnessPaPerM, liverSupportPaPerM, surfaces,
                    appositionPressurePa);
        }

        public Cage withContact(boolean on) {
            return new Cage(boxes, thorax, on, contactStiffnessPaPerM, liverSupportPaPerM, surfaces,
                    appositionPressurePa);
        }

        public Cage withContactStiffness(double paPerM) {
            return new Cage(boxes, thorax, contact, paPerM, liverSupportPaPerM, surfaces, appositionPressurePa);
        }

        /** The liver's support stiffness per unit area, Pa/m; 0 turns it off. */
        public Cage withLiverSupport(double paPerM) {
            return new Cage(boxes, thorax, contact, contactStiffnessPaPerM, paPerM, surfaces, appositionPressurePa);
        }

        /** The cage as bone surfaces (true) or as the attachment band's segments (false). */
        public Cage withSurfaces(boolean on) {
            return new Cage(boxes, thorax, contact, contactStiffnessPaPerM, liverSupportPaPerM, on,
                    appositionPressurePa);
        }

        /** The abdominal pressure's rise on the zone of apposition at end-inspiration, Pa; 0 turns it off. */
        public Cage withAppositionPressure(double pa) {
            return new Cage(boxes, thorax, contact, contactStiffnessPaPerM, liverSupportPaPerM, surfaces, pa);
        }

        /** Whether the bones are surfaces: a thorax, or the cage swept into surfaces. */
        public boolean boneSurfaces() {
            return thorax != null || surfaces;
        }

        /** Which cage, for summaries. */
        public String describe() {
            return thorax != null ? "thorax " + thorax
                    : DiaphragmSetup.cage(boxes) + (surfaces ? " as bone surfaces" : "");
        }
    }

    /** The defaults: the generated double dome at the paper's resolution in the parametric cage, quiet breathing. */
    public static DiaphragmSpec defaults() {
        return new DiaphragmSpec(Mesh.defaults(), DiaphragmParameters.defaults(), BoundaryConditions.defaults(),
                Breathing.defaults(), Cage.defaults(), null, DEFAULT_TENDON_RULE);
    }

    /**
     * The paper's model (section 3.2): its tissue springs, attachment by a distance threshold with the nodes
     * driven, and vertical action lines with per-node forces.
     */
    public static DiaphragmSpec paper() {
        DiaphragmSpec d = defaults();
        return d.withTissue(d.tissue().withTissueModel(TissueModel.PAPER)).withBoundary(BoundaryConditions.paper())
                .withCage(d.cage().withContact(false)).withTendonRule(TendonRule.PLANE);
    }

    public DiaphragmSpec withMesh(Mesh m) {
        return new DiaphragmSpec(m, tissue, boundary, breathing, cage, actionLines, tendonRule);
    }

    public DiaphragmSpec withTissue(DiaphragmParameters p) {
        return new DiaphragmSpec(mesh, p, boundary, breathing, cage, actionLines, tendonRule);
    }

    public DiaphragmSpec withBoundary(BoundaryConditions b) {
        return new DiaphragmSpec(mesh, tissue, b, breathing, cage, actionLines, tendonRule);
    }

    public DiaphragmSpec withBreathing(Breathing b) {
        return new DiaphragmSpec(mesh, tissue, boundary, b, cage, actionLines, tendonRule);
    }

    public DiaphragmSpec withCage(Cage c) {
        return new DiaphragmSpec(mesh, tissue, boundary, breathing, c, actionLines, tendonRule);
    }

    public DiaphragmSpec withActionLines(List<ActionLines.Line> l) {
        return new DiaphragmSpec(mesh, tissue, boundary, breathing, cage, l, tendonRule);
    }

    public DiaphragmSpec withTendonRule(TendonRule r) {
        return new DiaphragmSpec(mesh, tissue, boundary, breathing, cage, actionLines, r);
    }

    /** The peak muscle action the scene starts with, Pa: the given one, or the muscle load's default. */
    public double musclePa() {
        return breathing.musclePa() != null ? breathing.musclePa() : DiaphragmSetup.defaultMusclePa(
                boundary.muscleLoad());
    }

    /** New live controls at this spec's starting values. */
    public DiaphragmControls newControls() {
        return new DiaphragmControls(breathing.ribAmplitude(), musclePa());
    }
}

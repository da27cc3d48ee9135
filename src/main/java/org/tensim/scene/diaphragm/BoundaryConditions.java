package org.tensim.scene.diaphragm;

import java.util.Locale;
import org.tensim.model.Check;

/**
 * How the diaphragm is held and loaded: its attachment to ribs, cartilage, sternum and
 * spine, and how the muscle's action reaches the nodes. The paper's choices stay
 * available by name; the defaults are the ones whose totals do not depend on the mesh
 * (docs/diaphragm.md, "Boundary conditions").
 *
 * @param attachment          {@link Attachment#BAND} (default) or the paper's {@link Attachment#PAPER_THRESHOLD}
 * @param bandStiffnessPaPerM band: stiffness per unit area of diaphragm tying it to the cage, Pa/m (N/m per m^2);
 *                            each node in the band gets {@code k_i = k_b A_i / 2 * taper(d_i)} (half per face)
 * @param bandTaperM          band: width over which the tie's stiffness falls smoothly to zero at the band's outer
 *                            edge (the attachment threshold), m; in [0, threshold]
 * @param muscleLoad          active fibre tension {@link MuscleLoad#FIBRES} (default: it converges with the mesh, docs/diaphragm.md,
 *                            "Active fibre tension"), a vertical traction {@link MuscleLoad#PRESSURE} or the paper's
 *                            {@link MuscleLoad#PAPER_NODES}
 * @param costalOriginsOnly   band: attach only to the diaphragm's anatomical origins (ribs 7-12 and their
 *                            cartilages, the xiphoid, the spine) rather than to any cage segment
 */
public record BoundaryConditions(Attachment attachment, double bandStiffnessPaPerM, double bandTaperM,
        MuscleLoad muscleLoad, boolean costalOriginsOnly) {

    /** Default band stiffness, Pa/m (docs/diaphragm.md: boundary layer sqrt(E t / k_b) near 2 mm). */
    public static final double DEFAULT_BAND_PA_PER_M = 2.5e7;
    /**
     * Default taper of the band's outer edge, m: 1 mm, every node held or free; wider tapers (5, 15, 20 mm)
     * made the field depend more on the mesh (docs/history.md, "The diaphragm's boundary conditions").
     */
    public static final double DEFAULT_TAPER_M = 0.001;

    /** How the diaphragm is attached to the cage. */
    public enum Attachment {
        /**
         * The paper's: every node closer than the threshold to a cage segment is driven rigidly with
         * its rib, fixed to the spine, or tied by two springs of fixed stiffness (N/m) to cartilage or
         * sternum. The number of attached nodes, hence the total stiffness, grows with the resolution. The rule is
         * the generic {@link org.tensim.scene.conditions.DistanceAttachment}, as a scene file's attachment condition.
         */
        PAPER_THRESHOLD,
        /**
         * A band of elastic ties with a stiffness per unit area: each node within the threshold is tied
         * by a zero-length spring {@code k_b A_i / 2} (tapered at the band's edge) to its rest point carried
         * by a rib (a driven anchor), to a fixed anchor (spine), or to the ends of a cartilage or sternum
         * segment, shared among the segments within the threshold ({@link AttachmentBand}). The band's
         * total stiffness is {@code k_b} times its area, whatever the mesh.
         */
        BAND
    }

    /** How the action lines' load reaches the nodes. */
    public enum MuscleLoad {
        /** The paper's: each muscle node gets {@code P s(t) w(d_i) A_i / 2} at its own distance d_i. */
        PAPER_NODES,
        /**
         * A traction {@code P s(t) w(d(x))} on the muscle's area (the tendon plane cutting through
         * elements), integrated over each triangle with a 16-point rule and shared among its corners by
         * the linear shape functions (the consistent load vector of a linear element).
         */
        PRESSURE,
        /**
         * Active fibre tension: a membrane tension {@code T = P s(t) t} (P read as an active stress, Pa; t the
         * thickness) along the meridians to the central tendon on every muscle triangle, which pulls the tendon
         * down by tensing the walls instead of pushing on them ({@link MuscleFibres}).
         */
        FIBRES
    }

    public BoundaryConditions {
        if (attachment == null || muscleLoad == null) {
            throw new IllegalArgumentException("attachment model and muscle load model must be given"
                    + " (band or paper-threshold; pressure, paper-nodes or fibres)");
        }
        Check.positive("attachment band stiffness", "Pa/m", bandStiffnessPaPerM);
        Check.nonNegative("attachment band taper", "m", bandTaperM);
    }

    /** The default muscle load's name as on the command line and in sweep specs and presets. */
    public static final String DEFAULT_MUSCLE_LOAD = "fibres";

    /** The defaults: an elastic band on the anatomical origins and the muscle's active fibre tension. */
    public static BoundaryConditions defaults() {
        return new BoundaryConditions(Attachment.BAND, DEFAULT_BAND_PA_PER_M, DEFAULT_TAPER_M, MuscleLoad.FIBRES,
                true);
    }

    /** The paper's: attachment by a distance threshold, muscle forces per node. */
    public static BoundaryConditions paper() {
        return new BoundaryConditions(Attachment.PAPER_THRESHOLD, DEFAULT_BAND_PA_PER_M, DEFAULT_TAPER_M,
                MuscleLoad.PAPER_NODES, false);
    }

    public BoundaryConditions withMuscleLoad(MuscleLoad m) {
        return new BoundaryConditions(attachment, bandStiffnessPaPerM, bandTaperM, m, costalOriginsOnly);
    }

    public BoundaryConditions withBandStiffness(double paPerM) {
        return new BoundaryConditions(attachment, paPerM, bandTaperM, muscleLoad, costalOriginsOnly);
    }

    /** A model's name as on the command line, e.g. "paper-nodes": the inverse of {@link #parse}. */
    public static String name(Enum<?> model) {
        return model.name().toLowerCase(Locale.ROOT).replace('_', '-');
    }

    /** Parses a model name as given on the command line: "band", "paper-threshold", "pressure", "paper-nodes", "fibres". */
    public static <E extends Enum<E>> E parse(Class<E> type, String name) {
        for (E e : type.getEnumConstants()) {
            if (name(e).equals(name)) {
                return e;
            }
        }
        StringBuilder known = new StringBuilder();
        for (E e : type.getEnumConstants()) {
            known.append(known.length() == 0 ? "" : ", ").append(name(e));
        }
        throw new IllegalArgumentException("unknown " + type.getSimpleName() + " model '" + name + "'; expected one of "
                + known);
    }
}

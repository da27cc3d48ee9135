package org.tensim.scene.diaphragm;

import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * The rise of the abdominal pressure on the diaphragm's lower face during inspiration (package-private, called by
 * the scene builder when {@link DiaphragmSpec.Breathing#abdominalPressurePa} is above 0).
 *
 * <p>As the dome descends it compresses the abdominal contents, and the pressure on the muscle's abdominal face
 * rises; in the zone of apposition that pressure acts on the muscle's inner face and holds it on the lower rib
 * cage (De Troyer and Boriek, Compr Physiol 2011, "Mechanics of the respiratory muscles"). The abdominal support's
 * ties ({@link DiaphragmParameters#abdominalSupportPaPerM}) do not press it there: they pull each node back to its
 * rest point, as hard from the wall as towards it (docs/thorax.md, "Is the full mesh converged?").
 *
 * <p>Every free lower-surface node v gets the force {@code f_v(t) = P s(t) A_v d_v} (N): P the pressure rise at
 * end-inspiration (Pa), s(t) the breathing level (0 at end-expiration, 1 at end-inspiration), A_v the node's share
 * of the lower face's area (a third of each lower triangle's, m^2), and d_v the unit vector from v to its partner on
 * the upper face at rest, the face's inward normal across the thickness. The forces sum to P s(t) times the lower
 * face's area projected on each direction. It is a dead load: its direction is the rest one, which the diaphragm's
 * rotations of a few degrees in a quiet breath leave about right (a follower pressure would turn with the face).
 *
 * <p>Two uses: on the whole lower face ({@link DiaphragmSpec.Breathing#abdominalPressurePa}, off by default), and on
 * the zone of apposition only ({@link DiaphragmSpec.Cage#appositionPressurePa}, with bone surfaces), where the rise
 * also follows the muscle's live action.
 */
final class AbdominalPressure {
    private AbdominalPressure() {
    }

    /**
     * Applies the pressure's force laws to the builder's free lower-surface nodes, or to those of them in
     * {@code only}; returns the lower-face area they carry, m^2.
     *
     * @param areaM2 per vertex, its share of its own face's area (a third of each triangle's), m^2
     * @param only   per vertex, whether the pressure acts there (the zone of apposition, {@link AppositionZone});
     *               null: on the whole lower face
     */
    static double add(Topology t, TwoSurfaces surfaces, double[] areaM2, BreathingCycle cycle, double pressurePa,
            boolean[] only) {
        return add(t, surfaces, areaM2, cycle, pressurePa, only, null, 1);
    }

    /**
     * As {@link #add(Topology, TwoSurfaces, double[], BreathingCycle, double, boolean[])}, the pressure scaled by the
     * muscle's live action: {@code P m(t) / m_ref}, with m the muscle amplitude of {@code controls} (read at every
     * evaluation, so a GUI's change takes effect at the next step) and {@code m_ref} the amplitude P was given for.
     * The abdominal pressure rises because the dome descends into the abdomen: with the muscle off there is none.
     *
     * @param controls      the live controls (null: the pressure as given)
     * @param referenceMusclePa the muscle amplitude at which the rise is P, Pa (&gt; 0)
     */
    static double add(Topology t, TwoSurfaces surfaces, double[] areaM2, BreathingCycle cycle, double pressurePa,
            boolean[] only, DiaphragmControls controls, double referenceMusclePa) {
        double pressed = 0;
        for (int v = 0; v < surfaces.mesh().vertexCount(); v++) {
            Node node = t.node(v);
            if (surfaces.isUpper(v) || node.isFixed() || node.isDriven() || only != null && !only[v]) {
                continue;
            }
            Vec3 d = t.node(surfaces.partner(v)).position().minus(node.position());
            double len = Math.sqrt(d.dot(d));
            if (!(len > 0)) {
                continue; // a node on the rim shared by both faces: no thickness to press across
            }
            double scale = pressurePa * areaM2[v] / len;
            double fx = scale * d.x();
            double fy = scale * d.y();
            double fz = scale * d.z();
            t.applyForce(node, (time, f, o) -> {
                double s = cycle.level(time)
                        * (controls == null ? 1 : controls.muscleAmplitudePa() / referenceMusclePa);
                f[o] += fx * s;
                f[o + 1] += fy * s;
                f[o + 2] += fz * s;
            });
            pressed += areaM2[v];
        }
        return pressed;
    }
}

package org.tensim.scene.diaphragm;

import java.util.Map;
import org.tensim.model.Topology;
import org.tensim.scene.shell.TwoSurfaces;
import org.tensim.solver.stability.ModalBounds;

/**
 * What {@link DiaphragmSceneBuilder}'s steps produce: everything a {@link DiaphragmScene} holds.
 *
 * @param parameters         the tissue parameters it was built with
 * @param topology           nodes, springs and rigid links (diaphragm, cage, anchors)
 * @param labels             tissue label per diaphragm node ({@link DiaphragmScene#TENDON}, MUSCLE)
 * @param apex               the apex node (highest upper-surface node)
 * @param actionLines        the muscle's action lines
 * @param attachedToRibs     diaphragm nodes attached to ribs
 * @param attachedToCartilage diaphragm nodes attached to cartilage or sternum
 * @param attachedToSpine    diaphragm nodes attached to the spine
 * @param attached           per diaphragm node: attached to ribs, cartilage, sternum or spine
 * @param modes              bounds on the highest angular frequency, rad/s
 * @param tendonAreaFraction tendon's share of the upper surface's area
 * @param firstAnchor        id of the first anchor node (-1: none)
 * @param addedMassKg        mass added by the mass floor, kg
 * @param appositionAreaM2   lower-face area pressed by the pressure on the zone of apposition, m^2 (0: none)
 */
record DiaphragmParts(DiaphragmParameters parameters, Topology topology, TwoSurfaces surfaces, int[] labels, RibCage cage,
        int apex, DiaphragmControls controls, BreathingCycle cycle, ActionLines actionLines, int attachedToRibs,
        int attachedToCartilage, int attachedToSpine, boolean[] attached, ModalBounds modes,
        double tendonAreaFraction, int firstAnchor, double addedMassKg, Map<String, double[]> attachedPerBone,
        Map<String, Integer> contactPairsPerBone, double appositionAreaM2) {
}

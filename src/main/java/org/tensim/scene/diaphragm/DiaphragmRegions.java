package org.tensim.scene.diaphragm;

import java.util.BitSet;
import java.util.LinkedHashMap;
import java.util.Map;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * The named parts of a built diaphragm, as sets of its nodes, for a scene file's {@code part:} regions: what the
 * scene's builder decided (the tissue labels, the attachment, the apposition zone), not a new rule. Only the
 * diaphragm's own nodes (0 to {@link DiaphragmScene#diaphragmNodes()} - 1), never the cage's or anchors'.
 */
public final class DiaphragmRegions {
    /** The parts' names, in the order {@link #of} gives them. */
    public static final java.util.List<String> NAMES = java.util.List.of("tendon", "muscle", "upper", "lower",
            "attached", "free", "apposition", "apex");

    private DiaphragmRegions() {
    }

    /**
     * The diaphragm's parts: {@code tendon} and {@code muscle} (the labels it was built with: the tendon rule and its
     * share, or a label file), {@code upper} and {@code lower} (the thoracic and abdominal surfaces), {@code attached}
     * (the nodes its attachment ties to the ribs, cartilage, sternum or spine) and {@code free} (the others),
     * {@code apposition} (the lower-surface nodes of the zone of apposition, {@link AppositionZone}; empty without
     * bone surfaces) and {@code apex} (the highest upper-surface node).
     */
    public static Map<String, BitSet> of(DiaphragmScene scene) {
        int n = scene.diaphragmNodes();
        TwoSurfaces s = scene.surfaces();
        Map<String, BitSet> parts = new LinkedHashMap<>();
        for (String name : NAMES) {
            parts.put(name, new BitSet());
        }
        boolean[] apposition = scene.bones() == null ? new boolean[n] : AppositionZone.lowerVertices(s, scene.bones());
        for (int v = 0; v < n; v++) {
            parts.get(scene.isTendon(v) ? "tendon" : "muscle").set(v);
            parts.get(s.isUpper(v) ? "upper" : "lower").set(v);
            parts.get(scene.isAttached(v) ? "attached" : "free").set(v);
            if (apposition[v]) {
                parts.get("apposition").set(v);
            }
        }
        parts.get("apex").set(scene.apexNode());
        return parts;
    }
}

package org.tensim.experiment.diaphragm;

import java.util.LinkedHashMap;
import java.util.Map;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DiaphragmSetup;

/**
 * A diaphragm run's make-up in its summary: source, surfaces, sizes, attachments (per bone in a thorax, with the
 * contact pairs and the apposition zone), tendon share, thickness.
 */
final class SceneMakeUp {
    private SceneMakeUp() {
    }

    /** Puts the scene's make-up into a run's summary. */
    static void describe(Map<String, Object> summary, DiaphragmSetup.Built built) {
        DiaphragmScene scene = built.scene();
        summary.put("source", built.source());
        summary.put("surfaces", built.mode().name().toLowerCase(java.util.Locale.ROOT));
        summary.put("nodes", scene.topology().nodeCount());
        summary.put("diaphragm_nodes", scene.diaphragmNodes());
        summary.put("anchor_nodes", scene.anchorNodes());
        summary.put("springs", scene.topology().springs().size());
        summary.put("membrane_triangles", scene.topology().triangles().size());
        summary.put("shear_elements", scene.topology().shears().size());
        summary.put("rigid_links", scene.topology().rigidLinks().size());
        summary.put("attached_nodes", scene.attachedNodes());
        summary.put("attached_to_ribs", scene.attachedToRibs());
        summary.put("attached_to_cartilage_or_sternum", scene.attachedToCartilage());
        summary.put("attached_to_spine", scene.attachedToSpine());
        summary.put("tendon_area_fraction", DiaphragmReport.round(scene.tendonAreaFraction(), 4));
        if (scene.bones() != null) {
            Map<String, Object> attached = new LinkedHashMap<>();
            double total = 0;
            for (Map.Entry<String, double[]> e : scene.attachedPerBone().entrySet()) {
                attached.put(e.getKey(), Map.of("area_mm2", DiaphragmReport.round(1e6 * e.getValue()[0], 1), "nodes",
                        (int) e.getValue()[1], "node_share", DiaphragmReport.round(e.getValue()[1] / scene.diaphragmNodes(), 4)));
                total += e.getValue()[0];
            }
            summary.put("attached_area_mm2", DiaphragmReport.round(1e6 * total, 1));
            summary.put("attached_per_bone", attached);
            summary.put("diaphragm_area_mm2", DiaphragmReport.round(1e6 * scene.surfaces().mesh().totalArea() / 2, 1));
            summary.put("contact_pairs", scene.topology().contacts().size());
            summary.put("contact_pairs_per_bone", scene.contactPairsPerBone());
            summary.put("apposition_pressure_pa", scene.appositionAreaM2() > 0
                    ? scene.spec().cage().appositionPressurePa() : 0.0);
            summary.put("apposition_area_mm2", DiaphragmReport.round(1e6 * scene.appositionAreaM2(), 1));
        }
        summary.put("thickness_mm", DiaphragmReport.round(1e3 * scene.surfaces().thicknessM(), 3));
    }
}

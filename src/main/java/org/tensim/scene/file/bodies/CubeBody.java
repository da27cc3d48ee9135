package org.tensim.scene.file.bodies;

import java.util.BitSet;
import java.util.List;
import org.tensim.scene.file.BodyContext;
import org.tensim.scene.file.BodyType;
import org.tensim.scene.file.MapReader;
import org.tensim.scene.file.QuantityKind;
import org.tensim.scene.file.SceneException;
import org.tensim.scene.file.ZoneContext;
import org.tensim.model.Topology;
import org.tensim.scene.CubeParameters;
import org.tensim.scene.CubeScene;
import org.tensim.scene.TensegrityElement;

/**
 * {@code type: cube}: the paper's cube (Fig. 3) as {@link CubeScene#addStructure} builds it, with no fixed node
 * and no load (the scene's conditions give them). Keys: {@code side} (length, 10 m), {@code node_mass} (mass,
 * 1 kg), {@code stiffness} (N/m, 100), {@code damping} (N s/m, 2) as in {@link CubeParameters#paper()}, and
 * {@code element}: {@code tensegrity} (the element with its six rigid struts, the default), {@code mass-spring}
 * (the element's nodes and cables without struts) or {@code none} (the eight corners only). Nodes 0-7 are the
 * corners, then the element's twelve in {@link TensegrityElement}'s order. Zones: {@code tensegrity} (see
 * {@link #applyZone}).
 */
public final class CubeBody implements BodyType {
    /** The values of {@code element}. */
    public static final List<String> ELEMENTS = List.of("tensegrity", "mass-spring", "none");
    /** The element's first node: the eight corners come first. */
    static final int FIRST_ELEMENT_NODE = 8;

    @Override
    public String name() {
        return "cube";
    }

    @Override
    public List<String> keys() {
        return List.of("side", "node_mass", "stiffness", "damping", "element");
    }

    /** Spring stiffness and damping change the compiled state's constants only. */
    @Override
    public List<String> liveKeys() {
        return List.of("stiffness", "damping");
    }

    @Override
    public int[] build(BodyContext ctx, Topology t) {
        CubeParameters d = CubeParameters.paper();
        MapReader r = ctx.keys();
        double side = r.positive("side", QuantityKind.LENGTH, ctx.units(), d.sideM());
        double mass = r.positive("node_mass", QuantityKind.MASS, ctx.units(), d.nodeMassKg());
        double k = r.positive("stiffness", QuantityKind.STIFFNESS, ctx.units(), d.stiffnessNPerM());
        double c = r.nonNegative("damping", QuantityKind.DAMPING, ctx.units(), d.dampingNsPerM());
        String element = r.choice("element", ELEMENTS, "tensegrity");
        CubeScene.addStructure(t, side, mass, k, c, !element.equals("none"), element.equals("tensegrity"));
        return null;
    }

    /** A {@code tensegrity} zone makes the struts of a mass-spring element rigid. */
    @Override
    public List<String> zoneModels() {
        return List.of("tensegrity");
    }

    /**
     * Adds, as a rigid link, each of the element's six struts whose two ends are in the zone; the body must be
     * {@code element: mass-spring} (with {@code tensegrity} they are rigid already, with {@code none} there are
     * none). The same links as {@code element: tensegrity}'s, in the same order: the zone over the whole element
     * makes the tensegrity cube.
     */
    @Override
    public void applyZone(ZoneContext zone, Topology t, BitSet nodes) {
        String element = zone.bodyKeys().choice("element", ELEMENTS, "tensegrity");
        if (!element.equals("mass-spring")) {
            throw SceneException.at(zone.node(), "a tensegrity zone of a cube needs element: mass-spring (this cube"
                    + " has element: " + element + ")");
        }
        int added = 0;
        for (int i = 0; i < TensegrityElement.STRUTS; i++) {
            int a = FIRST_ELEMENT_NODE + 2 * i;
            if (nodes.get(a) && nodes.get(a + 1)) {
                t.addRigidLink(t.node(a), t.node(a + 1));
                added++;
            }
        }
        if (added == 0) {
            throw SceneException.at(zone.node(), "the zone holds both ends of none of the element's struts (nodes "
                    + FIRST_ELEMENT_NODE + "-" + (FIRST_ELEMENT_NODE + 11) + ", strut i joining 8 + 2i and 9 + 2i)");
        }
    }
}

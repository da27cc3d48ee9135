package org.tensim.scene.file.bodies;

import java.util.List;
import org.tensim.scene.file.BodyContext;
import org.tensim.scene.file.BodyType;
import org.tensim.scene.file.MapReader;
import org.tensim.scene.file.QuantityKind;
import org.tensim.model.Topology;
import org.tensim.scene.CubeParameters;
import org.tensim.scene.CubeScene;

/**
 * {@code type: cube}: the paper's cube (Fig. 3) as {@link CubeScene#addStructure} builds it, with no fixed node
 * and no load (the scene's conditions give them). Keys: {@code side} (length, 10 m), {@code node_mass} (mass,
 * 1 kg), {@code stiffness} (N/m, 100), {@code damping} (N s/m, 2) as in {@link CubeParameters#paper()}, and
 * {@code element}: {@code tensegrity} (the element with its six rigid struts, the default), {@code mass-spring}
 * (the element's nodes and cables without struts) or {@code none} (the eight corners only). Nodes 0-7 are the
 * corners, then the element's twelve in {@link org.tensim.scene.TensegrityElement}'s order.
 */
public final class CubeBody implements BodyType {
    /** The values of {@code element}. */
    public static final List<String> ELEMENTS = List.of("tensegrity", "mass-spring", "none");

    @Override
    public String name() {
        return "cube";
    }

    @Override
    public List<String> keys() {
        return List.of("side", "node_mass", "stiffness", "damping", "element");
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
}

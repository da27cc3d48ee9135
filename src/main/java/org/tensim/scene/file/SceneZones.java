package org.tensim.scene.file;

import java.util.BitSet;
import java.util.List;
import java.util.Map;

/**
 * Reads a scene's {@code zones:} block: named parts of a body given a model of their own, e.g.
 * <pre>
 * zones:
 *   struts: {body: ts, region: element, model: tensegrity}
 * </pre>
 * {@code body} (required when the scene has more than one), {@code region} (the whole body when absent), {@code model}
 * (one of the body type's {@link BodyType#zoneModels()}) and {@code material} (the type's material keys). Each zone
 * is applied by the body's type ({@link BodyType#applyZone}), in file order.
 */
public final class SceneZones {
    /** The keys of a zone. */
    public static final List<String> KEYS = List.of("body", "region", "model", "material");

    private SceneZones() {
    }

    /** Applies every zone of the block (absent: none). */
    static void apply(SceneNode block, Map<String, SceneBody> bodies, Map<String, SceneRegions.Region> regions,
            SceneUnits u) {
        if (block == null) {
            return;
        }
        if (!block.isMap()) {
            throw SceneException.at(block, "expected a map of named zones, got " + block.describe());
        }
        for (Map.Entry<String, SceneNode> e : block.entries().entrySet()) {
            MapReader r = new MapReader(e.getValue(), KEYS);
            String body;
            if (r.has("body")) {
                body = SceneCheck.bodyName(r.scalar("body"), bodies);
            } else if (bodies.size() == 1) {
                body = bodies.keySet().iterator().next();
            } else {
                throw SceneException.at(r.node(), "missing required key 'body' (the scene has " + bodies.size()
                        + " bodies: " + String.join(", ", bodies.keySet()) + ")");
            }
            SceneBody b = bodies.get(body);
            BodyType type = BodyTypes.get(b.type());
            if (type.zoneModels().isEmpty()) {
                throw SceneException.at(r.node(), "body '" + body + "' (type " + b.type() + ") has no zones");
            }
            r.scalar("model");
            String model = r.choice("model", type.zoneModels(), null);
            BitSet nodes;
            if (r.has("region")) {
                SceneRegions.Region reg = SceneConditions.region(r.scalar("region"), regions);
                nodes = reg.in(body);
                if (nodes == null) {
                    throw SceneException.at(r.node().get("region"), "region '" + reg.name() + "' is not on body '"
                            + body + "'");
                }
            } else {
                nodes = new BitSet();
                nodes.set(0, b.topology().nodeCount());
            }
            MapReader material = r.has("material") ? new MapReader(r.required("material"), type.zoneMaterialKeys())
                    : null;
            List<String> bodyKeys = new java.util.ArrayList<>(type.keys());
            bodyKeys.add(0, "type");
            type.applyZone(new ZoneContext(r.node(), model, material, new MapReader(b.node(), bodyKeys), u),
                    b.topology(), nodes);
        }
    }
}

package org.tensim.scene.file;

import java.util.List;
import java.util.Map;

/**
 * Which key paths of a scene file a running simulation can take a new value of ({@code apply: live} in a
 * {@code parameters:} block): those whose change leaves the compiled state's nodes, springs, rigid links, masses
 * and fixed nodes as they are and changes only constants it holds (spring stiffness and damping, gravity, the
 * applied forces and the motion laws). They are:
 * <ul>
 * <li>a body's keys its type lists in {@link BodyType#liveKeys()} (a cube's {@code stiffness}, a volume's
 * {@code material.E});</li>
 * <li>a zone's {@code material} keys its body's type lists in {@link BodyType#liveZoneMaterialKeys()};</li>
 * <li>a force's {@code magnitude} (or {@code total}) and {@code direction[i]}, gravity's {@code acceleration[i]};</li>
 * <li>a sine law's {@code amplitude}, a ramp's {@code from} and {@code to}.</li>
 * </ul>
 * Everything else (a mesh, a cell size, a region, a density, a time) needs the scene rebuilt.
 */
public final class LiveKeys {
    /** Condition keys that can change live, by condition type. */
    static final Map<String, List<String>> CONDITIONS = Map.of("force", List.of("magnitude", "total", "direction"),
            "gravity", List.of("acceleration"));
    /** Law keys that can change live, by law type. */
    static final Map<String, List<String>> LAWS = Map.of("sine", List.of("amplitude"), "ramp", List.of("from", "to"));

    private LiveKeys() {
    }

    /**
     * Null when the value at {@code path} of the scene's tree can change live, else why not (for a refusal).
     *
     * @param root the scene's tree (the file's, overrides applied)
     */
    static String whyNotLive(SceneNode root, String path) {
        List<Object> steps = Overrides.steps(path, path);
        String rebuild = path + " can only apply on rebuild (it changes what the scene is built of, not a constant"
                + " of the running simulation; ";
        if (steps.size() < 2 || !(steps.get(0) instanceof String top)) {
            return rebuild + "live keys are listed in docs/scenes.md)";
        }
        SceneNode block = root.get(top);
        switch (top) {
            case "bodies": {
                BodyType type = bodyType(block == null ? null : block.get(String.valueOf(steps.get(1))));
                String rest = below(steps, 2);
                if (type != null && type.liveKeys().contains(rest)) {
                    return null;
                }
                return rebuild + "live keys of a " + (type == null ? "body" : type.name() + " body") + ": "
                        + (type == null || type.liveKeys().isEmpty() ? "none" : String.join(", ", type.liveKeys()))
                        + ")";
            }
            case "zones": {
                SceneNode zone = block == null ? null : block.get(String.valueOf(steps.get(1)));
                List<String> live = zoneLiveKeys(root, zone);
                if (steps.size() == 4 && "material".equals(steps.get(2)) && live.contains(steps.get(3))) {
                    return null;
                }
                return rebuild + "live keys of this zone: " + (live.isEmpty() ? "none"
                        : "material." + String.join(", material.", live)) + ")";
            }
            case "conditions":
            case "laws": {
                Map<String, List<String>> table = top.equals("laws") ? LAWS : CONDITIONS;
                SceneNode item = block == null ? null : steps.get(1) instanceof Integer k
                        ? (block.isList() && k < block.items().size() ? block.items().get(k) : null)
                        : block.get(String.valueOf(steps.get(1)));
                SceneNode type = item == null ? null : item.get("type");
                List<String> live = type == null ? List.of() : table.getOrDefault(type.text(), List.of());
                if (steps.size() >= 3 && live.contains(String.valueOf(steps.get(2)))) {
                    return null;
                }
                return rebuild + "live keys of " + (type == null ? "it" : "a " + type.text()) + ": "
                        + (live.isEmpty() ? "none" : String.join(", ", live)) + ")";
            }
            default:
                return rebuild + "live keys are listed in docs/scenes.md)";
        }
    }

    private static List<String> zoneLiveKeys(SceneNode root, SceneNode zone) {
        SceneNode bodies = root.get("bodies");
        if (zone == null || !zone.isMap() || bodies == null || !bodies.isMap()) {
            return List.of();
        }
        SceneNode named = zone.get("body");
        List<String> live = null;
        for (Map.Entry<String, SceneNode> e : bodies.entries().entrySet()) {
            if (named != null && !e.getKey().equals(named.text())) {
                continue;
            }
            BodyType t = bodyType(e.getValue());
            List<String> keys = t == null ? List.of() : t.liveZoneMaterialKeys();
            // A zone without body: may lie on several bodies: only keys every one of them takes live.
            live = live == null ? keys : live.stream().filter(keys::contains).toList();
        }
        return live == null ? List.of() : live;
    }

    private static BodyType bodyType(SceneNode body) {
        SceneNode t = body == null || !body.isMap() ? null : body.get("type");
        return t == null || !t.isScalar() ? null : BodyTypes.get(t.text());
    }

    /** The steps from {@code from} on as a dotted path ("material.E"); list items as [n]. */
    private static String below(List<Object> steps, int from) {
        StringBuilder b = new StringBuilder();
        for (int i = from; i < steps.size(); i++) {
            Object s = steps.get(i);
            if (s instanceof Integer k) {
                b.append('[').append(k).append(']');
            } else {
                b.append(b.length() == 0 ? "" : ".").append(s);
            }
        }
        return b.toString();
    }
}

package org.tensim.scene.file;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.model.Topology;
import org.tensim.scene.conditions.TimeLaw;

/**
 * Reads a scene file (docs/scenes.md; schema docs/scene.schema.json) into a {@link Scene}: the tree with every
 * value's place ({@link SceneTree}), the {@code --set} overrides ({@link Overrides}), then, in this order, the
 * units, the laws, the bodies (each built by its {@link BodyType}), the regions, the zones, the conditions, the
 * probes, the run settings and the expectations ({@link ExpectBlock}), then the named parameters
 * ({@link SceneParameters}: declared before the overrides, so that {@code --set NAME=VALUE} names one, and checked
 * once the scene is built against the dimension each key was read in). Every refusal is a {@link SceneException}
 * naming file, line, column and key path.
 */
public final class SceneLoader {
    /** The format version this loader reads. */
    public static final int VERSION = 1;
    /** The top-level keys. */
    public static final List<String> KEYS = List.of("version", "description", "units", "bodies", "laws", "regions",
            "zones", "conditions", "probes", "run", "expect", "parameters");

    private SceneLoader() {
    }

    /** Loads a scene file without overrides. */
    public static Scene load(Path file) {
        return load(file, List.of());
    }

    /**
     * Loads a scene file with {@code --set path=value} overrides applied to its tree first; {@code NAME=value}
     * sets a named parameter (range checked; a bare number is in the parameter's unit).
     */
    public static Scene load(Path file, List<String> overrides) {
        Path parent = file.toAbsolutePath().getParent();
        return load(file, SceneTree.read(file), parent == null ? Path.of(".") : parent, overrides);
    }

    /**
     * Loads a scene from its bytes (a scene kept as a resource), {@code name} naming it in messages and
     * {@code folder} the folder its relative file names are resolved against.
     */
    public static Scene load(String name, byte[] bytes, Path folder, List<String> overrides) {
        return load(Path.of(name), SceneTree.read(name, bytes), folder, overrides);
    }

    static Scene load(Path file, SceneNode root, Path folder, List<String> overrides) {
        Map<String, SceneParameters.Declared> declared = SceneParameters.declare(root);
        SceneParameters.override(root, declared, overrides);
        MapReader top = new MapReader(root, KEYS);
        version(top);
        if (top.has("description")) {
            top.string("description");
        }
        SceneUnits units = SceneUnits.read(top.optional("units"));
        Map<String, TimeLaw> laws = TimeLaws.read(top.optional("laws"), units, folder);
        Map<String, RigidBody> rigids = new LinkedHashMap<>();
        Map<String, SceneBody> bodies = bodies(top, units, folder, laws, rigids);
        standalone(top, bodies, rigids);
        Map<String, SceneRegions.Region> regions = SceneRegions.read(top.optional("regions"), bodies, units, folder,
                rigids.keySet());
        SceneZones.apply(top.optional("zones"), bodies, regions, units);
        List<BodyCoupling> couplings = SceneConditions.apply(top.optional("conditions"), bodies, regions, laws, units,
                rigids);
        List<SceneProbe> probes = SceneProbe.read(top.optional("probes"), bodies, regions, rigids,
                couplings);
        RunSettings run = RunSettings.read(top, units);
        for (SceneBody b : bodies.values()) {
            if (run.autoStep() && !BodyTypes.get(b.type()).standalone()) {
                throw SceneException.at(top.required("run").get("dt"), "dt: " + RunSettings.AUTO + " leaves the step"
                        + " to the body, and body '" + b.name() + "' (type " + b.type() + ") does not choose one:"
                        + " give a time step, e.g. \"1 ms\"");
            }
        }
        List<SceneExpectation> expect = ExpectBlock.read(top.optional("expect"), bodies, probes, units);
        List<SceneParameter> parameters = SceneParameters.resolve(declared, root, units);
        return new Scene(file, List.copyOf(overrides), bodies, laws, regions, probes, run, expect, parameters, rigids,
                List.copyOf(couplings));
    }

    /**
     * A {@link BodyType#standalone()} body is the file's only one, rigid bodies included, without zones (its own
     * keys give its tissues); its conditions and probes are read as any body's.
     */
    private static void standalone(MapReader top, Map<String, SceneBody> bodies, Map<String, RigidBody> rigids) {
        for (SceneBody b : bodies.values()) {
            if (!BodyTypes.get(b.type()).standalone()) {
                continue;
            }
            if (bodies.size() > 1 || !rigids.isEmpty()) {
                List<String> all = new java.util.ArrayList<>(bodies.keySet());
                all.addAll(rigids.keySet());
                throw SceneException.at(top.required("bodies"), "a " + b.type() + " body brings its own supports,"
                        + " bones and loads and is a file's only body; got " + all);
            }
            if (top.has("zones")) {
                throw SceneException.at(top.required("zones"), "a " + b.type() + " body brings its own tissues"
                        + " (its own keys set them): its file has no zones block (docs/scenes.md)");
            }
        }
    }

    private static void version(MapReader top) {
        SceneNode v = top.scalar("version");
        if (!v.text().strip().equals(Integer.toString(VERSION))) {
            throw SceneException.at(v, v.describe() + " is not a version this program reads (expected "
                    + VERSION + ")");
        }
    }

    private static Map<String, SceneBody> bodies(MapReader top, SceneUnits units, Path folder,
            Map<String, TimeLaw> laws, Map<String, RigidBody> rigids) {
        SceneNode block = top.required("bodies");
        if (!block.isMap() || block.entries().isEmpty()) {
            throw SceneException.at(block, "expected a map of named bodies (at least one), got " + block.describe());
        }
        Map<String, SceneBody> bodies = new LinkedHashMap<>();
        for (Map.Entry<String, SceneNode> e : block.entries().entrySet()) {
            SceneNode b = e.getValue();
            if (!b.isMap()) {
                throw SceneException.at(b, "expected a body {type: ..., ...}, got " + b.describe());
            }
            List<String> typeNames = new java.util.ArrayList<>(BodyTypes.names());
            typeNames.add(RigidBodies.TYPE);
            String typeName = TimeLaws.typeOf(b, typeNames);
            if (typeName.equals(RigidBodies.TYPE)) {
                rigids.put(e.getKey(), RigidBodies.read(e.getKey(), b, units, folder, laws));
                continue;
            }
            BodyType type = BodyTypes.get(typeName);
            java.util.List<String> keys = new java.util.ArrayList<>(type.keys());
            keys.add(0, "type");
            MapReader r = new MapReader(b, keys);
            Topology t = new Topology();
            int[] vertices;
            BodyContext ctx = new BodyContext(e.getKey(), r, units, folder);
            try {
                vertices = type.build(ctx, t);
            } catch (SceneException ex) {
                throw ex;
            } catch (IllegalArgumentException ex) {
                throw SceneException.at(b, ex.getMessage());
            }
            if (ctx.ownTopology() != null) {
                t = ctx.ownTopology();
            }
            if (t.nodeCount() == 0) {
                throw SceneException.at(b, "body '" + e.getKey() + "' has no node");
            }
            bodies.put(e.getKey(), new SceneBody(e.getKey(), typeName, t, vertices, b, ctx.surface(),
                    ctx.reportLines(), ctx.built()));
        }
        if (bodies.isEmpty()) {
            throw SceneException.at(block, "every body is rigid: a scene needs at least one body with nodes");
        }
        return bodies;
    }
}

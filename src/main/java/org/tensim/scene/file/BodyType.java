package org.tensim.scene.file;

import java.util.List;
import org.tensim.model.Topology;

/**
 * A kind of body a scene file can name with {@code type:} ({@code cube}, later {@code volume}, {@code rigid},
 * {@code shell}, {@code diaphragm}). A body type reads its own keys from the body's map and adds its nodes,
 * springs and links to a topology; the loader does the rest (regions, conditions, probes) the same way for every
 * type. Types are registered in {@link BodyTypes}; the loader never names one.
 */
public interface BodyType {
    /** The word after {@code type:}. */
    String name();

    /**
     * The keys this type accepts under the body besides {@code type} (checked before {@link #build} is called:
     * any other key is refused with a "did you mean"). The docs' JSON Schema lists the same keys.
     */
    List<String> keys();

    /**
     * Reads the body's keys through {@code ctx} (its {@link BodyContext#keys() reader}, its units and files) and
     * adds the body to {@code topology}, which is empty and the body's own. Bad values are refused with
     * {@link SceneException#at}, naming the key.
     *
     * @return the body's vertices: {@code vertexNodes[v]} is the node of mesh vertex (or index) v, which index
     *         lists and label files select by; null when they are the topology's nodes in order
     */
    int[] build(BodyContext ctx, Topology topology);

    /**
     * Whether a body of this type is a whole experiment (the diaphragm): it brings its own supports, loads and
     * outputs, so its file has it alone, without rigid bodies or zones (refused), its run is its type's own, its
     * conditions are those {@link #refusedCondition} lets through (extra loads and supports on its nodes), its
     * probes are recorded during that run, its {@code expect:} checks read that run's summary
     * ({@link #summaryKeys()}) and its probes' columns, and {@code run: {dt: auto}} leaves the step to its
     * time-step policy. False by default (and {@code dt: auto} is refused).
     */
    default boolean standalone() {
        return false;
    }

    /**
     * The step {@code dt: auto} gives a {@link #standalone()} body under an integrator, s, and the rule that chose
     * it (for {@code tensim check}); null when the type does not choose one.
     */
    default org.tensim.solver.stability.TimeStep autoStep(SceneBody body, String integratorName) {
        return null;
    }

    /**
     * Why a condition of {@code type} (one of {@link SceneConditions#TYPES}) cannot act on a body of this type, or
     * null when it can (every type, by default). The loader refuses such a condition naming its {@code type} key
     * and this reason.
     */
    default String refusedCondition(String type) {
        return null;
    }

    /**
     * The named parts of a body this type built, each the set of its nodes (a region's {@code part: NAME}, e.g. a
     * diaphragm's tendon or a shell's upper surface), in the order {@code tensim check} lists them; none by default
     * (a {@code part:} region on such a body is refused).
     */
    default java.util.Map<String, java.util.BitSet> parts(SceneBody body) {
        return java.util.Map.of();
    }

    /**
     * For a {@link #standalone()} type, the numbers its own run writes to summary.json that an {@code expect:}
     * check may read ({@code summary: KEY}), each with its unit ("" for a count or a ratio), besides its probes'
     * columns. None by default.
     */
    default java.util.Map<String, String> summaryKeys() {
        return java.util.Map.of();
    }

    /** The zone models this type supports ({@code zones:} with {@code model:}); none by default. */
    default List<String> zoneModels() {
        return List.of();
    }

    /** The keys of a zone's {@code material:} map for this type; none by default. */
    default List<String> zoneMaterialKeys() {
        return List.of();
    }

    /**
     * Gives {@code nodes} of a body this type built the zone's {@code model} (one of {@link #zoneModels()}),
     * after every body is built and every region resolved, before the conditions. Refusals name the zone
     * ({@link ZoneContext#node()}).
     */
    default void applyZone(ZoneContext zone, Topology topology, java.util.BitSet nodes) {
        throw SceneException.at(zone.node(), "body type '" + name() + "' has no zones");
    }

    /**
     * The keys of this type's body map, as paths below the body (e.g. {@code material.E}), that a running
     * simulation can take a new value of: those that change only the constants of the compiled state (spring
     * stiffness and damping), never its nodes, springs, links or masses. A named parameter may say
     * {@code apply: live} only for these (and the other live keys of {@link LiveKeys}); none by default.
     */
    default List<String> liveKeys() {
        return List.of();
    }

    /** As {@link #liveKeys()} for the keys of a zone's {@code material:} map on a body of this type. */
    default List<String> liveZoneMaterialKeys() {
        return List.of();
    }
}

package org.tensim.scene.file;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.tensim.scene.conditions.TimeLaw;

/**
 * A scene file as loaded by {@link SceneLoader}: its bodies (each with its topology, conditions applied), its
 * named laws and regions (resolved to nodes), its probes, its run settings and what its run must show. Every value
 * is in SI but the expectations', which are in their columns' units.
 *
 * @param file      the scene file
 * @param overrides the {@code --set} options applied, in order
 * @param expect    the {@code expect:} block's checks, in order (empty without one)
 * @param parameters the {@code parameters:} block's named parameters, in order (empty without one)
 * @param rigids    the {@code type: rigid} bodies, which have no nodes (not among {@code bodies}), in file order
 * @param couplings the contacts and slidings between deformable bodies ({@link BodyCoupling}), which a run builds
 *                  into one state ({@link CoupledBodies#merge}); empty when none
 */
public record Scene(Path file, List<String> overrides, Map<String, SceneBody> bodies, Map<String, TimeLaw> laws,
        Map<String, SceneRegions.Region> regions, List<SceneProbe> probes, RunSettings run,
        List<SceneExpectation> expect, List<SceneParameter> parameters, Map<String, RigidBody> rigids,
        List<BodyCoupling> couplings) {
    /** A scene whose deformable bodies are not coupled to each other. */
    public Scene(Path file, List<String> overrides, Map<String, SceneBody> bodies, Map<String, TimeLaw> laws,
            Map<String, SceneRegions.Region> regions, List<SceneProbe> probes, RunSettings run,
            List<SceneExpectation> expect, List<SceneParameter> parameters, Map<String, RigidBody> rigids) {
        this(file, overrides, bodies, laws, regions, probes, run, expect, parameters, rigids, List.of());
    }

    /** A scene without rigid bodies. */
    public Scene(Path file, List<String> overrides, Map<String, SceneBody> bodies, Map<String, TimeLaw> laws,
            Map<String, SceneRegions.Region> regions, List<SceneProbe> probes, RunSettings run,
            List<SceneExpectation> expect, List<SceneParameter> parameters) {
        this(file, overrides, bodies, laws, regions, probes, run, expect, parameters, Map.of());
    }

    /** The named parameter, or null. */
    public SceneParameter parameter(String name) {
        return parameters.stream().filter(p -> p.name().equals(name)).findFirst().orElse(null);
    }
}

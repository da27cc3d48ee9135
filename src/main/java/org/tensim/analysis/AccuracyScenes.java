package org.tensim.analysis;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.model.Topology;
import org.tensim.scene.CubeParameters;
import org.tensim.scene.CubeScene;
import org.tensim.scene.LatticeScene;
import org.tensim.scene.SpringScene;

/**
 * The scenes of the accuracy study, by name. A new scene (the diaphragm) joins
 * with one {@link #register} call; nothing else changes.
 */
public final class AccuracyScenes {
    /** Single spring: natural frequency, rad/s. */
    public static final double SPRING_OMEGA = 10;
    /** Single spring: initial stretch, m. */
    public static final double SPRING_STRETCH_M = 0.1;
    /** Damped spring: damping ratio. */
    public static final double DAMPED_ZETA = 0.1;

    private static final Map<String, AccuracyScene> SCENES = new LinkedHashMap<>();

    static {
        register(spring("spring", 0));
        register(spring("damped-spring", DAMPED_ZETA));
        register(new AccuracyScene("lattice",
                "lattice cube 4 x 4 x 4 nodes, spacing 0.1 m, 1 kg, 1000 N/m, bottom fixed, sagging under gravity from rest",
                () -> LatticeScene.build(4, 0.1, 1, 1000, 0, false), 0.25, 2e-3, 8, null));
        CubeParameters p = CubeParameters.paper();
        register(new AccuracyScene("cube-mss",
                "the paper's mass-spring cube (docs/cube.md parameters), first 2 s of the sinusoidal load",
                () -> CubeScene.massSpring(p).topology, 2, 2e-2, 8, null));
        register(new AccuracyScene("cube-ts",
                "the paper's tensegrity cube (docs/cube.md parameters), first 2 s of the sinusoidal load",
                () -> CubeScene.tensegrity(p).topology, 2, 2e-2, 8, null));
    }

    private AccuracyScenes() {
    }

    private static AccuracyScene spring(String name, double zeta) {
        double w = SPRING_OMEGA;
        double x0 = SPRING_STRETCH_M;
        return new AccuracyScene(name, "one 1 kg mass on one anchored spring, w = " + w + " rad/s, zeta = " + zeta
                + ", released from a " + x0 + " m stretch (exact solution)",
                () -> SpringScene.build(w, zeta, x0), 2, 2e-2, 8, (t, out) -> {
                    java.util.Arrays.fill(out, 0);
                    out[3] = SpringScene.REST_LENGTH_M + SpringScene.exactStretch(w, zeta, x0, t);
                });
    }

    /** Adds or replaces a scene. */
    public static synchronized void register(AccuracyScene scene) {
        SCENES.put(scene.name(), scene);
    }

    /** Registered names, in registration order. */
    public static synchronized List<String> names() {
        return List.copyOf(SCENES.keySet());
    }

    /**
     * The scene of that name.
     *
     * @throws IllegalArgumentException naming the unknown name and the known ones
     */
    public static synchronized AccuracyScene get(String name) {
        AccuracyScene s = SCENES.get(name);
        if (s == null) {
            throw new IllegalArgumentException("unknown scene '" + name + "': expected one of "
                    + String.join(", ", SCENES.keySet()));
        }
        return s;
    }

    /** A fresh topology of the named scene. */
    public static Topology build(String name) {
        return get(name).topology().get();
    }
}

package org.tensim.tuning;

import java.util.ArrayList;
import java.util.List;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.solver.Simulation;
import org.tensim.scene.tunable.Body;
import org.tensim.scene.tunable.SceneFactory;
import org.tensim.scene.tunable.TunableParameter;
import org.tensim.scene.tunable.ViewScene;

/**
 * A small test scene with what the diaphragm has and the cube lacks: a shaded
 * surface in two colours (a red "muscle" rim, a pale "tendon" centre) and a tendon
 * that can be mass-spring or tensegrity (rigid links along the tendon's edges).
 * A square membrane in the x-z plane, border fixed, sagging under gravity.
 */
public final class MembraneTestScene implements ViewScene {
    static final int N = 12;
    static final double SPACING_M = 0.1;
    static final String STIFFNESS = "stiffnessNPerM";
    /** Needs a new scene: gravity is set when the topology is built (a stand-in for a new mesh or cycle). */
    public static final String GRAVITY = "gravityMPerS2";
    static final List<TunableParameter> PARAMETERS = List.of(
            TunableParameter.log(STIFFNESS, "Stiffness", "N/m", 1, 1000, 50, "every spring"),
            TunableParameter.linear(GRAVITY, "Gravity", "m/s^2", 0, 20, 9.81, "set at build").restarting());

    private final Simulation sim;
    private final List<Body> bodies;

    MembraneTestScene(boolean tensegrity, double gravity) {
        Topology t = new Topology();
        Node[][] g = new Node[N][N];
        float[] colours = new float[3 * N * N];
        for (int i = 0; i < N; i++) {
            for (int k = 0; k < N; k++) {
                g[i][k] = t.addNode(i * SPACING_M, 0, k * SPACING_M, 0.01);
                if (i == 0 || k == 0 || i == N - 1 || k == N - 1) {
                    g[i][k].fix();
                }
                int id = g[i][k].id();
                boolean tendon = tendon(i) && tendon(k);
                colours[3 * id] = tendon ? 0.92f : 0.75f;
                colours[3 * id + 1] = tendon ? 0.9f : 0.18f;
                colours[3 * id + 2] = tendon ? 0.8f : 0.15f;
            }
        }
        List<Integer> tri = new ArrayList<>();
        for (int i = 0; i < N; i++) {
            for (int k = 0; k < N; k++) {
                if (i + 1 < N) {
                    link(t, g[i][k], g[i + 1][k], tensegrity && tendon(i) && tendon(i + 1) && tendon(k));
                }
                if (k + 1 < N) {
                    link(t, g[i][k], g[i][k + 1], tensegrity && tendon(k) && tendon(k + 1) && tendon(i));
                }
                if (i + 1 < N && k + 1 < N) {
                    t.addSpring(g[i][k], g[i + 1][k + 1], 50, 0.05);
                    t.addSpring(g[i + 1][k], g[i][k + 1], 50, 0.05);
                    tri.addAll(List.of(g[i][k].id(), g[i + 1][k].id(), g[i + 1][k + 1].id()));
                    tri.addAll(List.of(g[i][k].id(), g[i + 1][k + 1].id(), g[i][k + 1].id()));
                }
            }
        }
        t.setGravity(new Vec3(0, -gravity, 0));
        t.setViscousDamping(0.02);
        sim = Simulation.of(t);
        bodies = List.of(new Body("membrane", sim, tri.stream().mapToInt(Integer::intValue).toArray(), colours,
                Vec3.ZERO, g[N / 2][N / 2].id()));
    }

    private static boolean tendon(int i) {
        return i >= N / 3 && i < N - N / 3;
    }

    private static void link(Topology t, Node a, Node b, boolean rigid) {
        if (rigid) {
            t.addRigidLink(a, b);
        } else {
            t.addSpring(a, b, 50, 0.05);
        }
    }

    public static SceneFactory factory() {
        return new SceneFactory() {
            @Override
            public String name() {
                return "membrane";
            }

            @Override
            public boolean hasTendonChoice() {
                return true;
            }

            @Override
            public ViewScene create(boolean tensegrityTendon, java.util.Map<String, Double> values) {
                return new MembraneTestScene(tensegrityTendon, values.getOrDefault(GRAVITY, 9.81));
            }
        };
    }

    @Override
    public String name() {
        return "membrane";
    }

    @Override
    public String title() {
        return "test membrane";
    }

    @Override
    public List<Body> bodies() {
        return bodies;
    }

    @Override
    public List<TunableParameter> parameters() {
        return PARAMETERS;
    }

    @Override
    public void apply(String key, double value) {
        if (!key.equals(STIFFNESS)) {
            throw new IllegalArgumentException("no parameter " + key);
        }
        for (int i = 0; i < sim.state().springCount(); i++) {
            sim.state().setSpringStiffness(i, value);
        }
    }

    @Override
    public double defaultTimeStep() {
        return 1e-3;
    }

    @Override
    public double displacementScale() {
        return 3;
    }
}

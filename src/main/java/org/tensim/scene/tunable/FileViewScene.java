package org.tensim.scene.tunable;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.tensim.model.LinearMapping;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.file.EmbeddedSurface;
import org.tensim.scene.file.Scene;
import org.tensim.scene.file.SceneBody;
import org.tensim.scene.file.SceneLoader;
import org.tensim.scene.file.SceneProbe;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;

/**
 * A scene file (docs/scenes.md) for the GUI: each body simulated as {@code tensim run} simulates it, at the file's
 * step with the file's integrator. A body drawn by its nodes (the cube) is one {@link Body}; a body that carries a
 * surface (a volume) is its lattice, drawn as springs, followed by its surface: a display-only body whose vertices
 * are fixed nodes (never integrated, no springs), set after every step to the lattice's positions through the
 * mapping, so that what is drawn is the fine surface the lattice carries. The chart follows the file's first probe
 * (its first node); the file declares no live parameters yet, so there are no controls beyond the run's.
 */
public final class FileViewScene implements ViewScene {
    private final Scene scene;
    private final List<Body> bodies = new ArrayList<>();

    private FileViewScene(Scene scene) {
        this.scene = scene;
        SceneProbe first = scene.probes().isEmpty() ? null : scene.probes().get(0);
        for (SceneBody b : scene.bodies().values()) {
            Simulation sim = new Simulation(SystemState.compile(b.topology()),
                    org.tensim.solver.integrators.Integrators.create(scene.run().integrator()));
            int probe = first != null && first.body().equals(b.name()) ? first.nodes()[0] : 0;
            bodies.add(new Body(b.name() + " (" + b.type() + ")", sim, new int[0], null, Vec3.ZERO, probe));
            if (b.surface() != null) {
                bodies.add(surface(b.name(), b.surface(), sim));
            }
        }
    }

    /** The display body of a carried surface, its positions mapped from {@code carrier} after every step. */
    private static Body surface(String name, EmbeddedSurface s, Simulation carrier) {
        LinearMapping map = s.mapping();
        double[] rest = map.restPoints(restTopology(carrier));
        Topology t = new Topology();
        for (int v = 0; v < map.pointCount(); v++) {
            t.addNode(rest[3 * v], rest[3 * v + 1], rest[3 * v + 2], 1).fix();
        }
        Simulation shown = new Simulation(SystemState.compile(t));
        shown.addListener(sim -> map.apply(carrier.state().x, sim.state().x));
        return new Body(name + " surface (vertex 0)", shown, s.mesh().triangles().clone(), null, Vec3.ZERO, 0);
    }

    /** The carrier's rest positions as a topology the mapping can read. */
    private static Topology restTopology(Simulation carrier) {
        double[] x0 = carrier.state().x0;
        Topology t = new Topology();
        for (int i = 0; i < x0.length / 3; i++) {
            t.addNode(x0[3 * i], x0[3 * i + 1], x0[3 * i + 2], 1);
        }
        return t;
    }

    /** A factory that reads the file anew for every scene it makes (a reset rebuilds from the file). */
    public static SceneFactory factory(Path file) {
        org.tensim.scene.file.Scene loaded = SceneLoader.load(file);
        for (org.tensim.scene.file.SceneBody b : loaded.bodies().values()) {
            if (org.tensim.scene.file.BodyTypes.get(b.type()).standalone()) {
                throw org.tensim.scene.file.SceneException.at(b.node(), "a " + b.type() + " body runs as its own"
                        + " experiment, which the GUI opens by name: tensim gui --scene " + b.type() + " with its"
                        + " options (the body's keys, - for _)");
            }
        }
        FileViewScene checked = new FileViewScene(loaded);
        return new SceneFactory() {
            private FileViewScene next = checked;

            @Override
            public String name() {
                return checked.name();
            }

            @Override
            public boolean hasTendonChoice() {
                return false;
            }

            @Override
            public ViewScene create(boolean tensegrityTendon, Map<String, Double> values) {
                FileViewScene s = next != null ? next : new FileViewScene(SceneLoader.load(file));
                next = null;
                return s;
            }
        };
    }

    /** The loaded scene. */
    public Scene scene() {
        return scene;
    }

    @Override
    public String name() {
        String f = scene.file().getFileName().toString();
        return "file-" + f.replaceAll("\\.(ya?ml|json)$", "");
    }

    @Override
    public String title() {
        return scene.file() + ": " + scene.bodies().size() + " bod" + (scene.bodies().size() == 1 ? "y" : "ies")
                + ", " + scene.run().integrator() + " at " + scene.run().dtS() + " s";
    }

    @Override
    public List<Body> bodies() {
        return bodies;
    }

    @Override
    public List<TunableParameter> parameters() {
        return List.of();
    }

    @Override
    public void apply(String key, double value) {
        throw new IllegalArgumentException("scene file " + scene.file() + " declares no parameter '" + key + "'");
    }

    @Override
    public double defaultTimeStep() {
        return scene.run().dtS();
    }

    @Override
    public String defaultIntegrator() {
        return scene.run().integrator();
    }

    @Override
    public Vec3 up() {
        // Gravity's opposite when the file sets one on its first body, else the view's default.
        Vec3 g = scene.bodies().values().iterator().next().topology().gravity();
        return g.norm() == 0 ? ViewScene.super.up() : g.times(-1 / g.norm());
    }
}

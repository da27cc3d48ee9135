package org.tensim.scene.tunable;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.model.LinearMapping;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.file.EmbeddedSurface;
import org.tensim.scene.file.Scene;
import org.tensim.scene.file.SceneBody;
import org.tensim.scene.file.SceneLoader;
import org.tensim.scene.file.SceneParameter;
import org.tensim.scene.file.SceneProbe;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;

/**
 * A scene file (docs/scenes.md) for the GUI: each body simulated as {@code tensim run} simulates it, at the file's
 * step with the file's integrator. A body drawn by its nodes (the cube) is one {@link Body}; a body that carries a
 * surface (a volume) is its lattice, drawn as springs, followed by its surface: a display-only body whose vertices
 * are fixed nodes (never integrated, no springs), set after every step to the lattice's positions through the
 * mapping, so that what is drawn is the fine surface the lattice carries. The chart follows the file's first probe
 * (its first node).
 *
 * <p>The file's named parameters ({@code parameters:}) are its controls. A rebuild one ({@link
 * TunableParameter#restarts()}) makes a new scene from the file with every current value as {@code --set
 * NAME=VALUE}. A live one loads the file anew with the new value on the preparing thread while the simulation
 * steps ({@link #prepare}), then hands the running simulations the new build's constants ({@link LiveConstants}):
 * the next step runs with them, from the positions and velocities reached.
 */
public final class FileViewScene implements ViewScene {
    private final Path file;
    /** The {@code --set} options of the command line, applied before the parameters' values. */
    private final List<String> given;
    private final Scene scene;
    private final List<Body> bodies = new ArrayList<>();
    /** The simulations of the file's bodies, in file order (the drawn surfaces left out). */
    private final List<Simulation> simulations = new ArrayList<>();
    /** The values the running simulations have, by parameter name (parameters' units). */
    private final Map<String, Double> values = new LinkedHashMap<>();
    /** As {@link #values} with the changes prepared but not yet handed over: each change builds on them. */
    private final Map<String, Double> prepared = new LinkedHashMap<>();

    private FileViewScene(Path file, List<String> given, Scene scene) {
        this.file = file;
        this.given = List.copyOf(given);
        this.scene = scene;
        for (SceneParameter p : scene.parameters()) {
            values.put(p.name(), p.value());
        }
        prepared.putAll(values);
        SceneProbe first = scene.probes().isEmpty() ? null : scene.probes().get(0);
        for (SceneBody b : scene.bodies().values()) {
            Simulation sim = new Simulation(SystemState.compile(b.topology()),
                    org.tensim.solver.integrators.Integrators.create(scene.run().integrator()));
            simulations.add(sim);
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
        return factory(file, List.of());
    }

    /**
     * As {@link #factory(Path)}, the file read with {@code sets} ({@code --set} options: key paths or parameter
     * names) before the values of the controls.
     */
    public static SceneFactory factory(Path file, List<String> sets) {
        FileViewScene checked = new FileViewScene(file, sets, SceneLoader.load(file, sets));
        // The values the file and the options give, before any control moves (the first scene's change live).
        Map<String, Double> defaults = new LinkedHashMap<>(checked.values);
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
                Map<String, Double> asked = new LinkedHashMap<>(defaults);
                for (Map.Entry<String, Double> e : values.entrySet()) {
                    if (asked.containsKey(e.getKey())) {
                        asked.put(e.getKey(), e.getValue());
                    }
                }
                FileViewScene s = next != null && asked.equals(defaults) ? next
                        : new FileViewScene(file, sets, SceneLoader.load(file, checked.sets(asked)));
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

    /**
     * The file's named parameters as controls: range and unit the file's, the default the value the scene was
     * loaded with, a logarithmic scale over ranges of a decade and more above zero.
     */
    @Override
    public List<TunableParameter> parameters() {
        return controls(scene);
    }

    /** A loaded scene file's named parameters as the GUI's controls and the sweeps' parameters. */
    public static List<TunableParameter> controls(Scene scene) {
        List<TunableParameter> out = new ArrayList<>();
        for (SceneParameter p : scene.parameters()) {
            boolean log = p.min() > 0 && p.max() / p.min() >= 10;
            String what = (p.description().isEmpty() ? "Sets " + p.path() + " of the scene file"
                    : p.description() + " (" + p.path() + ")") + "; " + (p.live() ? "applies to the running"
                    : "rebuilds the scene from the file, which restarts from rest") + ".";
            // Within the range to the last bit (a value converted between units may sit a rounding outside).
            double start = Math.max(p.min(), Math.min(p.max(), p.value()));
            out.add(new TunableParameter(p.name(), p.name(), p.unit(), p.min(), p.max(), start, log, what,
                    !p.live()));
        }
        return out;
    }

    /** The options a scene is loaded with: the command line's, then every parameter's value. */
    private List<String> sets(Map<String, Double> of) {
        List<String> sets = new ArrayList<>(given);
        for (Map.Entry<String, Double> e : of.entrySet()) {
            sets.add(e.getKey() + "=" + scene.parameter(e.getKey()).text(e.getValue()));
        }
        return sets;
    }

    @Override
    public void apply(String key, double value) {
        prepare(key, value).run();
    }

    /**
     * Loads the file anew with the live parameter's new value (and every other's current one), here on the
     * preparing thread; the rest hands its constants to the running simulations.
     *
     * @throws IllegalArgumentException for a name that is not a live parameter of the file, or a value the file
     *                                  refuses (the loader's message)
     */
    @Override
    public synchronized Runnable prepare(String key, double value) {
        SceneParameter p = scene.parameter(key);
        if (p == null || !p.live()) {
            throw new IllegalArgumentException("scene file " + scene.file() + " declares no live parameter '" + key
                    + "'" + (p == null ? "" : " (" + key + " applies on rebuild)"));
        }
        if (prepared.get(key) == value) {
            return () -> values.put(key, value);
        }
        Map<String, Double> next = new LinkedHashMap<>(prepared);
        next.put(key, value);
        Scene built = SceneLoader.load(file, sets(next));
        List<SystemState> fresh = new ArrayList<>();
        for (SceneBody b : built.bodies().values()) {
            fresh.add(SystemState.compile(b.topology()));
        }
        prepared.put(key, value);
        return () -> {
            List<String> names = new ArrayList<>(scene.bodies().keySet());
            for (int i = 0; i < simulations.size(); i++) {
                LiveConstants.adopt(simulations.get(i).state(), fresh.get(i), "body '" + names.get(i) + "'");
            }
            values.put(key, value);
        };
    }

    /** The current value of a parameter (tests, the window's readouts), in its unit. */
    public double value(String name) {
        Double v = values.get(name);
        if (v == null) {
            throw new IllegalArgumentException("scene file " + scene.file() + " declares no parameter '" + name
                    + "'");
        }
        return v;
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

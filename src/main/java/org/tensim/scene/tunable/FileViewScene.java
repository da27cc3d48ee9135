package org.tensim.scene.tunable;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.model.LinearMapping;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.scene.file.CoupledBodies;
import org.tensim.scene.file.EmbeddedSurface;
import org.tensim.scene.file.RigidBody;
import org.tensim.scene.file.Scene;
import org.tensim.scene.file.SceneBody;
import org.tensim.scene.file.SceneLoader;
import org.tensim.scene.file.SceneParameter;
import org.tensim.scene.file.SceneProbe;
import org.tensim.scene.rigid.RigidMeshes;
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
 * A rigid body is drawn as its surface (a plane as a square about the deformable bodies), a display-only body like
 * the carried surfaces, posed after every step of the first body at that body's time.
 *
 * <p>Bodies that touch or slide on each other ({@code with:} a deformable body) run as {@code tensim run} runs
 * them: one simulation holding their nodes and their couplings' terms ({@link CoupledBodies#merge},
 * {@link CoupledBodies#simulations}), drawn as one lattice, each body's surface carried from its own nodes in it.
 * A rebuild makes the whole coupled scene anew. A file whose body is a diaphragm opens the diaphragm's own view
 * scene ({@link DiaphragmSceneFile}).
 */
public final class FileViewScene implements ViewScene {
    private final Path file;
    /** The {@code --set} options of the command line, applied before the parameters' values. */
    private final List<String> given;
    private final Scene scene;
    /** The scene as it runs: bodies that touch each other merged into one ({@link CoupledBodies#merge}). */
    private final Scene merged;
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
        // Bodies that touch or slide on each other share one simulation with their couplings' terms, built as
        // tensim run builds it.
        merged = CoupledBodies.merge(scene);
        Map<String, Simulation> sims = CoupledBodies.simulations(merged, scene.run().integrator());
        Map<String, CoupledBodies.Place> places = CoupledBodies.places(scene);
        SceneProbe first = merged.probes().isEmpty() ? null : merged.probes().get(0);
        for (SceneBody b : merged.bodies().values()) {
            Simulation sim = sims.get(b.name());
            simulations.add(sim);
            int probe = first != null && first.body().equals(b.name()) ? first.nodes()[0] : 0;
            bodies.add(new Body(b.name() + " (" + b.type() + ")", sim, new int[0], null, Vec3.ZERO, probe));
            for (SceneBody member : scene.bodies().values()) {
                CoupledBodies.Place at = places.get(member.name());
                if (member.surface() != null && at.into().equals(b.name())) {
                    bodies.add(surface(member.name(), member.surface(), at.offset(), sim));
                }
            }
        }
        Simulation clock = bodies.get(0).simulation();
        for (RigidBody r : scene.rigids().values()) {
            bodies.add(rigid(r, r.mesh() != null ? r.mesh() : planeSquare(r, scene), clock));
        }
    }

    /** A rigid body's surface, its vertices posed at the clock's time after each of its steps. */
    private static Body rigid(RigidBody r, TriangleMesh mesh, Simulation clock) {
        Topology t = new Topology();
        for (int v = 0; v < mesh.vertexCount(); v++) {
            t.addNode(mesh.coord(v, 0), mesh.coord(v, 1), mesh.coord(v, 2), 1).fix();
        }
        Simulation shown = new Simulation(SystemState.compile(t));
        double[] rest = mesh.coordinates().clone();
        double[] rot = new double[9];
        double[] c = new double[3];
        clock.addListener(sim -> {
            r.motion().pose(sim.time(), rot, 0, c, 0);
            double[] x = shown.state().x;
            for (int i = 0; i < rest.length; i += 3) {
                for (int a = 0; a < 3; a++) {
                    x[i + a] = rot[3 * a] * rest[i] + rot[3 * a + 1] * rest[i + 1] + rot[3 * a + 2] * rest[i + 2]
                            + c[a];
                }
            }
        });
        return new Body(r.name() + " (rigid " + r.shape() + ")", shown, mesh.triangles().clone(), null, Vec3.ZERO,
                0);
    }

    /**
     * A plane drawn as a square about the deformable bodies: centred on their bounding box's centre projected on
     * it (a point minus its signed distance along the normal), of half-side that box's diagonal.
     */
    private static TriangleMesh planeSquare(RigidBody r, Scene scene) {
        double[] lo = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
        double[] hi = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (SceneBody b : scene.bodies().values()) {
            double[] bb = b.bounds();
            for (int a = 0; a < 3; a++) {
                lo[a] = Math.min(lo[a], bb[a]);
                hi[a] = Math.max(hi[a], bb[a + 3]);
            }
        }
        double[] m = {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
        double[] n = new double[3];
        double d = r.surface().distance(m[0], m[1], m[2], n, 0);
        double[] p = {m[0] - d * n[0], m[1] - d * n[1], m[2] - d * n[2]};
        double diag = Math.sqrt(Math.pow(hi[0] - lo[0], 2) + Math.pow(hi[1] - lo[1], 2) + Math.pow(hi[2] - lo[2], 2));
        return RigidMeshes.square(p, n, diag > 0 ? diag : 1);
    }

    /**
     * The display body of a carried surface, its positions mapped from {@code carrier} after every step; the
     * surface's body starts at node {@code offset} of the carrier (0 unless it shares a state with others).
     */
    private static Body surface(String name, EmbeddedSurface s, int offset, Simulation carrier) {
        LinearMapping map = offset == 0 ? s.mapping()
                : CoupledBodies.shifted(s.mapping(), offset, carrier.state().nodeCount);
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
        org.tensim.scene.file.Scene loaded = SceneLoader.load(file, sets);
        for (SceneBody b : loaded.bodies().values()) {
            if (b.built() instanceof org.tensim.scene.diaphragm.DiaphragmSetup.Built d) {
                return DiaphragmSceneFile.factory(loaded, b, d); // the diaphragm's own view scene and controls
            }
        }
        FileViewScene checked = new FileViewScene(file, sets, loaded);
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
        Scene built = CoupledBodies.merge(SceneLoader.load(file, sets(next)));
        List<SystemState> fresh = new ArrayList<>();
        for (SceneBody b : built.bodies().values()) {
            fresh.add(SystemState.compile(b.topology()));
        }
        prepared.put(key, value);
        return () -> {
            List<String> names = new ArrayList<>(merged.bodies().keySet());
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

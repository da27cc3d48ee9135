package org.tensim.tuning;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.tunable.TunableParameter;
import org.tensim.solver.integrators.IntegratorChoice;

/**
 * The values the user has tuned, and the one way they reach the simulation.
 * Each change is validated here (an out-of-range or non-finite value is refused
 * with a message naming the parameter, and nothing changes), stored, then passed
 * to the {@link Target} (the simulation runner, which applies it between two
 * steps). Controls listen for changes so that a loaded preset shows up in them.
 *
 * <p>Used from the Swing thread; the target must not block.
 */
public final class Tuning {
    /** Key of the time step, which belongs to the runner rather than to a scene. */
    public static final String TIME_STEP = "timeStepS";

    /** Where changes go. */
    public interface Target {
        void applyParameter(String key, double value);

        void applyIntegrator(IntegratorChoice choice);

        /** A change that needs a new topology: the scene is rebuilt. */
        void applyTendonModel(boolean tensegrity);

        /** A new muscle-load model: the scene is rebuilt with it. */
        void applyMuscleLoad(MuscleLoad muscleLoad);
    }

    private final String scene;
    // Replaced (same keys and ranges) when the muscle load changes; read on any thread.
    private volatile List<TunableParameter> parameters;
    private java.util.function.Function<MuscleLoad, List<TunableParameter>> parametersForLoad;
    private final List<IntegratorChoice> integrators;
    private final boolean tendonChoice;
    private final Map<String, Double> values = new LinkedHashMap<>();
    private final List<Runnable> listeners = new CopyOnWriteArrayList<>();
    // Read by the simulation thread through snapshot(): volatile, and the map is guarded by itself.
    private volatile IntegratorChoice integrator;
    private volatile boolean tensegrityTendon = true;
    private volatile MuscleLoad muscleLoad;
    private volatile List<String> sceneOptions;
    private volatile Target target;

    /**
     * @param scene         scene name
     * @param sceneParameters the scene's parameters
     * @param defaultDtS    the scene's time step, s
     * @param tendonChoice  whether the tendon model can be switched
     * @param integrators   the integrator choices, default first
     */
    public Tuning(String scene, List<TunableParameter> sceneParameters, double defaultDtS, boolean tendonChoice,
            List<IntegratorChoice> integrators) {
        this.scene = scene;
        List<TunableParameter> all = new ArrayList<>(sceneParameters);
        all.add(timeStepParameter(defaultDtS));
        this.parameters = List.copyOf(all);
        this.integrators = List.copyOf(integrators);
        this.tendonChoice = tendonChoice;
        this.integrator = integrators.get(0);
        for (TunableParameter p : parameters) {
            if (values.put(p.key(), p.defaultValue()) != null) {
                throw new IllegalArgumentException("parameter key '" + p.key() + "' appears twice");
            }
        }
    }

    /**
     * As the constructor above for a scene with a muscle-load choice (the diaphragm).
     *
     * @param muscleLoad the scene's muscle-load model, or null for a scene without a muscle
     */
    public Tuning(String scene, List<TunableParameter> sceneParameters, double defaultDtS, boolean tendonChoice,
            List<IntegratorChoice> integrators, MuscleLoad muscleLoad) {
        this(scene, sceneParameters, defaultDtS, tendonChoice, integrators);
        this.muscleLoad = muscleLoad;
    }

    /**
     * As the constructor above, with the scene's parameters for each muscle-load model
     * ({@link org.tensim.scene.tunable.SceneFactory#parameters(MuscleLoad)}): a change of the load then also changes
     * the parameters' labels, defaults and descriptions (the muscle action is an active stress with the fibres,
     * a pressure otherwise), as the rebuilt scene has them.
     */
    public Tuning(String scene, List<TunableParameter> sceneParameters, double defaultDtS, boolean tendonChoice,
            List<IntegratorChoice> integrators, MuscleLoad muscleLoad,
            java.util.function.Function<MuscleLoad, List<TunableParameter>> parametersForLoad) {
        this(scene, sceneParameters, defaultDtS, tendonChoice, integrators, muscleLoad);
        this.parametersForLoad = parametersForLoad;
    }

    /** The time step parameter, s, log scale from 10 us to 50 ms, defaulting to the scene's. */
    public static TunableParameter timeStepParameter(double defaultDtS) {
        double min = 1e-5;
        double max = 0.05;
        return TunableParameter.log(TIME_STEP, "Time step", "s", min, max, Math.max(min, Math.min(max, defaultDtS)),
                "Integration step h. Smaller is more accurate and stable but slower; the status bar warns "
                        + "above the critical estimate.");
    }

    /** Sets where changes go (the simulation runner). */
    public void bind(Target t) {
        target = t;
    }

    public String scene() {
        return scene;
    }

    /** All parameters, the scene's then the time step. */
    public List<TunableParameter> parameters() {
        return parameters;
    }

    public TunableParameter parameter(String key) {
        for (TunableParameter p : parameters) {
            if (p.key().equals(key)) {
                return p;
            }
        }
        throw new IllegalArgumentException("scene '" + scene + "' has no parameter '" + key + "'; known: " + keys());
    }

    /** Parameter keys, in order. */
    public List<String> keys() {
        return List.copyOf(values.keySet());
    }

    public List<IntegratorChoice> integrators() {
        return integrators;
    }

    public boolean hasTendonChoice() {
        return tendonChoice;
    }

    public double get(String key) {
        parameter(key);
        synchronized (values) {
            return values.get(key);
        }
    }

    /**
     * Validates and applies one value.
     *
     * @throws IllegalArgumentException naming the parameter, value and range; nothing changes then
     */
    public void set(String key, double value) {
        parameter(key).validate(value, null);
        synchronized (values) {
            values.put(key, value);
        }
        if (target != null) {
            target.applyParameter(key, value);
        }
        fire();
    }

    public IntegratorChoice integrator() {
        return integrator;
    }

    /** Selects an integrator by name; refuses an unknown one, naming the known ones. */
    public void setIntegrator(String name) {
        IntegratorChoice c = integratorNamed(name, null);
        integrator = c;
        if (target != null) {
            target.applyIntegrator(c);
        }
        fire();
    }

    IntegratorChoice integratorNamed(String name, String source) {
        for (IntegratorChoice c : integrators) {
            if (c.name().equals(name)) {
                return c;
            }
        }
        throw new IllegalArgumentException((source == null ? "" : source + ": ") + "integrator '" + name
                + "' is not available; expected one of " + integrators.stream().map(IntegratorChoice::name).toList());
    }

    public boolean tensegrityTendon() {
        return tensegrityTendon;
    }

    /** Switches the tendon model; the scene is rebuilt (a new topology), so the simulation restarts. */
    public void setTensegrityTendon(boolean tensegrity) {
        if (tensegrity == tensegrityTendon) {
            return;
        }
        tensegrityTendon = tensegrity;
        if (target != null && tendonChoice) {
            target.applyTendonModel(tensegrity);
        }
        fire();
    }

    /** The muscle-load model, or null for a scene without a muscle. */
    public MuscleLoad muscleLoad() {
        return muscleLoad;
    }

    /**
     * Switches the muscle-load model; the scene is rebuilt (the load's topology changes), so the simulation
     * restarts. The muscle action keeps its value: set it too when it was tuned for the other load.
     *
     * @throws IllegalArgumentException for a scene without a muscle; nothing changes then
     */
    public void setMuscleLoad(MuscleLoad load) {
        checkMuscleLoad(load, null);
        if (load == muscleLoad) {
            return;
        }
        muscleLoad = load;
        if (parametersForLoad != null) {
            describe(parametersForLoad.apply(load));
        }
        if (target != null) {
            target.applyMuscleLoad(load);
        }
        fire();
    }

    /** Takes the scene's parameters' descriptions (same keys, the time step kept); values are unchanged. */
    private void describe(List<TunableParameter> sceneParameters) {
        List<TunableParameter> all = new ArrayList<>(sceneParameters);
        all.add(parameter(TIME_STEP));
        if (all.size() != parameters.size()) {
            throw new IllegalStateException("the scene's parameters for another muscle load differ in number: "
                    + all.size() + " against " + parameters.size());
        }
        for (int i = 0; i < all.size(); i++) {
            if (!all.get(i).key().equals(parameters.get(i).key())) {
                throw new IllegalStateException("the scene's parameters for another muscle load differ: '"
                        + all.get(i).key() + "' where '" + parameters.get(i).key() + "' was");
            }
        }
        parameters = List.copyOf(all);
    }

    private void checkMuscleLoad(MuscleLoad load, String source) {
        String where = source == null ? "" : source + ": field 'muscleLoad': ";
        if (load == null) {
            throw new IllegalArgumentException(where + "a muscle load is needed, got none");
        }
        if (muscleLoad == null) {
            throw new IllegalArgumentException(where + "muscle load '" + BoundaryConditions.name(load) + "': scene '"
                    + scene + "' has no muscle");
        }
    }

    /** The current values as a settings record. */
    public Settings snapshot() {
        synchronized (values) {
            return new Settings(scene, integrator.name(), tensegrityTendon, values, muscleLoad, sceneOptions);
        }
    }

    /**
     * The options the scene was built from, in command-line form without the muscle load
     * ({@link Settings#sceneOptions}); null when not known. They are fixed for the scene: a preset records them,
     * and {@link #apply} leaves them alone.
     */
    public List<String> sceneOptions() {
        return sceneOptions;
    }

    /** Records the options the scene was built from (see {@link #sceneOptions()}). */
    public void setSceneOptions(List<String> options) {
        sceneOptions = options == null ? null : List.copyOf(options);
    }

    /**
     * Applies a whole settings record after checking all of it: if any value is
     * refused, nothing changes.
     */
    public void apply(Settings s, String source) {
        validate(s, source);
        // Checked: now apply, tendon and muscle load first (they rebuild the scene, which then takes the values below).
        if (tendonChoice) {
            setTensegrityTendon(s.tensegrityTendon());
        }
        if (s.muscleLoad() != null) {
            setMuscleLoad(s.muscleLoad());
        }
        if (!integrator.name().equals(s.integrator())) {
            setIntegrator(s.integrator());
        }
        for (Map.Entry<String, Double> e : s.values().entrySet()) {
            if (e.getValue() != get(e.getKey())) {
                set(e.getKey(), e.getValue());
            }
        }
    }

    /**
     * Checks a settings record against this scene without changing anything.
     *
     * @throws IllegalArgumentException naming the source, the field, the value and what was expected
     */
    public void validate(Settings s, String source) {
        if (!scene.equals(s.scene())) {
            throw new IllegalArgumentException(source + ": field 'scene' is '" + s.scene() + "' but this window shows '"
                    + scene + "'");
        }
        integratorNamed(s.integrator(), source + ": field 'integrator'");
        if (s.muscleLoad() != null) {
            checkMuscleLoad(s.muscleLoad(), source);
        }
        for (Map.Entry<String, Double> e : s.values().entrySet()) {
            if (!values.containsKey(e.getKey())) {
                throw new IllegalArgumentException(source + ": field 'parameters." + e.getKey()
                        + "' is not a parameter of scene '" + scene + "'; known: " + keys());
            }
            parameter(e.getKey()).validate(e.getValue(), source + ": field 'parameters." + e.getKey() + "'");
        }
    }

    /** Called after every change (on the thread that made it). */
    public void addListener(Runnable r) {
        listeners.add(r);
    }

    private void fire() {
        for (Runnable r : listeners) {
            r.run();
        }
    }
}

package org.tensim.solver;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.tensim.model.Topology;
import org.tensim.solver.stability.CriticalTimeStep;
import org.tensim.solver.stability.ModalBounds;
import org.tensim.solver.stability.TimeStep;
import org.tensim.solver.stability.TimeStepPolicy;

/**
 * Runs the paper's three-stage loop on a compiled {@link SystemState}:
 * <ol>
 * <li>{@link Stage#INTEGRATE}: the {@link Integrator} (by default the paper's
 * {@link MidpointRK2}) advances positions and velocities as if there were no
 * rigid links;</li>
 * <li>{@link Stage#PROJECT}: {@link RigidLinkProjection} restores every rigid
 * link's length, mass-weighted, fixed nodes never moving; where nodes touch hard bodies
 * ({@link org.tensim.model.ContactBody#hard()}), {@link ContactForces#project} then puts every node that went
 * deeper than its gap back on it along the body's normal, alternately with the links' projection
 * ({@link #CONTACT_ROUNDS} rounds, the links last), so that neither a large step nor an inexact implicit
 * solve leaves a node inside a bone (the penalty alone lets it in by its load over the stiffness); each round
 * runs the force terms' own projections too ({@link ForceTerm#project}: a mapped surface kept out of bones);</li>
 * <li>{@link Stage#VELOCITY}: new velocities from the corrected positions: each
 * node moved by the projection gets {@code v += (x_corrected - x_unconstrained) / dt},
 * so the velocity matches the constrained motion (a node that no link or hard contact touches keeps
 * the integrator's velocity, and with it the integrator's order); a node put back on a bone loses
 * the velocity that carried it in (an inelastic, frictionless contact).</li>
 * </ol>
 * then checks the state for divergence and notifies the {@link StepListener}s.
 * Every stage is timed into {@link #profile()}.
 *
 * <p>Checks, on every run:
 * <ul>
 * <li>Critical time step: on the first step with a given integrator and dt, an
 * explicit integrator stepping beyond {@link CriticalTimeStep#forMethod} of
 * the state's estimate is reported ({@link SolverSettings#stepLimitSeverity}, default
 * {@link Severity#WARN}; {@link Severity#ERROR} throws
 * {@link IllegalArgumentException} naming the estimate).</li>
 * <li>Divergence: a non-finite position or velocity, a runaway node (checked every
 * step, {@link #setRunawayLimit}), or the kinetic + spring
 * energy growing more than {@link SolverSettings#energyGrowthLimit} times between checks made
 * every {@link SolverSettings#energyCheckInterval} steps, or (where the scene bounds its motion,
 * {@link #setDisplacementLimit}) a node farther than that from where it started, throws
 * {@link SimulationDivergedException} naming the step, the time, the worst node
 * and the critical step estimate.</li>
 * <li>Rigid-link projection: a projection that stops at its iteration cap above
 * its tolerance is counted and reported with its residual
 * ({@link SolverSettings#projectionFailureSeverity}, default {@link Severity#WARN};
 * {@link Severity#ERROR} throws {@link ProjectionFailedException}).</li>
 * </ul>
 * All of these settings are one {@link SolverSettings} record ({@link #apply}), read as the steps are made.
 * Warnings go to {@link #setWarningSink} (default: standard error).
 */
public final class Simulation {
    private final SystemState state;
    private final ForceModel forces;
    private final RigidLinkProjection projection = new RigidLinkProjection();
    private final List<StepListener> listeners = new CopyOnWriteArrayList<>();
    // Notified from this array: iterating the list would allocate an iterator per step.
    private volatile StepListener[] listenerSnapshot = new StepListener[0];
    private final StepProfile profile = new StepProfile();
    private final double[] unconstrained;
    /**
     * Rounds of the contact projection, each followed by the links' projection: a node put back on a bone
     * while its rigid column pulls it in again gets there to within half its correction per round.
     */
    public static final int CONTACT_ROUNDS = 3;
    private int[] correctedNodes; // free nodes the projection stage may move (links', contacts', terms'), each once
    private final boolean hardContacts;
    private int termVersionSeen; // the force terms' version correctedNodes and unconstrained are for
    private boolean termProjection; // whether a force term has a projection stage
    private Integrator integrator;
    private double time;
    private long steps;
    private long unconvergedProjections;
    private final DivergenceMonitor monitor = new DivergenceMonitor();
    private final java.util.function.DoubleSupplier criticalStepOfIntegrator = this::criticalStepOfIntegrator;
    private SolverSettings settings = SolverSettings.DEFAULTS;
    private java.util.function.Consumer<String> warningSink = m -> System.err.println("tensim: warning: " + m);
    private Integrator checkedIntegrator;
    private double checkedDt = Double.NaN;
    private long stepLimitWarnings;

    /** A simulation of a compiled state with the paper's RK2 integrator. */
    public Simulation(SystemState state) {
        this(state, new MidpointRK2());
    }

    /** A simulation with the given settings, the integrator's CG included ({@link Integrator#configure}). */
    public Simulation(SystemState state, Integrator integrator, SolverSettings settings) {
        this(state, integrator);
        install(settings, true);
    }

    public Simulation(SystemState state, Integrator integrator) {
        this.state = state;
        this.forces = new ForceModel(state);
        this.hardContacts = state.contacts.hardNodes().length > 0;
        this.unconstrained = new double[3 * state.nodeCount]; // the positions before the projection stage
        termsChanged();
        setIntegrator(integrator);
        monitor.setEnergyGrowthLimit(settings.energyGrowthLimit());
        monitor.setEnergyCheckInterval(settings.energyCheckInterval());
        state.applyMotions(0, state.x, state.v, new double[6]);
    }

    /** Compiles the topology and makes a simulation with the paper's RK2 integrator. */
    public static Simulation of(Topology t) {
        return new Simulation(SystemState.compile(t));
    }

    public SystemState state() {
        return state;
    }

    public ForceModel forces() {
        return forces;
    }

    public Integrator integrator() {
        return integrator;
    }

    /** Replaces the integrator; takes effect at the next step. */
    public void setIntegrator(Integrator i) {
        if (i == null) {
            throw new IllegalArgumentException("integrator must not be null");
        }
        integrator = i;
    }

    /** The rigid-link projection (its tolerance and sweep cap are the settings', {@link #apply}). */
    public RigidLinkProjection projection() {
        return projection;
    }

    public StepProfile profile() {
        return profile;
    }

    /**
     * Applies the settings, e.g. {@code sim.apply(sim.settings().withStepLimitSeverity(Severity.IGNORE))}: the
     * severities, the energy check, the projection's tolerance and sweep cap (read every step), and, when they
     * differ from those in force, the CG settings, which go to the integrator ({@link Integrator#configure}: an
     * implicit method's CG), so that an integrator's own (a named setup's, {@code --cg-tolerance}) stay otherwise;
     * the thread count is read by {@code parallel.Parallelism.install(Simulation)}. Takes effect at the next step.
     */
    public Simulation apply(SolverSettings s) {
        java.util.Objects.requireNonNull(s, "solver settings");
        install(s, s.cgTolerance() != settings.cgTolerance() || s.cgMaxIterations() != settings.cgMaxIterations());
        return this;
    }

    private void install(SolverSettings s, boolean configureIntegrator) {
        settings = s;
        monitor.setEnergyGrowthLimit(s.energyGrowthLimit());
        monitor.setEnergyCheckInterval(s.energyCheckInterval());
        if (configureIntegrator) {
            integrator.configure(s);
        }
    }

    /**
     * The settings in force, as last applied (the defaults before). An integrator set later keeps its own CG
     * settings.
     */
    public SolverSettings settings() {
        return settings;
    }

    /** Simulated time, s. */
    public double time() {
        return time;
    }

    /** Steps completed. */
    public long steps() {
        return steps;
    }

    /** Steps whose projection stopped at the iteration cap above the tolerance. */
    public long unconvergedProjections() {
        return unconvergedProjections;
    }

    /** Steps whose dt was beyond the critical step estimate of an explicit integrator (counted once per dt). */
    public long stepLimitWarnings() {
        return stepLimitWarnings;
    }

    /** Where warnings go (default: standard error, prefixed "tensim: warning: "). */
    public Simulation setWarningSink(java.util.function.Consumer<String> sink) {
        warningSink = java.util.Objects.requireNonNull(sink, "warning sink");
        return this;
    }

    /**
     * Speed, in scene sizes per step, beyond which a node has run away and the run is stopped
     * as diverged at that very step (checked every step, with the finiteness check);
     * {@link Double#POSITIVE_INFINITY} leaves only the finiteness and distance checks. Default 10.
     */
    public Simulation setRunawayLimit(double sizesPerStep) {
        monitor.setRunawayLimit(sizesPerStep);
        return this;
    }

    public double runawayLimit() {
        return monitor.runawayLimit();
    }

    /**
     * How far (m) a node may move from where it started before the run is stopped as diverged,
     * checked every {@link SolverSettings#energyCheckInterval()} steps: a bound a scene's physics
     * sets on its motion, which catches a slow runaway that neither the energy growth nor the speed
     * check sees. Default {@link Double#POSITIVE_INFINITY} (off).
     */
    public Simulation setDisplacementLimit(double metres) {
        monitor.setDisplacementLimit(metres);
        return this;
    }

    public double displacementLimit() {
        return monitor.displacementLimit();
    }

    /** The state's critical time step estimate ({@link SystemState#criticalTimeStep()}). */
    public CriticalTimeStep criticalTimeStep() {
        return state.criticalTimeStep();
    }

    /** The step beyond which the current integrator is expected to go unstable on this state, s. */
    public double criticalStepOfIntegrator() {
        return state.criticalTimeStep().forMethod(integrator.explicit(), integrator.undampedStabilityLimit());
    }

    /**
     * The step {@link TimeStepPolicy} recommends for the current integrator on this
     * state, from its w_max estimate (damping not counted), with how it was chosen.
     * Scenes that know their damping (the diaphragm) ask the policy with it.
     */
    public TimeStep recommendedTimeStep() {
        return TimeStepPolicy.recommend(integrator.name(), integrator.stability(), integrator.explicit(),
                ModalBounds.undamped(state.criticalTimeStep()));
    }

    /** Adds l, notified after every step, in the order added, on the thread that steps. */
    public void addListener(StepListener l) {
        synchronized (listeners) {
            listeners.add(l);
            listenerSnapshot = listeners.toArray(new StepListener[0]);
        }
    }

    /** Removes l: it is not notified after the next steps (nothing when it was not added). */
    public void removeListener(StepListener l) {
        synchronized (listeners) {
            listeners.remove(l);
            listenerSnapshot = listeners.toArray(new StepListener[0]);
        }
    }

    /**
     * Advances the simulation by dt seconds.
     *
     * @throws IllegalArgumentException     when dt is not finite and > 0
     * @throws SimulationDivergedException when the step leaves a non-finite state
     */
    public void step(double dt) {
        if (!(dt > 0) || !Double.isFinite(dt)) {
            throw new IllegalArgumentException("time step dt must be a finite number > 0 s, got " + dt);
        }
        if (dt != checkedDt || integrator != checkedIntegrator) {
            checkStepLimit(dt);
        }
        if (forces.termVersion() != termVersionSeen) {
            termsChanged();
        }
        long t0 = System.nanoTime();
        integrator.step(forces, time, dt);
        long t1 = System.nanoTime();
        profile.record(Stage.INTEGRATE, t1 - t0);

        boolean links = state.linkCount() > 0, hard = hardContacts || termProjection;
        if (links || hard) {
            System.arraycopy(state.x, 0, unconstrained, 0, unconstrained.length);
        }
        if (links) {
            projectLinks(dt);
        }
        for (int round = 0; round < CONTACT_ROUNDS && hard; round++) {
            double moved = hardContacts ? state.contacts.project(time + dt, state.x, state.invMass) : 0;
            if (Math.max(moved, termProjection ? forces.projectTerms(time + dt, state.x, state.invMass) : 0) == 0) {
                break;
            }
            if (links) {
                projectLinks(dt);
            }
        }
        long t2 = System.nanoTime();
        profile.record(Stage.PROJECT, t2 - t1);

        if (links || hard) {
            updateVelocities(dt);
        }
        for (int k : state.heldDof) { // held coordinates stay at rest whatever the integrator's linear solve gave
            state.x[k] = state.x0[k];
            state.v[k] = 0;
        }
        long t3 = System.nanoTime();
        profile.record(Stage.VELOCITY, t3 - t2);

        time += dt;
        steps++;
        monitor.check(state, forces, steps, time, dt, criticalStepOfIntegrator);
        long t4 = System.nanoTime();
        profile.record(Stage.CHECK, t4 - t3);

        for (StepListener l : listenerSnapshot) {
            l.afterStep(this);
        }
        profile.record(Stage.NOTIFY, System.nanoTime() - t4);
        profile.countStep();
    }

    /** Steps with a fixed dt until the simulated time reaches {@code endTime} (s). */
    public void runUntil(double endTime, double dt) {
        while (time < endTime - 0.5 * dt) {
            step(dt);
        }
    }

    private void projectLinks(double dt) {
        if (!projection.project(state, state.x, settings.projectionTolerance(), settings.projectionMaxIterations())) {
            unconvergedProjections++;
            projectionFailed(dt);
        }
    }

    /** The nodes the velocity update corrects, with those of the force terms' projections (added or removed). */
    private void termsChanged() {
        termVersionSeen = forces.termVersion();
        int[] p = forces.projectedNodes();
        termProjection = p.length > 0;
        correctedNodes = java.util.stream.Stream.of(state.linkNodes, state.contacts.hardNodes(), p)
                .flatMapToInt(java.util.stream.IntStream::of).distinct().sorted().toArray();
    }

    private void updateVelocities(double dt) {
        final double inv = 1 / dt;
        final double[] x = state.x;
        final double[] v = state.v;
        for (int node : correctedNodes) {
            if (state.invMass[node] == 0) {
                continue; // fixed and driven nodes keep their prescribed velocity
            }
            for (int k = 3 * node; k < 3 * node + 3; k++) {
                v[k] += (x[k] - unconstrained[k]) * inv;
            }
        }
    }

    private void checkStepLimit(double dt) {
        checkedDt = dt;
        checkedIntegrator = integrator;
        Severity stepLimitSeverity = settings.stepLimitSeverity();
        if (stepLimitSeverity == Severity.IGNORE || !integrator.explicit()) {
            return;
        }
        double limit = criticalStepOfIntegrator();
        if (dt > limit) {
            stepLimitWarnings++;
            String msg = StepWarnings.stepLimit(dt, limit, integrator.name(), state.criticalTimeStep());
            if (stepLimitSeverity == Severity.ERROR) {
                throw new IllegalArgumentException(msg);
            }
            warningSink.accept(msg);
        }
    }

    private void projectionFailed(double dt) {
        Severity projectionSeverity = settings.projectionFailureSeverity();
        if (projectionSeverity == Severity.IGNORE) {
            return;
        }
        String msg = StepWarnings.projection(steps + 1, time + dt, projection, settings.projectionTolerance());
        if (projectionSeverity == Severity.ERROR) {
            throw new ProjectionFailedException(steps + 1, projection.worstLink(), projection.maxRelativeError(),
                    msg);
        }
        StepWarnings.everyPowerOfTen(unconvergedProjections, msg, warningSink);
    }
}

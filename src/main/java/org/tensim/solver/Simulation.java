package org.tensim.solver;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.tensim.model.Topology;

/**
 * Runs the paper's three-stage loop on a compiled {@link SystemState}:
 * <ol>
 * <li>{@link Stage#INTEGRATE}: the {@link Integrator} (by default the paper's
 * {@link MidpointRK2}) advances positions and velocities as if there were no
 * rigid links;</li>
 * <li>{@link Stage#PROJECT}: {@link RigidLinkProjection} restores every rigid
 * link's length, mass-weighted, fixed nodes never moving;</li>
 * <li>{@link Stage#VELOCITY}: new velocities from the corrected positions: each
 * node moved by the projection gets {@code v += (x_corrected - x_unconstrained) / dt},
 * so the velocity matches the constrained motion (a node that no link touches keeps
 * the integrator's velocity, and with it the integrator's order).</li>
 * </ol>
 * then checks the state for divergence and notifies the {@link StepListener}s.
 * Every stage is timed into {@link #profile()}.
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
    private Integrator integrator;
    private double time;
    private long steps;
    private long unconvergedProjections;

    /** A simulation of a compiled state with the paper's RK2 integrator. */
    public Simulation(SystemState state) {
        this(state, new MidpointRK2());
    }

    public Simulation(SystemState state, Integrator integrator) {
        this.state = state;
        this.forces = new ForceModel(state);
        this.unconstrained = new double[state.linkCount() > 0 ? 3 * state.nodeCount : 0];
        setIntegrator(integrator);
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

    /** The rigid-link projection, whose tolerance and iteration cap can be set. */
    public RigidLinkProjection projection() {
        return projection;
    }

    public StepProfile profile() {
        return profile;
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

    public void addListener(StepListener l) {
        synchronized (listeners) {
            listeners.add(l);
            listenerSnapshot = listeners.toArray(new StepListener[0]);
        }
    }

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
        long t0 = System.nanoTime();
        integrator.step(forces, time, dt);
        long t1 = System.nanoTime();
        profile.record(Stage.INTEGRATE, t1 - t0);

        boolean links = state.linkCount() > 0;
        if (links) {
            System.arraycopy(state.x, 0, unconstrained, 0, unconstrained.length);
            if (!projection.project(state, state.x)) {
                unconvergedProjections++;
            }
        }
        long t2 = System.nanoTime();
        profile.record(Stage.PROJECT, t2 - t1);

        if (links) {
            updateVelocities(dt);
        }
        long t3 = System.nanoTime();
        profile.record(Stage.VELOCITY, t3 - t2);

        time += dt;
        steps++;
        checkFinite();
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

    private void updateVelocities(double dt) {
        final double inv = 1 / dt;
        final double[] x = state.x;
        final double[] v = state.v;
        for (int node : state.linkNodes) {
            if (state.invMass[node] == 0) {
                continue; // fixed and driven nodes keep their prescribed velocity
            }
            for (int k = 3 * node; k < 3 * node + 3; k++) {
                v[k] += (x[k] - unconstrained[k]) * inv;
            }
        }
    }

    private void checkFinite() {
        final double[] x = state.x;
        final double[] v = state.v;
        for (int k = 0; k < x.length; k++) {
            // A sum of the two is not finite if either is not: one branch per coordinate.
            if (!Double.isFinite(x[k] + v[k])) {
                int node = k / 3;
                throw new SimulationDivergedException(steps, time, node, "has position ("
                        + x[3 * node] + ", " + x[3 * node + 1] + ", " + x[3 * node + 2] + ") m and velocity ("
                        + v[3 * node] + ", " + v[3 * node + 1] + ", " + v[3 * node + 2]
                        + ") m/s; reduce the time step or add damping");
            }
        }
    }
}

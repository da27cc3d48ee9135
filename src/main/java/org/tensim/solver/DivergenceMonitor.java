package org.tensim.solver;

import org.tensim.model.Check;

/**
 * The divergence checks of {@link Simulation}, run after every step:
 * <ul>
 * <li>every step: every position and velocity finite, and no runaway node: none
 * faster than {@link #runawayLimit()} scene sizes per step ({@code |v_k| dt <= limit * size}),
 * the size being the larger of the diagonal of the starting bounding box and the
 * longest spring (1 m if both are 0). A stable run never moves a node across ten
 * scenes in one step (a free fall may take a node far away, but not that fast); an
 * unstable one does so within a few steps of leaving the physical range, long
 * before it overflows. One comparison per coordinate
 * ({@code |v_k|/V + (x_k - x_k) <= 1}, false for NaN and infinities in either) keeps
 * the check as cheap as the finiteness test alone;</li>
 * <li>every {@link #energyCheckInterval()} steps, the mechanical energy
 * E = kinetic + spring + change of gravity's potential since the first step (J)
 * at most {@link #energyGrowthLimit()} times
 * {@code max(E at the previous check, floor)}, the first reference being the
 * energy after the first step. The floor is the larger of the energy of every
 * spring strained by 1 % of its rest length (so that a body starting from rest
 * under a growing load is not mistaken for a blow-up) and 1e-3 of the energy
 * exchanged, kinetic + spring + |change of gravity's potential| (so that the
 * round-off of a free fall, whose E stays near 0, is not either). A stable scheme
 * under bounded loads does not multiply its energy by 100 within 100 steps;
 * one beyond its critical step does, long before the numbers overflow.</li>
 * <li>every {@link #energyCheckInterval()} steps, when the scene sets one
 * ({@link #setDisplacementLimit}), no node farther than that limit from where it started
 * ({@code |x_i - x0_i| <= limit}, m): a scene whose motion is bounded by its physics (a breathing
 * diaphragm) can go astray slowly, its energy growing by less than the growth limit between
 * checks and no node ever fast, until it is far outside anything the model means; this catches
 * such a slow runaway. Off (infinite) by default: a falling or flying body has no such bound.</li>
 * </ul>
 * Allocation-free except when it throws.
 */
final class DivergenceMonitor {
    /** Default energy growth factor allowed between two checks: 100. */
    static final double DEFAULT_GROWTH_LIMIT = 100;
    /** Default steps between energy checks: 100. */
    static final int DEFAULT_INTERVAL = 100;
    /** Strain of every spring whose energy is the floor of the reference: 1 %. */
    static final double FLOOR_STRAIN = 0.01;

    private double growthLimit = DEFAULT_GROWTH_LIMIT;
    private int interval = DEFAULT_INTERVAL;
    private double floor = Double.NaN;
    private double lastEnergy = Double.NaN;
    private double gravity0;
    /** Fraction of the energy exchanged below which changes of E are round-off. */
    static final double EXCHANGE_FRACTION = 1e-3;
    /** Default runaway speed: scene sizes per step. */
    static final double DEFAULT_RUNAWAY_LIMIT = 10;
    private double runawayLimit = DEFAULT_RUNAWAY_LIMIT;
    private double sceneSize = Double.NaN;
    private double displacementLimit = Double.POSITIVE_INFINITY;

    double runawayLimit() {
        return runawayLimit;
    }

    void setRunawayLimit(double sizesPerStep) {
        if (!(sizesPerStep > 0)) {
            throw new IllegalArgumentException("runaway limit must be > 0 scene sizes per step (or Infinity to turn"
                    + " the check off), got " + sizesPerStep);
        }
        runawayLimit = sizesPerStep;
    }

    double displacementLimit() {
        return displacementLimit;
    }

    void setDisplacementLimit(double metres) {
        if (!(metres > 0)) {
            throw new IllegalArgumentException("displacement limit must be > 0 m (or Infinity to turn the check"
                    + " off), got " + metres);
        }
        displacementLimit = metres;
    }

    double energyGrowthLimit() {
        return growthLimit;
    }

    void setEnergyGrowthLimit(double factor) {
        if (!(factor > 1)) {
            throw new IllegalArgumentException("energy growth limit must be a factor > 1 (or Infinity to turn the"
                    + " check off), got " + factor);
        }
        growthLimit = factor;
    }

    int energyCheckInterval() {
        return interval;
    }

    void setEnergyCheckInterval(int steps) {
        interval = Check.atLeast("energy check interval (steps)", steps, 1);
    }

    /**
     * Checks the state after step number {@code step} at time t.
     *
     * @param criticalStep the critical time step estimate for the integrator in use, s
     *                     (evaluated only when throwing)
     */
    void check(SystemState s, ForceModel forces, long step, double t, double dt,
            java.util.function.DoubleSupplier criticalStep) {
        final double[] x = s.x;
        final double[] v = s.v;
        if (Double.isNaN(sceneSize)) {
            startingSize(s);
        }
        final double speedLimit = runawayLimit * sceneSize / dt;
        final double invV = 1 / speedLimit;
        for (int k = 0; k < x.length; k++) {
            // One comparison per coordinate: x - x is 0, or NaN for a NaN or infinite x; |v|/V > 1 is a runaway.
            if (!(Math.abs(v[k]) * invV + (x[k] - x[k]) <= 1)) {
                checkCoordinate(s, k, step, t, speedLimit, criticalStep);
            }
        }
        if (displacementLimit != Double.POSITIVE_INFINITY && step % interval == 0) {
            checkDisplacements(s, step, t, criticalStep);
        }
        if (growthLimit == Double.POSITIVE_INFINITY) {
            return;
        }
        if (Double.isNaN(lastEnergy)) {
            // First step: the energy the run starts with (e.g. a released stretch) is the first reference.
            floor = floor(s);
            gravity0 = forces.gravityEnergy();
            lastEnergy = forces.kineticEnergy() + forces.elasticEnergy(t, x);
            return;
        }
        if (step % interval != 0) {
            return;
        }
        double kinetic = forces.kineticEnergy();
        double spring = forces.elasticEnergy(t, x);
        double dGravity = forces.gravityEnergy() - gravity0;
        double e = kinetic + spring + dGravity;
        double exchanged = kinetic + spring + Math.abs(dGravity);
        double ref = Math.max(lastEnergy, Math.max(floor, EXCHANGE_FRACTION * exchanged));
        if (e > growthLimit * ref) {
            int node = fastest(s);
            throw new SimulationDivergedException(step, t, node, "is the fastest node ("
                    + Math.sqrt(speed2(v, node)) + " m/s): the mechanical energy grew to " + e
                    + " J, more than " + growthLimit + " times " + ref + " J within " + interval + " steps; "
                    + advice(criticalStep), criticalStep.getAsDouble());
        }
        lastEnergy = e;
    }

    /** The exact limits for coordinate k, whose combined test failed. */
    private void checkCoordinate(SystemState s, int k, long step, double t, double speedLimit,
            java.util.function.DoubleSupplier criticalStep) {
        double[] x = s.x;
        double[] v = s.v;
        if (!Double.isFinite(x[k] + v[k])) {
            int node = worstNonFinite(s, k / 3);
            throw new SimulationDivergedException(step, t, node, "has position (" + x[3 * node] + ", "
                    + x[3 * node + 1] + ", " + x[3 * node + 2] + ") m and velocity (" + v[3 * node] + ", "
                    + v[3 * node + 1] + ", " + v[3 * node + 2] + ") m/s; " + advice(criticalStep),
                    criticalStep.getAsDouble());
        }
        int node = k / 3;
        throw new SimulationDivergedException(step, t, node, "ran away: position (" + x[3 * node] + ", "
                + x[3 * node + 1] + ", " + x[3 * node + 2] + ") m, velocity (" + v[3 * node] + ", "
                + v[3 * node + 1] + ", " + v[3 * node + 2] + ") m/s, faster than " + speedLimit + " m/s ("
                + runawayLimit + " scene sizes of " + sceneSize + " m per step); " + advice(criticalStep),
                criticalStep.getAsDouble());
    }

    /** Every node within {@link #displacementLimit} of its starting position {@code x0}. */
    private void checkDisplacements(SystemState s, long step, double t,
            java.util.function.DoubleSupplier criticalStep) {
        final double[] x = s.x;
        final double[] x0 = s.x0;
        final double limit2 = displacementLimit * displacementLimit;
        for (int i = 0; i < s.nodeCount; i++) {
            double dx = x[3 * i] - x0[3 * i];
            double dy = x[3 * i + 1] - x0[3 * i + 1];
            double dz = x[3 * i + 2] - x0[3 * i + 2];
            if (dx * dx + dy * dy + dz * dz > limit2) {
                throw new SimulationDivergedException(step, t, i, "went astray: it is "
                        + Math.sqrt(dx * dx + dy * dy + dz * dz) + " m from where it started (" + x0[3 * i] + ", "
                        + x0[3 * i + 1] + ", " + x0[3 * i + 2] + ") m, farther than the scene's bound of "
                        + displacementLimit + " m (velocity " + Math.sqrt(speed2(s.v, i)) + " m/s); a slow"
                        + " runaway, which neither the energy nor the speed check caught; " + advice(criticalStep)
                        + ", or solve each step more exactly", criticalStep.getAsDouble());
            }
        }
    }

    /** The scene size, from the state the run starts with. */
    private void startingSize(SystemState s) {
        double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] hi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int k = 0; k < s.x0.length; k++) {
            lo[k % 3] = Math.min(lo[k % 3], s.x0[k]);
            hi[k % 3] = Math.max(hi[k % 3], s.x0[k]);
        }
        double diag = s.nodeCount == 0 ? 0 : Math.sqrt(Math.pow(hi[0] - lo[0], 2) + Math.pow(hi[1] - lo[1], 2)
                + Math.pow(hi[2] - lo[2], 2));
        double longest = 0;
        for (int i = 0; i < s.springCount(); i++) {
            longest = Math.max(longest, s.springL[i]);
        }
        double size = Math.max(diag, longest);
        sceneSize = size > 0 && Double.isFinite(size) ? size : 1;
    }

    private static String advice(java.util.function.DoubleSupplier criticalStep) {
        return "the critical time step estimate is " + criticalStep.getAsDouble()
                + " s; reduce the time step or add damping";
    }

    private static double floor(SystemState s) {
        double e = 0;
        for (int i = 0; i < s.springCount(); i++) {
            double d = FLOOR_STRAIN * s.springL[i];
            e += 0.5 * s.springK[i] * d * d;
        }
        for (int i = 0; i < s.triangleCount(); i++) {
            // Energy of a triangle stretched by the same strain along one axis: (mu + lambda / 2) eps^2.
            e += (s.triMu[i] + 0.5 * s.triLambda[i]) * FLOOR_STRAIN * FLOOR_STRAIN;
        }
        return e > 0 ? e : Double.MIN_NORMAL;
    }

    /**
     * The first free node with a non-finite value, else {@code first}: a fixed
     * node's velocity turns NaN only because its (unused) force did, which a free
     * neighbour caused.
     */
    private static int worstNonFinite(SystemState s, int first) {
        for (int i = first; i < s.nodeCount; i++) {
            if (s.invMass[i] != 0 && !Double.isFinite(s.x[3 * i] + s.x[3 * i + 1] + s.x[3 * i + 2] + s.v[3 * i]
                    + s.v[3 * i + 1] + s.v[3 * i + 2])) {
                return i;
            }
        }
        return first;
    }

    private static int fastest(SystemState s) {
        int best = 0;
        double top = -1;
        for (int i = 0; i < s.nodeCount; i++) {
            double v2 = speed2(s.v, i);
            if (v2 > top) {
                top = v2;
                best = i;
            }
        }
        return best;
    }

    private static double speed2(double[] v, int i) {
        return v[3 * i] * v[3 * i] + v[3 * i + 1] * v[3 * i + 1] + v[3 * i + 2] * v[3 * i + 2];
    }
}

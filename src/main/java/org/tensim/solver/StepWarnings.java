package org.tensim.solver;

import org.tensim.solver.stability.CriticalTimeStep;

/** The warnings a {@link Simulation} gives about its steps, worded in one place. */
final class StepWarnings {
    private StepWarnings() {
    }

    /** A step dt (s) beyond the integrator's critical step estimate {@code limit} (s) on the state. */
    static String stepLimit(double dt, double limit, String integrator, CriticalTimeStep c) {
        return "time step " + dt + " s is beyond the critical step estimate " + limit + " s of " + integrator
                + " on this scene (w_max = " + c.omegaMaxPower() + " rad/s by power iteration, Gershgorin bound "
                + c.omegaMaxGershgorin() + " rad/s); expect the run to blow up";
    }

    /** The projection of step {@code step}, ending at time t (s), stopped above its tolerance. */
    static String projection(long step, double t, RigidLinkProjection p, double tolerance) {
        return "rigid-link projection at step " + step + " (t = " + t + " s) stopped after " + p.iterations()
                + " sweeps with a relative length error of " + p.maxRelativeError() + " on link " + p.worstLink()
                + " (tolerance " + tolerance + "): the links contradict each other, or need more sweeps than the cap"
                + " (SolverSettings.withProjection) or a looser tolerance";
    }

    /**
     * Gives the n-th occurrence's message when n is 1 or a power of ten: enough to be seen, not a flood.
     */
    static void everyPowerOfTen(long n, String msg, java.util.function.Consumer<String> sink) {
        if (n == 1 || (n % 10 == 0 && Long.toString(n).matches("10*"))) {
            sink.accept(msg + (n > 1 ? " (" + n + " such steps so far)" : ""));
        }
    }
}

package org.tensim.solver.prefactored;

/**
 * Chooses, call by call, between the shared and the one-thread form of a kernel that gives the same bits either
 * way, by their measured wall time: each form's time per call is a moving average, the faster form is used, and
 * every {@link #PROBE_PERIOD}-th call tries the other, so that the choice follows a machine whose other core is
 * taken by another process for a while, then freed. Allocation-free.
 */
final class SharingChoice {
    /** One call in this many runs the form that is not the faster, to measure it again. */
    static final int PROBE_PERIOD = 16;
    /** Weight of the newest call in a form's moving average. */
    static final double WEIGHT = 0.25;

    private final KernelSharing policy;
    private double sharedNs = Double.NaN;
    private double serialNs = Double.NaN;
    private long calls;

    SharingChoice(KernelSharing policy) {
        this.policy = policy;
    }

    /** Whether the next call shares its kernel among the threads (when there are two or more). */
    boolean share() {
        switch (policy) {
            case NEVER:
                return false;
            case ALWAYS:
                return true;
            default:
                calls++;
                if (Double.isNaN(sharedNs)) {
                    return true;
                }
                if (Double.isNaN(serialNs)) {
                    return false;
                }
                boolean faster = sharedNs <= serialNs;
                return calls % PROBE_PERIOD == 0 ? !faster : faster;
        }
    }

    /** Records the wall time of a call made in the given form, ns. */
    void record(boolean shared, long ns) {
        if (shared) {
            sharedNs = Double.isNaN(sharedNs) ? ns : sharedNs + WEIGHT * (ns - sharedNs);
        } else {
            serialNs = Double.isNaN(serialNs) ? ns : serialNs + WEIGHT * (ns - serialNs);
        }
    }

    /** The moving average of a form's time per call, ns (NaN before its first call); for tests and reports. */
    double averageNanos(boolean shared) {
        return shared ? sharedNs : serialNs;
    }
}

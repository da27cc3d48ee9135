package org.tensim.io;

/** Thrown by a run's loop when SIGINT or SIGTERM asked it to stop ({@link RunSignals#stopRequested()}). */
public final class RunInterruptedException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public RunInterruptedException() {
        super("interrupted (SIGINT or SIGTERM)");
    }
}

package org.tensim.io;

/**
 * SIGINT (Ctrl-C) and SIGTERM during a run. Java turns both into a shutdown of
 * the JVM, which runs this class's hook: the hook asks the run's loop to stop,
 * closes the run's CSV files (each {@link CsvWriter} finishes the row in progress
 * first), writes {@code summary.json} with {@code "status": "interrupted"} unless
 * the run already wrote its own status, and ends the process with that status's
 * exit code (130 for an interrupted run). A JVM that ends normally (the run has
 * finished and the command returned) finds no active run and the hook does nothing.
 */
public final class RunSignals {
    private static volatile boolean stopRequested;
    private static volatile RunFolder active;
    private static volatile RunStatus lastStatus;
    private static volatile boolean mainProcess;
    private static volatile boolean exiting;
    private static boolean installed;

    private RunSignals() {
    }

    /** True once SIGINT or SIGTERM arrived: long loops poll this and stop at a whole step. */
    public static boolean stopRequested() {
        return stopRequested;
    }

    /** Throws {@link RunInterruptedException} once a stop was requested. */
    public static void checkStop() {
        if (stopRequested) {
            throw new RunInterruptedException();
        }
    }

    static synchronized void activate(RunFolder run) {
        install();
        active = run;
    }

    /** Installs the shutdown hook (once). */
    static synchronized void install() {
        if (!installed) {
            Runtime.getRuntime().addShutdownHook(new Thread(RunSignals::onShutdown, "tensim-run-signals"));
            installed = true;
        }
    }

    static void deactivate(RunFolder run) {
        if (active == run) {
            lastStatus = run.status();
            active = null;
        }
    }

    /**
     * Called by the program's main method: in this process a signal ends the JVM with the
     * exit code of the run's status (130 if it was still running), not the JVM's 128 + signal.
     */
    public static void mainProcess() {
        mainProcess = true;
    }

    /** Called by the main method just before System.exit: the shutdown that follows is no signal. */
    public static void exiting() {
        exiting = true;
    }

    private static void onShutdown() {
        if (exiting) {
            return;
        }
        OutputFiles.deleteInFlight();
        RunFolder run = active;
        RunStatus status = lastStatus;
        if (run != null) {
            stopRequested = true;
            status = run.interruptIfUnfinished();
        }
        if (mainProcess && status != null) {
            // halt, not return: the JVM would exit with 128 + the signal's number whatever the run's status.
            Runtime.getRuntime().halt(status.exitCode());
        }
    }
}

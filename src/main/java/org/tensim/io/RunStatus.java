package org.tensim.io;

import java.util.Locale;

/**
 * How a run ended, as written in its {@code summary.json} ({@code "status"}) and
 * as the process's exit code (docs/outputs.md).
 */
public enum RunStatus {
    /** Every output written; exit code 0. */
    OK(0),
    /** The simulation stopped at a non-finite or runaway step; outputs up to it are kept and marked; exit 1. */
    DIVERGED(1),
    /** An error stopped the run (bad mesh, file-system error, ...); exit 1. */
    FAILED(1),
    /**
     * The run ended, every output written, but what its scene file's {@code expect:} block states does not hold
     * (each check's measured value and verdict are in the summary); exit 3.
     */
    EXPECTATION_FAILED(3),
    /** SIGINT (Ctrl-C) or SIGTERM; the CSVs end on their last whole row; exit 130. */
    INTERRUPTED(130);

    /** Exit code of a command whose options were refused (picocli's usage error). */
    public static final int USAGE_EXIT = 2;

    private final int exitCode;

    RunStatus(int exitCode) {
        this.exitCode = exitCode;
    }

    /** The process exit code for this status. */
    public int exitCode() {
        return exitCode;
    }

    /** The word written in summary.json: ok, diverged, failed, interrupted. */
    public String word() {
        return name().toLowerCase(Locale.ROOT);
    }
}

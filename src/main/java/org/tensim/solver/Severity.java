package org.tensim.solver;

/**
 * What the simulation does when a check fails that does not make the state
 * unusable (a step beyond the critical step, a rigid-link projection that missed
 * its tolerance): the event is always counted; beyond that it is ignored, reported
 * through the simulation's warning sink, or raised as an exception.
 */
public enum Severity {
    /** Counted only. */
    IGNORE,
    /** Counted and reported through {@link Simulation#setWarningSink}. */
    WARN,
    /** Raised as an exception that stops the run. */
    ERROR
}

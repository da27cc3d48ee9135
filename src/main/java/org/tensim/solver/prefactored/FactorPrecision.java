package org.tensim.solver.prefactored;

/**
 * The precision in which the preconditioner's triangular solves read the Cholesky factor's entries. The
 * factorisation is always made in double and the solves always sum in double; only the stored entries of L
 * differ.
 *
 * <p>Why the choice exists: the solves stream the whole factor twice per preconditioner application (L, then
 * L^T), and on the default diaphragm at 43 rings that is 418,674 to 635,941 entries (5-8 MB with their row
 * indices), more than the 4 MiB L2 of this project's machines. Single-precision entries take a third off the
 * bytes per entry (4 + 4 for entry and row index, against 8 + 4). A preconditioner need not be exact: conjugate
 * gradient converges to the true Newton step with any symmetric positive definite preconditioner, so that a
 * step solved to its tolerance is the same with either (tested). A step stopped after a fixed number of
 * iterations (the default bdf2, 1 Newton x 4 CG) depends on the preconditioner, and its trajectory moves
 * within the scene's sensitivity (docs/performance.md).
 */
public enum FactorPrecision {
    /** L's entries in double: the solves' results to round-off (the default). */
    DOUBLE,
    /** L's entries rounded to float (relative 6e-8 each), widened to double where they are used. */
    SINGLE
}

package org.tensim.solver.prefactored;

/**
 * The timed parts of a {@link PrefactoredBdf2} step's Newton-Krylov solve
 * ({@link PrefactoredBdf2#partMillisPerStep}); what is left of the step (predictor, history,
 * error estimate, driven nodes) is the step's time minus their sum.
 */
public enum Bdf2Part {
    /** Linearisation of the rigid links at each Newton iterate and the shift of its velocities onto them. */
    LINKS,
    /** The force pass at each Newton iterate and the residual g(v). */
    RESIDUAL,
    /** Linearisation of the Jacobian (springs' directions, triangles' deformation and stress, fibres). */
    LINEARISE,
    /** Jacobian-vector products of conjugate gradient, with the links' dual projection. */
    PRODUCTS,
    /** Preconditioner applications: three-column solves with the Cholesky factor, and the links' projection. */
    SOLVES
}

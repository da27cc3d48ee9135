package org.tensim.solver.prefactored;

/** Which matrix {@link PrefactoredBdf2} factors as its conjugate gradient's preconditioner ({@link PrefactoredMatrix}). */
public enum PreconditionerMatrix {
    /**
     * Liu et al.'s constant matrix: springs, triangles, shear elements and contact taken isotropically at rest,
     * assembled from the parameters.
     */
    ISOTROPIC,
    /**
     * The Jacobian's own entries read by probing products, factored as a scalar matrix with per-node 3 x 3
     * scalings (the default). Where contact acts or rigid links share nodes the isotropic matrix is used instead.
     */
    PROBED
}

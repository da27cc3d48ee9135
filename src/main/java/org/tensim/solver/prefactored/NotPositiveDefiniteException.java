package org.tensim.solver.prefactored;

/**
 * A sparse Cholesky factorisation met a pivot that is not positive: the matrix is not
 * symmetric positive definite. The message names the matrix and its size.
 */
public final class NotPositiveDefiniteException extends IllegalStateException {
    private static final long serialVersionUID = 1L;

    public NotPositiveDefiniteException(String message) {
        super(message);
    }
}

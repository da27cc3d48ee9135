package org.tensim.solver.prefactored;

/**
 * Whether bdf2 shares its preconditioner's solves ({@link SubtreeSolve}) and the fibres' and shear elements'
 * part of its Jacobian products ({@link NodeParts}) among the force model's threads. Both forms give the same
 * bits, so the choice changes the time of a step only, never its result.
 */
public enum KernelSharing {
    /** On the calling thread alone: the form before they were shared. */
    NEVER,
    /** On the threads whenever the force model has two or more. */
    ALWAYS,
    /**
     * On the threads while that is measured to be faster ({@link SharingChoice}), the triangles' part of the
     * products with them (shared in the other two): on a machine whose other core is taken by another process, a
     * shared kernel waits for the busy core and costs more than on one thread.
     */
    MEASURED
}

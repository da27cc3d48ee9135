package org.tensim.solver;

/**
 * Notified on the simulation thread after each completed step (the scene graph,
 * recorders). A listener reads or copies the state and returns quickly; it must
 * not block, lock or modify the model.
 */
@FunctionalInterface
public interface StepListener {
    void afterStep(Simulation simulation);
}

/**
 * Integrators of m a = f behind {@link org.tensim.solver.Integrator} and their one
 * catalogue, {@link org.tensim.solver.integrators.Integrators}: every named setup
 * ({@link org.tensim.solver.integrators.IntegratorChoice}, a method with its settings)
 * and the real-time setting, by name, for the command line, the GUI, the studies and
 * the sweep and calibration specs. Each integrator is one small class; the simulation
 * applies the same rigid-link projection and velocity update after every one of them.
 * The paper's own RK2 is {@link org.tensim.solver.MidpointRK2}. Like all of the solver
 * layer, it uses only {@code org.tensim.model} and the JDK (no Java3D, Swing, AWT,
 * files or scenes).
 *
 * <p>Stability figures are for an undamped spring, omega = sqrt(k/m) (rad/s),
 * step h (s); see {@code ../shared/docs/PHYSICS.md}.
 */
package org.tensim.solver.integrators;

/**
 * Integrators of m a = f behind {@link org.tensim.solver.Integrator}, chosen by
 * name through {@link org.tensim.solver.integrators.Integrators}. Each is one small
 * class; the simulation applies the same rigid-link projection and velocity update
 * after every one of them. The paper's own RK2 is
 * {@link org.tensim.solver.MidpointRK2}.
 *
 * <p>Stability figures are for an undamped spring, omega = sqrt(k/m) (rad/s),
 * step h (s); see {@code ../shared/docs/PHYSICS.md}.
 */
package org.tensim.solver.integrators;

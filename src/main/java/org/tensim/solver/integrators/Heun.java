package org.tensim.solver.integrators;

import org.tensim.solver.stability.ButcherTableau;

/**
 * Heun's second-order Runge-Kutta method (explicit trapezoidal rule): an Euler
 * predictor to the end of the step, then the average of the two slopes.
 *
 * <pre>
 *   a1 = f(t, x, v) / m                                    0 |
 *   x_p = x + h v,            v_p = v + h a1               1 | 1
 *   a2 = f(t + h, x_p, v_p) / m                            --+---------
 *   x &lt;- x + h/2 (v + v_p),   v &lt;- v + h/2 (a1 + a2)       | 1/2  1/2
 * </pre>
 *
 * Global error O(h^2); two force evaluations per step. On linear problems its
 * amplification factor is that of every two-stage RK2, R(z) = 1 + z + z^2/2, so
 * like the paper's midpoint rule it grows slowly on an undamped spring at every
 * step size (|R(i w h)|^2 = 1 + (w h)^4 / 4) and needs damping or a small w h.
 */
public final class Heun extends ExplicitRungeKutta {
    /** The trapezoidal tableau. */
    public static final ButcherTableau TABLEAU = ButcherTableau.of(new String[][] {{}, {"1"}}, "1/2", "1/2");

    public Heun() {
        super("heun", 2, TABLEAU);
    }
}

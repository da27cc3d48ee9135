package org.tensim.solver.integrators;

import org.tensim.solver.stability.ButcherTableau;

/**
 * The classic fourth-order Runge-Kutta method on (x' = v, v' = f / m):
 *
 * <pre>
 *   stage 1: (x, v)                              -&gt; slopes (v,  a1)        0   |
 *   stage 2: (x + h/2 v,  v + h/2 a1) at t + h/2 -&gt; slopes (v2, a2)        1/2 | 1/2
 *   stage 3: (x + h/2 v2, v + h/2 a2) at t + h/2 -&gt; slopes (v3, a3)        1/2 | 0    1/2
 *   stage 4: (x + h v3,   v + h a3)   at t + h   -&gt; slopes (v4, a4)        1   | 0    0    1
 *   x &lt;- x + h/6 (v + 2 v2 + 2 v3 + v4)                                  ----+--------------------
 *   v &lt;- v + h/6 (a1 + 2 a2 + 2 a3 + a4)                                    | 1/6  1/3  1/3  1/6
 * </pre>
 *
 * Global error O(h^4); four force evaluations per step. R(z) = 1 + z + z^2/2 +
 * z^3/6 + z^4/24: on an undamped spring |R(i w h)| &lt;= 1 iff w h &lt;= 2 sqrt(2)
 * (about 2.83), where it loses a little energy per step ((w h)^6 / 72 to first order).
 */
public final class RK4 extends ExplicitRungeKutta {
    /** The classic tableau. */
    public static final ButcherTableau TABLEAU = ButcherTableau.of(
            new String[][] {{}, {"1/2"}, {"0", "1/2"}, {"0", "0", "1"}}, "1/6", "1/3", "1/3", "1/6");

    public RK4() {
        super("rk4", 4, TABLEAU);
    }
}

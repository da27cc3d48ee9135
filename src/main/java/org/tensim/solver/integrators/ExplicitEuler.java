package org.tensim.solver.integrators;

import org.tensim.solver.stability.ButcherTableau;

/**
 * Forward (explicit) Euler on the first-order system (x' = v, v' = f / m):
 *
 * <pre>
 *   a = f(t, x, v) / m                       0 |
 *   x &lt;- x + h v,      v &lt;- v + h a          --+--
 *                                              | 1
 * </pre>
 *
 * Global error O(h); one force evaluation per step. Amplification factor
 * R(z) = 1 + z: on an undamped spring (z = i w h) |R| = sqrt(1 + (w h)^2) &gt; 1, so
 * the amplitude grows at every step size (x exp(pi w h) per period for small w h).
 * Only damping (Re z &lt; 0) brings it inside the unit disc. A baseline, not a method
 * to simulate with. The position update uses the old velocity: that is what makes
 * it explicit.
 */
public final class ExplicitEuler extends ExplicitRungeKutta {
    /** The one-stage tableau. */
    public static final ButcherTableau TABLEAU = ButcherTableau.of(new String[][] {{}}, "1");

    public ExplicitEuler() {
        super("euler", 1, TABLEAU);
    }
}

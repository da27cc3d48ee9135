package org.tensim.model;

/**
 * A linear spring between two nodes, with damping along its axis.
 *
 * <p>With {@code d = x_b - x_a}, {@code l = |d|}, {@code u = d / l} and
 * {@code v_rel = (v_b - v_a) . u}, the force on node a is
 * {@code f_a = (k (l - L) + c v_rel) u} and {@code f_b = -f_a}: a stretched spring
 * pulls its ends together. Its energy is {@code E = k (l - L)^2 / 2}.
 *
 * @param a                first node id
 * @param b                second node id (different from a)
 * @param stiffness        k, N/m (>= 0)
 * @param restLength       L, m (>= 0)
 * @param damping          c, N s/m (>= 0), along the axis only
 */
public record Spring(int a, int b, double stiffness, double restLength, double damping) {
    public Spring {
        if (a == b) {
            throw new IllegalArgumentException("a spring must join two different nodes, got node " + a
                    + " to itself");
        }
        Check.nonNegative("spring " + a + "-" + b + " stiffness", "N/m", stiffness);
        Check.nonNegative("spring " + a + "-" + b + " rest length", "m", restLength);
        Check.nonNegative("spring " + a + "-" + b + " damping", "N s/m", damping);
    }
}

package org.tensim.model;

import java.util.function.DoubleUnaryOperator;

/**
 * An active fibre tension on a triangle: a muscle's contraction as a membrane tension along the
 * fibre direction, scaled by the active force-length relation f_L ({@link ForceLength}: the full
 * tension at and above the rest length, less as the fibre shortens, none below 0.4 of it).
 *
 * <p>Corners as in {@link TriangleElement}: corner k is the midpoint of nodes {@code p[k]} and
 * {@code q[k]}. With the rest corners Y_k, the unit fibre direction f0 in the rest triangle's plane
 * is written on the rest edges, {@code f0 = c_1 (Y_1 - Y_0) + c_2 (Y_2 - Y_0)}, so that the fibre's
 * image is {@code F f0 = c_1 (y_1 - y_0) + c_2 (y_2 - y_0)} (F the triangle's deformation gradient)
 * and its stretch {@code lambda = |F f0|}. The energy and the forces are
 *
 * <pre>
 *   W = sigma_a(t) t A0 Phi(lambda),   Phi' = f_L,
 *   f_k = -dW/dy_k:   f_1 = -T f_L A0 c_1 u,  f_2 = -T f_L A0 c_2 u,  f_0 = -(f_1 + f_2)
 * </pre>
 *
 * with {@code u = F f0 / lambda}, sigma_a(t) the active stress (Pa, &gt;= 0), t the thickness the
 * element stands for (m), A0 the rest area and {@code T = sigma_a t} the tension (N/m). The forces
 * sum to zero and have no moment (W depends on the corners through an edge vector only, and on its
 * length only), and they shorten the fibre. The active energy is not counted as elastic energy: the
 * muscle does work on the tissue.
 */
public final class ActiveFibre {
    private final int[] p;
    private final int[] q;
    private final double c1;
    private final double c2;
    private final double volumeM3;
    private final DoubleUnaryOperator stressPa;

    /**
     * @param p          first node of each corner (3 ids)
     * @param q          second node of each corner (3 ids; equal to p's for a plain triangle)
     * @param rest       rest positions of the three corners, m
     * @param direction  fibre direction; its component in the rest triangle's plane is used (normalised here)
     * @param thicknessM t, m (&gt; 0): the thickness of muscle this element stands for
     * @param stressPa   active stress sigma_a(t), Pa, as a function of time (s); evaluated at every force pass, so it
     *                   must not allocate
     */
    ActiveFibre(int[] p, int[] q, Vec3[] rest, Vec3 direction, double thicknessM, DoubleUnaryOperator stressPa) {
        String name = "active fibre on triangle " + p[0] + "-" + p[1] + "-" + p[2];
        Check.positive(name + " thickness", "m", thicknessM);
        if (stressPa == null) {
            throw new IllegalArgumentException(name + ": the active stress law (Pa over time) must be given");
        }
        Vec3 e1 = rest[1].minus(rest[0]);
        Vec3 e2 = rest[2].minus(rest[0]);
        // Gram system of the rest edges: f0 = c1 e1 + c2 e2 is the projection of the direction on the plane.
        double g11 = e1.dot(e1);
        double g12 = e1.dot(e2);
        double g22 = e2.dot(e2);
        double det = g11 * g22 - g12 * g12;
        if (!(det > 1e-24 * g11 * g22)) {
            throw new IllegalArgumentException(name + " is degenerate: corners " + rest[0] + ", " + rest[1] + ", "
                    + rest[2] + " (m); expected a triangle of positive area");
        }
        double b1 = direction.dot(e1);
        double b2 = direction.dot(e2);
        double a1 = (g22 * b1 - g12 * b2) / det;
        double a2 = (g11 * b2 - g12 * b1) / det;
        double len = e1.times(a1).plus(e2.times(a2)).norm();
        if (!(len > 1e-6 * direction.norm())) {
            throw new IllegalArgumentException(name + ": the fibre direction " + direction
                    + " is (almost) normal to the triangle; expected a direction in its plane");
        }
        this.c1 = a1 / len;
        this.c2 = a2 / len;
        this.p = p.clone();
        this.q = q.clone();
        this.volumeM3 = 0.5 * Math.sqrt(det) * thicknessM;
        this.stressPa = stressPa;
    }

    /** First node of corner k (0..2). */
    public int p(int k) {
        return p[k];
    }

    /** Second node of corner k (0..2). */
    public int q(int k) {
        return q[k];
    }

    /** The fibre's rest direction on the rest edges: {@code f0 = c(1) (Y_1 - Y_0) + c(2) (Y_2 - Y_0)}, 1/1. */
    public double c(int k) {
        if (k != 1 && k != 2) {
            throw new IllegalArgumentException("fibre coefficient index must be 1 or 2, got " + k);
        }
        return k == 1 ? c1 : c2;
    }

    /** {@code t A0}, m^3: the muscle volume the tension acts in. */
    public double volumeM3() {
        return volumeM3;
    }

    /** The active stress sigma_a(t), Pa. */
    public DoubleUnaryOperator stressPa() {
        return stressPa;
    }
}

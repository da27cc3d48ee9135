package org.tensim.model;

/**
 * A membrane triangle of St Venant-Kirchhoff material in plane stress: the constant-strain
 * triangle of finite elements with Green's strain, which is also Delingette's "biquadratic
 * triangular springs" (Delingette 2008, IEEE TVCG 14(2), "Triangular springs for modeling
 * nonlinear membranes", eq. 7-9: the same energy written on the edges' squared lengths).
 *
 * <p>Corner k sits at the midpoint of two nodes, {@code y_k = (x_{p_k} + x_{q_k}) / 2}; a plain
 * triangle has {@code p_k = q_k}. Midpoint corners put a membrane on the mid-surface of a
 * two-surface shell (the average of an upper node and its lower partner) without adding nodes.
 *
 * <p>With the rest triangle in its own plane frame, {@code D_m = [Y_1 - Y_0, Y_2 - Y_0]} (2 x 2, m),
 * the deformation gradient is {@code F = [y_1 - y_0, y_2 - y_0] D_m^-1} (3 x 2), Green's strain
 * {@code E = (F^T F - I) / 2} and the energy
 *
 * <pre>
 *   W = A t (mu tr(E^2) + lambda / 2 tr(E)^2),   mu = E_Y / (2 (1 + nu)),   lambda = E_Y nu / (1 - nu^2)
 * </pre>
 *
 * (A the rest area, t the thickness, E_Y Young's modulus; lambda is the plane-stress Lame constant).
 * For small strains it is the linear constant-strain triangle, so a uniform strain is represented
 * exactly on any triangle and for any nu (the patch test); it is invariant under rigid motions.
 * The rest shape is the corners' positions when the element is made.
 *
 * <p>Damping (optional) is Kelvin-Voigt, proportional to the stiffness as a spring's axial damping
 * {@code c = beta k} is: the viscous stress {@code beta (2 mu dE/dt + lambda tr(dE/dt) I)} is added
 * to S, with {@code dE/dt = sym(F^T dF/dt)}; it dissipates {@code beta (2 mu |dE/dt|^2 + lambda
 * tr(dE/dt)^2) A t >= 0} and does not resist rigid motions.
 */
public final class TriangleElement {
    private final int[] p;
    private final int[] q;
    private final double[] restInverse;
    private final double areaM2;
    private final double thicknessM;
    private final double youngPa;
    private final double poisson;
    private final double dampingS;

    /**
     * @param p          first node of each corner (3 ids)
     * @param q          second node of each corner (3 ids; equal to p's for a plain triangle)
     * @param rest       the rest positions of the three corners, m
     * @param thicknessM t, m (&gt; 0)
     * @param youngPa    E, Pa (&gt; 0)
     * @param poisson    nu, in (-1, 0.5]
     * @param dampingS   beta, s (&gt;= 0): the viscous stress's factor over the elastic one's
     */
    TriangleElement(int[] p, int[] q, Vec3[] rest, double thicknessM, double youngPa, double poisson,
            double dampingS) {
        String name = "triangle element " + p[0] + "-" + p[1] + "-" + p[2];
        this.thicknessM = Check.positive(name + " thickness", "m", thicknessM);
        this.youngPa = Check.positive(name + " Young's modulus", "Pa", youngPa);
        if (!(poisson > -1 && poisson <= 0.5)) {
            throw new IllegalArgumentException(name + " Poisson's ratio must be in (-1, 0.5] (dimensionless), got "
                    + poisson);
        }
        this.poisson = poisson;
        this.dampingS = Check.nonNegative(name + " damping time beta", "s", dampingS);
        this.p = p.clone();
        this.q = q.clone();
        Vec3 e1 = rest[1].minus(rest[0]);
        Vec3 e2 = rest[2].minus(rest[0]);
        double l1 = e1.norm();
        Vec3 cross = new Vec3(e1.y() * e2.z() - e1.z() * e2.y(), e1.z() * e2.x() - e1.x() * e2.z(),
                e1.x() * e2.y() - e1.y() * e2.x());
        double twiceArea = cross.norm();
        if (!(l1 > 0) || !(twiceArea > 1e-12 * l1 * e2.norm())) {
            throw new IllegalArgumentException(name + " is degenerate: its corners " + rest[0] + ", " + rest[1] + ", "
                    + rest[2] + " (m) are collinear or coincide; expected a triangle of positive area");
        }
        // Rest frame: first axis along e1, second in the plane; D_m = [[l1, a], [0, b]].
        double a = e1.dot(e2) / l1;
        double b = twiceArea / l1;
        this.restInverse = new double[] {1 / l1, -a / (l1 * b), 0, 1 / b};
        this.areaM2 = twiceArea / 2;
    }

    /** First node of corner k (0..2). */
    public int p(int k) {
        return p[k];
    }

    /** Second node of corner k (0..2); equal to {@link #p(int)} for a plain corner. */
    public int q(int k) {
        return q[k];
    }

    /** {@code D_m^-1} row-major (m^-1): [r00, r01, r10, r11]. */
    public double restInverse(int i) {
        return restInverse[i];
    }

    /** Rest area A, m^2. */
    public double areaM2() {
        return areaM2;
    }

    public double thicknessM() {
        return thicknessM;
    }

    public double youngPa() {
        return youngPa;
    }

    public double poisson() {
        return poisson;
    }

    /** Stiffness-proportional damping time beta, s (0: undamped). */
    public double dampingS() {
        return dampingS;
    }

    /** {@code A t mu}, J (N m): the shear modulus times the element's volume. */
    public double muVolume() {
        return areaM2 * thicknessM * youngPa / (2 * (1 + poisson));
    }

    /** {@code A t lambda}, J, with the plane-stress {@code lambda = E nu / (1 - nu^2)}. */
    public double lambdaVolume() {
        return areaM2 * thicknessM * youngPa * poisson / (1 - poisson * poisson);
    }
}

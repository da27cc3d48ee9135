package org.tensim.scene;

import org.tensim.model.Check;
import org.tensim.model.Node;
import org.tensim.model.Topology;

/**
 * One mass on one anchored spring, the test oscillator of the integrators: node 0
 * fixed at the origin, node 1 (mass m = 1 kg) on the x axis at rest length
 * {@value #REST_LENGTH_M} m plus an initial stretch x0, released at rest. Motion
 * stays on the axis, where the spring force is exactly linear:
 * {@code m x'' = -k x - c x'} with k = m w^2 and c = 2 zeta sqrt(k m), so
 * {@code x(t) = x0 e^(-zeta w t) (cos(w_d t) + zeta w / w_d sin(w_d t))},
 * {@code w_d = w sqrt(1 - zeta^2)} (zeta &lt; 1).
 */
public final class SpringScene {
    /** Rest length of the spring, m. */
    public static final double REST_LENGTH_M = 1;
    /** Mass of the moving node, kg. */
    public static final double MASS_KG = 1;

    private SpringScene() {
    }

    /**
     * @param omega    natural frequency sqrt(k/m), rad/s (> 0)
     * @param zeta     damping ratio c / (2 sqrt(k m)), dimensionless, 0 &lt;= zeta
     * @param stretchM initial stretch x0, m (|x0| &lt; rest length)
     */
    public static Topology build(double omega, double zeta, double stretchM) {
        Check.positive("spring natural frequency", "rad/s", omega);
        Check.nonNegative("spring damping ratio", "", zeta);
        Check.finite("spring initial stretch", "m", stretchM);
        if (Math.abs(stretchM) >= REST_LENGTH_M) {
            throw new IllegalArgumentException("spring initial stretch must be smaller than the rest length "
                    + REST_LENGTH_M + " m in size, got " + stretchM + " m");
        }
        double k = MASS_KG * omega * omega;
        double c = 2 * zeta * Math.sqrt(k * MASS_KG);
        Topology t = new Topology();
        Node anchor = t.addNode(0, 0, 0, MASS_KG).fix();
        Node bob = t.addNode(REST_LENGTH_M + stretchM, 0, 0, MASS_KG);
        t.addSpring(anchor.id(), bob.id(), k, REST_LENGTH_M, c);
        return t;
    }

    /** Exact stretch x(t) (m) of the underdamped oscillator released at rest (zeta &lt; 1). */
    public static double exactStretch(double omega, double zeta, double stretchM, double t) {
        if (zeta >= 1) {
            throw new IllegalArgumentException("exact solution implemented for zeta < 1 only, got " + zeta);
        }
        double wd = omega * Math.sqrt(1 - zeta * zeta);
        return stretchM * Math.exp(-zeta * omega * t) * (Math.cos(wd * t) + zeta * omega / wd * Math.sin(wd * t));
    }
}

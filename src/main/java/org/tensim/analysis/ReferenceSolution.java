package org.tensim.analysis;

import org.hipparchus.ode.ODEState;
import org.hipparchus.ode.ODEStateAndDerivative;
import org.hipparchus.ode.OrdinaryDifferentialEquation;
import org.hipparchus.ode.nonstiff.DormandPrince853Integrator;
import org.tensim.model.Topology;
import org.tensim.solver.ForceModel;
import org.tensim.solver.SystemState;

/**
 * Reference trajectories of a scene without rigid links from Hipparchus'
 * adaptive Dormand-Prince 8(5,3) at tight tolerance, through an adapter from
 * tensim's flat state to Hipparchus' {@link OrdinaryDifferentialEquation}:
 * y = (x, v) with 6 n components, x' = v and v' = f(t, x, v) / m on free nodes,
 * zero derivatives on fixed nodes; driven nodes take their prescribed positions
 * and velocities before each force evaluation.
 *
 * <p>Scenes with rigid links have no ODE of this form (the projection is not a
 * force): {@link #solve} refuses them, and their reference is instead the finest
 * step of the most accurate integrator (see {@link AccuracyStudy}).
 */
public final class ReferenceSolution {
    /** Default relative and absolute tolerance of the reference: 1e-12. */
    public static final double DEFAULT_TOLERANCE = 1e-12;

    private ReferenceSolution() {
    }

    /** The adapter: tensim's force model as Hipparchus' first-order ODE. */
    public static final class Equations implements OrdinaryDifferentialEquation {
        private final SystemState s;
        private final ForceModel model;
        private final double[] x;
        private final double[] v;
        private final double[] f;
        private final double[] scratch = new double[6];

        public Equations(SystemState s) {
            this.s = s;
            this.model = new ForceModel(s);
            this.x = new double[3 * s.nodeCount];
            this.v = new double[3 * s.nodeCount];
            this.f = new double[3 * s.nodeCount];
        }

        @Override
        public int getDimension() {
            return 6 * s.nodeCount;
        }

        @Override
        public double[] computeDerivatives(double t, double[] y) {
            int n3 = 3 * s.nodeCount;
            System.arraycopy(y, 0, x, 0, n3);
            System.arraycopy(y, n3, v, 0, n3);
            s.applyMotions(t, x, v, scratch);
            model.computeForces(t, x, v, f);
            double[] d = new double[2 * n3];
            for (int i = 0; i < s.nodeCount; i++) {
                double w = s.invMass[i];
                for (int k = 3 * i; k < 3 * i + 3; k++) {
                    d[k] = w == 0 ? 0 : v[k];
                    d[n3 + k] = w * f[k];
                }
            }
            return d;
        }
    }

    /**
     * Positions (m, 3 per node) of the scene at {@code endTime} (s), starting at
     * rest at its initial positions.
     *
     * @param tolerance relative and absolute tolerance of the adaptive steps
     * @throws IllegalArgumentException when the scene has rigid links
     */
    public static double[] solve(Topology t, double endTime, double tolerance) {
        if (!t.rigidLinks().isEmpty()) {
            throw new IllegalArgumentException("the Dormand-Prince reference needs a scene without rigid links; this one has "
                    + t.rigidLinks().size() + " (use the finest step of the most accurate integrator instead)");
        }
        SystemState s = SystemState.compile(t);
        int n3 = 3 * s.nodeCount;
        double[] y0 = new double[2 * n3];
        double[] scratch = new double[6];
        double[] x = s.x.clone();
        double[] v = s.v.clone();
        s.applyMotions(0, x, v, scratch);
        System.arraycopy(x, 0, y0, 0, n3);
        System.arraycopy(v, 0, y0, n3, n3);
        DormandPrince853Integrator dp = new DormandPrince853Integrator(1e-12 * endTime, endTime, tolerance, tolerance);
        ODEStateAndDerivative end = dp.integrate(new Equations(s), new ODEState(0, y0), endTime);
        double[] y = end.getPrimaryState();
        double[] out = new double[n3];
        System.arraycopy(y, 0, out, 0, n3);
        double[] vEnd = new double[n3];
        System.arraycopy(y, n3, vEnd, 0, n3);
        s.applyMotions(endTime, out, vEnd, scratch);
        return out;
    }
}

package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.model.Topology;
import org.tensim.solver.integrators.Integrators;

/** A scene's own force term, seen by every integrator and by the energy. */
class ForceTermTest {
    /** The term {@code f = -k x}: a spring to the origin, energy {@code k |x|^2 / 2}. */
    private static ForceTerm anchor(double k) {
        return new ForceTerm() {
            @Override
            public void addForces(double t, double[] x, double[] v, double[] f) {
                for (int i = 0; i < x.length; i++) {
                    f[i] -= k * x[i];
                }
            }

            @Override
            public double energy(double t, double[] x) {
                double e = 0;
                for (double xi : x) {
                    e += 0.5 * k * xi * xi;
                }
                return e;
            }
        };
    }

    @Test
    void aTermOscillatesANodeAtItsFrequencyInExplicitAndImplicitIntegrators() {
        double m = 2;
        double k = 50;
        double period = 2 * Math.PI * Math.sqrt(m / k);
        for (String integrator : new String[] {"rk2", "bdf2"}) {
            Topology t = new Topology();
            t.addNode(0.01, 0, 0, m);
            Simulation sim = new Simulation(SystemState.compile(t), Integrators.create(integrator));
            sim.forces().addTerm(anchor(k));
            double dt = period / 2000;
            double e0 = sim.forces().elasticEnergy(0, sim.state().x);
            assertEquals(0.5 * k * 1e-4, e0, 1e-15);
            sim.runUntil(period, dt);
            // After one period the node is back where it started, to the integrators' error.
            assertEquals(0.01, sim.state().x[0], 1e-5, integrator);
            assertTrue(Math.abs(sim.state().v[0]) < 1e-3, integrator + ": v = " + sim.state().v[0]);
        }
    }

    @Test
    void aRemovedTermNoLongerActs() {
        Topology t = new Topology();
        t.addNode(0.01, 0, 0, 1);
        Simulation sim = Simulation.of(t);
        ForceTerm term = anchor(10);
        sim.forces().addTerm(term);
        double[] f = new double[3];
        sim.forces().computeForces(0, sim.state().x, sim.state().v, f);
        assertEquals(-0.1, f[0], 1e-15);
        sim.forces().removeTerm(term);
        sim.forces().computeForces(0, sim.state().x, sim.state().v, f);
        assertEquals(0, f[0], 0);
        assertEquals(0, sim.forces().terms().size());
    }
}

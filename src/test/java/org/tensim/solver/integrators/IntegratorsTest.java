package org.tensim.solver.integrators;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.solver.Integrator;
import org.tensim.solver.MidpointRK2;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.stability.LinearStability;
import org.tensim.solver.stability.StabilityTheory;

/** Properties every integrator must have, whatever its order. */
class IntegratorsTest {
    static List<String> names() {
        return Integrators.names();
    }

    @Test
    void registryHasTheSevenMethodsAndTheirNames() {
        assertEquals(List.of("euler", "symplectic-euler", "rk2", "heun", "verlet", "rk4", "implicit-euler", "bdf2"),
                Integrators.names());
        assertTrue(Integrators.helpList().startsWith(
                "euler, symplectic-euler, rk2 (the paper's), heun, verlet, rk4, implicit-euler, bdf2"),
                Integrators.helpList());
        for (String n : Integrators.names()) {
            Integrator i = Integrators.create(n);
            assertEquals(n, i.name());
            assertTrue(i != Integrators.create(n), "a fresh instance per call (scratch arrays are per state)");
        }
        assertTrue(Integrators.create("rk2") instanceof MidpointRK2, "the paper's RK2 is MidpointRK2");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Integrators.create("rk45"));
        assertTrue(e.getMessage().contains("'rk45'") && e.getMessage().contains("implicit-euler"), e.getMessage());
    }

    /**
     * One catalogue: the methods, then the named variants; every name is accepted by {@link Integrators#create},
     * an unknown one is refused with every valid name.
     */
    @Test
    void catalogueHoldsTheMethodsAndTheirNamedVariants() {
        List<String> all = Integrators.choiceNames();
        assertEquals(Integrators.names(), all.subList(0, Integrators.names().size()));
        assertEquals(List.of(Integrators.REAL_TIME_IMPLICIT, Integrators.LARGE_STEP_ACCURATE, Integrators.CONTACT,
                Integrators.CONTACT_REAL_TIME),
                all.subList(Integrators.names().size(), all.size()));
        List<IntegratorChoice> menu = Integrators.choices();
        assertEquals(Integrators.DEFAULT, menu.get(0).name(), "the paper's first");
        assertEquals(all.size(), menu.size());
        for (IntegratorChoice c : menu) {
            assertEquals(c, Integrators.choice(c.name()));
            if (c.name().equals(Integrators.REAL_TIME_IMPLICIT)) {
                ImplicitEuler ie = (ImplicitEuler) c.create();
                assertEquals("implicit-euler", ie.name());
                assertEquals(Integrators.REAL_TIME_CG_TOLERANCE, ie.tolerance());
            } else if (c.name().equals(Integrators.LARGE_STEP_ACCURATE)) {
                org.tensim.solver.prefactored.PrefactoredBdf2 b =
                        (org.tensim.solver.prefactored.PrefactoredBdf2) Integrators.create(c.name());
                assertEquals("bdf2", b.name());
                assertEquals(2, b.newtonIterations());
                assertEquals(8, b.krylovIterations());
            } else if (c.name().equals(Integrators.CONTACT)) {
                org.tensim.solver.prefactored.PrefactoredBdf2 b =
                        (org.tensim.solver.prefactored.PrefactoredBdf2) Integrators.create(c.name());
                assertEquals("bdf2", b.name());
                assertEquals(3, b.newtonIterations());
                assertEquals(20, b.krylovIterations());
                assertEquals(0, b.linkCoupling());
            } else if (c.name().equals(Integrators.CONTACT_REAL_TIME)) {
                org.tensim.solver.prefactored.PrefactoredBdf2 b =
                        (org.tensim.solver.prefactored.PrefactoredBdf2) Integrators.create(c.name());
                assertEquals("bdf2", b.name());
                assertEquals(1, b.newtonIterations());
                assertEquals(8, b.krylovIterations());
                assertEquals(1, b.linkCoupling());
            } else {
                assertEquals(c.name(), c.create().name());
            }
            assertTrue(c.create() != c.create(), "a new instance for every body");
        }
        assertEquals(Integrators.REAL_TIME, Integrators.choice(Integrators.REAL_TIME).create().name());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Integrators.choice("bdf3"));
        assertEquals("unknown integrator 'bdf3': expected one of " + String.join(", ", all), e.getMessage());
        java.util.List<String> completion = new java.util.ArrayList<>();
        new Integrators.Names().forEach(completion::add);
        assertEquals(all, completion, "help texts list every name");
    }

    /** A free, tumbling 4-node chain with damped springs and no external force keeps its momentum. */
    @ParameterizedTest
    @MethodSource("names")
    void conservesLinearMomentumOfAFreeChain(String name) {
        Topology t = new Topology();
        Node prev = t.addNode(0, 0, 0, 1);
        for (int i = 1; i < 4; i++) {
            Node n = t.addNode(i, 0.3 * i * i, 0, 1 + i);
            t.addSpring(prev, n, 50, 0.5);
            prev = n;
        }
        SystemState s = SystemState.compile(t);
        s.v[0] = 1;
        s.v[4] = -2;
        s.v[11] = 0.5;
        double[] p0 = new double[3];
        s.momentum(p0);
        Simulation sim = new Simulation(s, Integrators.create(name));
        sim.setWarningSink(m -> { });
        sim.runUntil(2, 1e-3);
        double[] p1 = new double[3];
        s.momentum(p1);
        for (int k = 0; k < 3; k++) {
            assertEquals(p0[k], p1[k], 1e-11, name + ": momentum component " + k);
        }
        assertTrue(s.x[9] != 3, "the chain moved");
    }

    /** Fixed nodes stay put, driven nodes follow their motion, under every integrator. */
    @ParameterizedTest
    @MethodSource("names")
    void fixedAndDrivenNodesFollowTheirPrescription(String name) {
        Topology t = new Topology();
        Node fixed = t.addNode(0, 0, 0, 1).fix();
        Node free = t.addNode(1, 0, 0, 1);
        Node driven = t.addNode(2, 0, 0, 1);
        driven.drive((time, rest, out, o) -> {
            out[o] = rest.x() + 0.1 * Math.sin(3 * time);
            out[o + 1] = rest.y();
            out[o + 2] = rest.z();
        });
        t.addSpring(fixed, free, 100, 0.1);
        t.addSpring(free, driven, 100, 0.1);
        t.setGravity(new Vec3(0, -9.81, 0));
        SystemState s = SystemState.compile(t);
        Simulation sim = new Simulation(s, Integrators.create(name));
        double[] lowest = {0};
        sim.addListener(x -> lowest[0] = Math.min(lowest[0], x.state().x[4]));
        sim.runUntil(1, 1e-3);
        assertEquals(0, s.x[0], 0);
        assertEquals(0, s.x[1], 0);
        assertEquals(2 + 0.1 * Math.sin(3 * sim.time()), s.x[6], 1e-12, name + ": driven node x");
        assertEquals(0.3 * Math.cos(3 * sim.time()), s.v[6], 1e-6, name + ": driven node velocity");
        // The two springs start straight at rest length: the free node falls, then swings about its sag.
        assertTrue(lowest[0] < -0.05, name + ": the free node falls under gravity, lowest y = " + lowest[0]);
    }

    /** Verlet reuses its end-of-step force only when that is exact: results equal to recomputing it. */
    @Test
    void verletForceReuseIsExact() {
        Topology t = new Topology();
        Node a = t.addNode(0, 0, 0, 1).fix();
        Node b = t.addNode(1.1, 0.2, 0, 1);
        t.addSpring(a, b, 100, 0);
        SystemState s1 = SystemState.compile(t);
        SystemState s2 = SystemState.compile(t);
        Simulation reusing = new Simulation(s1, new VelocityVerlet());
        Simulation fresh = new Simulation(s2, new VelocityVerlet());
        for (int i = 0; i < 500; i++) {
            reusing.step(1e-3);
            fresh.setIntegrator(new VelocityVerlet()); // a new instance has nothing to reuse
            fresh.step(1e-3);
        }
        assertEquals(s2.x[3], s1.x[3], 1e-14);
        assertEquals(s2.v[4], s1.v[4], 1e-14);
        assertEquals(500 + 1, reusing.forces().evaluations(), "one force pass per step plus the first");
        assertEquals(1000, fresh.forces().evaluations());
    }

    @Test
    void implicitEulerSolvesItsSystemToTolerance() {
        Topology t = org.tensim.scene.LatticeScene.build(4, 0.1, 1, 1000, 0.5, false);
        SystemState s = SystemState.compile(t);
        ImplicitEuler ie = new ImplicitEuler();
        Simulation sim = new Simulation(s, ie);
        sim.runUntil(0.05, 5e-3); // w_max h about 1: well beyond any explicit limit
        assertEquals(0, ie.unconvergedSolves());
        assertTrue(ie.lastRelativeResidual() <= ImplicitEuler.DEFAULT_TOLERANCE, "residual " + ie.lastRelativeResidual());
        assertTrue(ie.lastIterations() > 1, "a real solve: " + ie.lastIterations() + " CG iterations");
    }

    /**
     * A fixed node under an infinite force (a mis-set load, a spring at a singular
     * length) must not turn into 0 * inf = NaN in any integrator: fixed nodes are not
     * integrated, so the free node and the fixed one stay finite.
     */
    @ParameterizedTest
    @MethodSource("names")
    void anInfiniteForceOnAFixedNodeDoesNotPoisonTheState(String name) {
        Topology t = new Topology();
        Node fixed = t.addNode(0, 0, 0, 1).fix();
        Node free = t.addNode(1.1, 0, 0, 1);
        t.addSpring(fixed.id(), free.id(), 100, 1.0, 0.5); // stretched by 0.1 m
        t.applyForce(fixed, (time, f, o) -> f[o + 1] += Double.POSITIVE_INFINITY);
        SystemState s = SystemState.compile(t);
        Simulation sim = new Simulation(s, Integrators.create(name));
        sim.setWarningSink(m -> { });
        sim.runUntil(0.1, 1e-3);
        for (int k = 0; k < 6; k++) {
            assertTrue(Double.isFinite(s.x[k]) && Double.isFinite(s.v[k]), name + ": coordinate " + k + " x = "
                    + s.x[k] + ", v = " + s.v[k]);
        }
        assertEquals(0, s.x[0], 0);
        assertEquals(0, s.x[1], 0);
        assertEquals(0, s.v[1], 0);
        assertTrue(Math.abs(s.x[3] - 1.0) <= 0.1 && s.x[3] < 1.09, name + ": the free node swings about its rest"
                + " length 1 m, x = " + s.x[3]);
    }

    /**
     * Every registered method describes its linear stability, or is implicit (then
     * taken as unconditionally stable): its undamped limit must agree with its own
     * step formula (bounded just below the limit, growing just above; 0 = growing at
     * w h = 0.01; infinite = bounded at w h = 1000).
     */
    @ParameterizedTest
    @MethodSource("names")
    void stabilityLimitAgreesWithTheStepFormula(String name) {
        Integrator in = Integrators.create(name);
        LinearStability st = in.stability();
        if (st == null) {
            assertTrue(!in.explicit(), name + ": an explicit method must describe its stability");
            assertEquals(Double.POSITIVE_INFINITY, in.undampedStabilityLimit(), name);
            return;
        }
        double limit = st.undampedLimit();
        assertEquals(limit, in.undampedStabilityLimit(), 0, name);
        if (limit == 0) {
            assertTrue(!StabilityTheory.stable(st, 1e-2, 0), name + " grows at w h = 0.01");
        } else if (limit == Double.POSITIVE_INFINITY) {
            assertTrue(StabilityTheory.stable(st, 1e3, 0), name + " bounded at w h = 1000");
        } else {
            assertTrue(StabilityTheory.stable(st, 0.999 * limit, 0), name + " bounded just below " + limit);
            assertTrue(!StabilityTheory.stable(st, 1.001 * limit, 0), name + " grows just above " + limit);
        }
    }

    /** Computed from the tableaux' stability polynomials: the textbook values, RK4's to the last bit. */
    @Test
    void undampedLimitsComputedFromTheTableaux() {
        assertEquals(0, ExplicitEuler.TABLEAU.undampedLimit());
        assertEquals(0, Heun.TABLEAU.undampedLimit());
        assertEquals(0, MidpointRK2.TABLEAU.undampedLimit());
        assertEquals(2 * Math.sqrt(2), RK4.TABLEAU.undampedLimit(), 0);
        assertEquals("1/24", RK4.TABLEAU.stabilityPolynomial().coefficient(4).toString());
    }

    /** The hand-fused paper's RK2 is the generic tableau loop, bit for bit (on a damped, driven, loaded lattice). */
    @Test
    void handFusedRk2IsTheMidpointTableau() {
        Topology t = org.tensim.solver.parallel.ParallelIntegratorsTest.scene();
        Simulation fused = new Simulation(SystemState.compile(t), new MidpointRK2());
        Simulation generic = new Simulation(SystemState.compile(t), new ExplicitRungeKutta("rk2", 2,
                MidpointRK2.TABLEAU));
        fused.runUntil(0.05, 1e-3);
        generic.runUntil(0.05, 1e-3);
        assertArrayEquals(fused.state().x, generic.state().x);
        assertArrayEquals(fused.state().v, generic.state().v);
    }
}

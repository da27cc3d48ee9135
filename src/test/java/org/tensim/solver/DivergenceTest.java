package org.tensim.solver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.io.CsvWriter;
import org.tensim.scene.CubeParameters;
import org.tensim.scene.CubeScene;
import org.tensim.scene.SpringScene;
import org.tensim.solver.integrators.Integrators;

/** Divergence detection: non-finite states and energy growth stop the run with a useful message. */
class DivergenceTest {
    @Test
    void energyGrowthStopsTheRunBeforeOverflowNamingStepTimeNodeAndEstimate(@TempDir Path dir) throws IOException {
        // Symplectic Euler at w h = 2.5: |lambda| about 4 per step, energy x16 per step.
        SystemState s = SystemState.compile(SpringScene.build(10, 0, 1e-6));
        Simulation sim = new Simulation(s, Integrators.create("symplectic-euler"));
        sim.setWarningSink(m -> { }).setRunawayLimit(Double.POSITIVE_INFINITY);
        Path csv = dir.resolve("run.csv");
        try (CsvWriter w = new CsvWriter(csv, List.of("t_s", "x_m", "v_m_s"), 1)) {
            sim.addListener(x -> {
                try {
                    w.row(x.time(), x.state().x[3], x.state().v[3]);
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            });
            SimulationDivergedException e = assertThrows(SimulationDivergedException.class,
                    () -> sim.runUntil(100, 0.25));
            String m = e.getMessage();
            assertTrue(m.contains("energy grew"), m);
            assertTrue(m.contains("step " + e.step()) && m.contains("t = " + e.timeSeconds() + " s"), m);
            assertTrue(m.contains("node 1"), "the moving node is the worst: " + m);
            assertTrue(m.contains("critical time step estimate is 0.2 s"), m);
            assertEquals(0.2, e.criticalStepSeconds(), 1e-12);
            assertTrue(Double.isFinite(s.x[3]), "stopped before the numbers overflowed");
        }
        List<String> lines = Files.readAllLines(csv);
        assertEquals(sim.steps(), lines.size(), "header + every completed step but the one that diverged");
        for (String line : lines.subList(1, lines.size())) {
            for (String cell : line.split(",")) {
                assertTrue(Double.isFinite(Double.parseDouble(cell)), "readable, finite row: " + line);
            }
        }
    }

    @Test
    void nonFiniteStateIsReportedWithItsNode() {
        SystemState s = SystemState.compile(SpringScene.build(10, 0, 0.01));
        Simulation sim = new Simulation(s, Integrators.create("rk4"));
        sim.setWarningSink(m -> { }).apply(sim.settings().withEnergyCheck(Double.POSITIVE_INFINITY, sim.settings().energyCheckInterval()));
        SimulationDivergedException e = assertThrows(SimulationDivergedException.class, () -> sim.runUntil(1e9, 5));
        assertEquals(1, e.node());
        assertTrue(e.getMessage().contains("critical time step estimate"), e.getMessage());
    }

    /**
     * An infinity or a NaN anywhere, in a position or a velocity, on any axis of any node (the
     * last one included), stops the run after that step and names its node.
     */
    @Test
    void aSingleNonFiniteCoordinateAnywhereIsFound() {
        int n = 7;
        for (int node = 0; node < n; node++) {
            for (int axis = 0; axis < 3; axis++) {
                for (double bad : new double[] {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY}) {
                    for (boolean velocity : new boolean[] {false, true}) {
                        org.tensim.model.Topology t = new org.tensim.model.Topology();
                        for (int i = 0; i < n; i++) {
                            t.addNode(i, 0, 0, 1); // free, unconnected: nothing spreads the bad value
                        }
                        SystemState s = SystemState.compile(t);
                        Simulation sim = new Simulation(s, Integrators.create("symplectic-euler"));
                        sim.setWarningSink(m -> { }).apply(sim.settings().withEnergyCheck(Double.POSITIVE_INFINITY, sim.settings().energyCheckInterval()));
                        sim.step(0.01); // a clean step passes
                        (velocity ? s.v : s.x)[3 * node + axis] = bad;
                        SimulationDivergedException e = assertThrows(SimulationDivergedException.class,
                                () -> sim.step(0.01), "node " + node + " axis " + axis + " " + bad);
                        assertEquals(node, e.node(), e.getMessage());
                    }
                }
            }
        }
    }

    /**
     * The per-step runaway check stops an unstable run at the first step where a node moves more
     * than 10 scene sizes in one step: every row written before it is within that range, and the
     * run stops within a few steps of leaving the physical range, where the energy check (every 100
     * steps) let it run on to 1e10 m.
     */
    @Test
    void aRunawayStopsTheRunAtThatStep(@TempDir Path dir) throws IOException {
        SystemState s = SystemState.compile(SpringScene.build(10, 0, 1e-6)); // w = 10 rad/s, one 1 m spring
        Simulation sim = new Simulation(s, Integrators.create("symplectic-euler"));
        sim.setWarningSink(m -> { }).apply(sim.settings().withEnergyCheck(Double.POSITIVE_INFINITY, sim.settings().energyCheckInterval()));
        double dt = 0.25; // w h = 2.5: |lambda| about 4 per step
        double size = 1; // the spring's rest length: the largest of the scene's sizes
        double[] worst = {0};
        long[] lastGood = {0};
        sim.addListener(x -> {
            worst[0] = Math.max(worst[0], Math.abs(x.state().v[3]) * dt);
            lastGood[0] = x.steps();
        });
        SimulationDivergedException e = assertThrows(SimulationDivergedException.class, () -> sim.runUntil(1e4, dt));
        assertTrue(e.getMessage().contains("ran away") && e.getMessage().contains("node 1"), e.getMessage());
        assertTrue(worst[0] <= DivergenceMonitor.DEFAULT_RUNAWAY_LIMIT * size,
                "every completed step stayed within 10 scene sizes per step: " + worst[0]);
        assertEquals(lastGood[0] + 1, e.step(), "stopped at the very step that ran away");
        assertTrue(e.step() < 20, "a |lambda| = 4 blow-up from 1e-6 m crosses 10 m/step within 20 steps, got "
                + e.step());
    }

    /** A long free fall (gravity, no spring) is not a runaway: it moves far, but not scene sizes per step. */
    @Test
    void aLongFreeFallIsNotARunaway() {
        org.tensim.model.Topology t = new org.tensim.model.Topology();
        t.addNode(0, 0, 0, 1);
        t.addNode(0.1, 0, 0, 1);
        t.setGravity(new org.tensim.model.Vec3(0, -9.81, 0));
        Simulation sim = new Simulation(SystemState.compile(t), Integrators.create("rk2"));
        sim.runUntil(10, 1e-3);
        assertEquals(-0.5 * 9.81 * 100, sim.state().x[1], 0.01, "490 m down, 4,900 times the scene's size");
    }

    @Test
    void growthLimitIsValidated() {
        Simulation sim = new Simulation(SystemState.compile(SpringScene.build(10, 0, 0.01)));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> sim.apply(sim.settings().withEnergyCheck(0.5, 100)));
        assertTrue(e.getMessage().contains("0.5"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> sim.apply(sim.settings().withEnergyCheck(100, 0)));
        assertThrows(IllegalArgumentException.class, () -> sim.setRunawayLimit(0));
    }

    /** The forced, damped paper cubes gain energy from their load, legitimately: no false alarm. */
    @Test
    void drivenCubesAreNotMistakenForDivergence() {
        CubeParameters p = CubeParameters.paper();
        for (boolean rigid : new boolean[] {false, true}) {
            Simulation sim = new Simulation(SystemState.compile(CubeScene.build(p, rigid).topology));
            sim.apply(sim.settings().withStepLimitSeverity(Severity.ERROR).withProjectionFailureSeverity(Severity.ERROR));
            sim.runUntil(p.durationS(), p.dtS());
            assertEquals(p.steps(), sim.steps());
        }
    }

    /**
     * A slow runaway: a free node drifting at a constant 0.015 m/s keeps its energy and is never fast, so
     * neither the energy nor the speed check stops it; a displacement limit of 1 m does, at the first check
     * after it is crossed (the check runs every energy-check interval, 100 steps of 1 s here: 1.5 m at step
     * 100), naming the node and its distance. Without a limit the same run goes on.
     */
    @Test
    void aSlowRunawayIsStoppedByTheScenesDisplacementLimit() {
        for (boolean limited : new boolean[] {false, true}) {
            org.tensim.model.Topology t = new org.tensim.model.Topology();
            t.addNode(0, 0, 0, 1);
            t.addNode(1, 0, 0, 1);
            SystemState s = SystemState.compile(t);
            Simulation sim = new Simulation(s, Integrators.create("symplectic-euler"));
            sim.setWarningSink(m -> { });
            s.v[3] = 0.015;
            if (!limited) {
                sim.runUntil(300, 1);
                assertTrue(s.x[3] > 4, "no check stops a slow drift by default: " + s.x[3]);
                continue;
            }
            sim.setDisplacementLimit(1);
            SimulationDivergedException e = assertThrows(SimulationDivergedException.class, () -> sim.runUntil(300, 1));
            assertEquals(1, e.node());
            assertEquals(0, e.step() % sim.settings().energyCheckInterval(), "stopped at a check: " + e.step());
            assertTrue(s.x[3] > 1 && s.x[3] < 1 + 0.015 * sim.settings().energyCheckInterval() + 1e-9,
                    "at the first check after the bound was crossed: " + s.x[3]);
            assertTrue(e.getMessage().contains("went astray") && e.getMessage().contains("bound of 1.0 m"),
                    e.getMessage());
        }
        assertThrows(IllegalArgumentException.class, () -> Simulation.of(new org.tensim.model.Topology())
                .setDisplacementLimit(0));
    }
}

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
        sim.setWarningSink(m -> { });
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
        sim.setWarningSink(m -> { }).setEnergyGrowthLimit(Double.POSITIVE_INFINITY);
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
                        sim.setWarningSink(m -> { }).setEnergyGrowthLimit(Double.POSITIVE_INFINITY);
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

    @Test
    void growthLimitIsValidated() {
        Simulation sim = new Simulation(SystemState.compile(SpringScene.build(10, 0, 0.01)));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> sim.setEnergyGrowthLimit(0.5));
        assertTrue(e.getMessage().contains("0.5"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> sim.setEnergyCheckInterval(0));
    }

    /** The forced, damped paper cubes gain energy from their load, legitimately: no false alarm. */
    @Test
    void drivenCubesAreNotMistakenForDivergence() {
        CubeParameters p = CubeParameters.paper();
        for (boolean rigid : new boolean[] {false, true}) {
            Simulation sim = new Simulation(SystemState.compile(CubeScene.build(p, rigid).topology));
            sim.setStepLimitSeverity(Severity.ERROR).setProjectionFailureSeverity(Severity.ERROR);
            sim.runUntil(p.durationS(), p.dtS());
            assertEquals(p.steps(), sim.steps());
        }
    }
}

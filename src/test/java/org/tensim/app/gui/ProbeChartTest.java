package org.tensim.app.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tensim.solver.Simulation;
import org.tensim.scene.tunable.Body;
import org.tensim.scene.tunable.ProbeRecorder;

/** The live chart keeps drawing whatever the probe does (headless: XChart draws into an image). */
class ProbeChartTest {
    /** A probe driven along -z by a given law of time, for exact chart data. */
    static Body body(org.tensim.model.Motion m) {
        org.tensim.model.Topology t = new org.tensim.model.Topology();
        t.addNode(0, 0, 0, 1).drive(m);
        return new Body("probe", Simulation.of(t), new int[0], null, org.tensim.model.Vec3.ZERO, 0);
    }

    @Test
    void nanometreDisplacementsDoNotHangTheChart() {
        // Probes that have barely moved: once sent XChart's tick search into an endless loop (it depends on
        // the fonts, so several spans and signs are drawn). A guard against a hang, not a speed check.
        Body b = body((time, rest, out, o) -> {
            out[o] = 0;
            out[o + 1] = 0;
            out[o + 2] = 0;
        });
        assertTimeoutPreemptively(Duration.ofSeconds(90), () -> {
            for (int k = 3; k <= 14; k++) {
                for (double sign : new double[] {-1, 1}) {
                    ProbeChart chart = new ProbeChart(2);
                    chart.attach(new ProbeRecorder(List.of(b), 0.005, 64), List.of(b));
                    double span = sign * Math.pow(10, -k);
                    chart.add(0, new double[][] {{0, 0, 0}});
                    chart.add(0.005030265760472356, new double[][] {{0, 0, span * 0.0088}});
                    chart.add(0.010060531520944714, new double[][] {{0, 0, span}});
                    chart.redraw();
                    assertEquals(span, chart.latest(0), 0);
                    assertTrue(chart.render().getWidth() > 100);
                }
            }
        });
    }

    @Test
    void magnitudeAndComponentsAreCharted() {
        Body b = body((time, rest, out, o) -> {
            out[o] = 3 * time;
            out[o + 1] = 4 * time;
            out[o + 2] = 0;
        });
        ProbeRecorder r = new ProbeRecorder(List.of(b), 0.01, 64);
        b.simulation().addListener(r);
        ProbeChart chart = new ProbeChart(1);
        chart.attach(r, List.of(b));
        for (int i = 0; i < 10; i++) {
            b.simulation().step(0.01);
        }
        chart.refresh();
        assertEquals(0.4, chart.latest(0), 1e-9, "y at t = 0.1 s");
        chart.setAxis(3);
        assertEquals(0.5, chart.latest(0), 1e-9, "|d| = 5 t");
        chart.setAxis(0);
        assertEquals(0.3, chart.latest(0), 1e-9);
    }
}

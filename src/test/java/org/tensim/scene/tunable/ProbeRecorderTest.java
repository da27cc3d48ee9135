package org.tensim.scene.tunable;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tensim.solver.Simulation;

class ProbeRecorderTest {
    @Test
    void samplesAtTheIntervalInOrderWithTheProbeDisplacement() {
        Simulation s = FrameBufferTest.clockScene(2);
        ProbeRecorder r = new ProbeRecorder(List.of(FrameBufferTest.body(s)), 0.1, 64);
        s.addListener(r);
        for (int i = 0; i < 100; i++) {
            s.step(0.01);
        }
        List<double[]> got = new ArrayList<>();
        r.drain((t, d) -> got.add(new double[] {t, d[0][0], d[0][1], d[0][2]}));
        assertEquals(11, got.size(), "t = 0, 0.1, ..., 1.0");
        for (int i = 0; i < got.size(); i++) {
            double[] g = got.get(i);
            assertEquals(0.1 * i, g[0], 1e-9);
            // Node 0 is driven to (t, t, t) from the origin: displacement is (t, t, t).
            assertEquals(g[0], g[1], 1e-12);
            assertEquals(g[0], g[3], 1e-12);
        }
        List<Double> again = new ArrayList<>();
        r.drain((t, d) -> again.add(t));
        assertEquals(List.of(), again, "drained samples are not repeated");
    }

    @Test
    void aSlowReaderLosesTheOldestSamplesOnly() {
        Simulation s = FrameBufferTest.clockScene(1);
        ProbeRecorder r = new ProbeRecorder(List.of(FrameBufferTest.body(s)), 0.5, 4);
        s.addListener(r);
        for (int i = 0; i < 10; i++) {
            s.step(0.5);
        }
        List<Double> times = new ArrayList<>();
        r.drain((t, d) -> times.add(t));
        // 11 samples (t = 0 to 5) in a ring of 4: the newest 3 are readable (one slot is kept
        // between writer and reader), the older ones are gone.
        assertEquals(List.of(4.0, 4.5, 5.0), times);
    }
}

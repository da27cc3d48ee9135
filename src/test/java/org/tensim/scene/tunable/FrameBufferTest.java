package org.tensim.scene.tunable;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.solver.Simulation;

/** The scene graph's hand-over: whole frames only, newest first, never a torn one. */
class FrameBufferTest {
    /**
     * Nodes driven so that every coordinate equals the simulated time: in a whole
     * frame every value equals the frame's time; a torn frame would mix two steps.
     */
    static Simulation clockScene(int nodes) {
        Topology t = new Topology();
        for (int i = 0; i < nodes; i++) {
            t.addNode(0, 0, 0, 1).drive((time, rest, out, o) -> {
                out[o] = time;
                out[o + 1] = time;
                out[o + 2] = time;
            });
        }
        return Simulation.of(t);
    }

    static Body body(Simulation s) {
        return new Body("clock", s, new int[0], null, Vec3.ZERO, 0);
    }

    @Test
    void readerNeverSeesAHalfUpdatedFrame() throws Exception {
        Simulation s = clockScene(300);
        FrameBuffer fb = new FrameBuffer(List.of(body(s)));
        s.addListener(fb);
        AtomicReference<String> torn = new AtomicReference<>();
        AtomicLong frames = new AtomicLong();
        Thread reader = new Thread(() -> {
            double last = -1;
            while (!Thread.currentThread().isInterrupted() && torn.get() == null) {
                FrameBuffer.Frame f = fb.takeNewer();
                if (f == null) {
                    Thread.onSpinWait();
                    continue;
                }
                float expect = (float) f.time;
                for (float v : f.positions[0]) {
                    if (v != expect) {
                        torn.set("frame at t = " + f.time + " holds " + v);
                        break;
                    }
                }
                if (f.time < last) {
                    torn.set("frames went back in time: " + f.time + " after " + last);
                }
                last = f.time;
                frames.incrementAndGet();
            }
        });
        reader.start();
        for (int i = 0; i < 5000; i++) {
            s.step(1.0 / 1024); // exact in float and double
        }
        reader.interrupt();
        reader.join(10000);
        assertNull(torn.get());
        assertTrue(frames.get() > 0, "the reader got frames");
    }

    @Test
    void takesTheNewestFrameOnceAndNullWhenNothingIsNew() {
        Simulation s = clockScene(3);
        FrameBuffer fb = new FrameBuffer(List.of(body(s)));
        s.addListener(fb);
        assertNull(fb.takeNewer(), "nothing published yet");
        s.step(0.25);
        s.step(0.25);
        s.step(0.25);
        FrameBuffer.Frame f = fb.takeNewer();
        assertEquals(0.75, f.time);
        assertEquals(3, f.step);
        assertEquals(0.75f, f.positions[0][7]);
        assertNull(fb.takeNewer(), "already taken");
        s.step(0.25);
        assertEquals(1.0, fb.takeNewer().time);
    }
}

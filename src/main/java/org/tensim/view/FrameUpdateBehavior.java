package org.tensim.view;

import org.tensim.scene.tunable.FrameBuffer;
import java.util.Iterator;
import java.util.List;
import org.jogamp.java3d.Behavior;
import org.jogamp.java3d.WakeupCriterion;
import org.jogamp.java3d.WakeupOnElapsedFrames;

/**
 * Copies the newest simulation frame into the by-reference geometry. It wakes up
 * every other frame ({@code WakeupOnElapsedFrames(1)}), never every frame: Java3D
 * 1.7.2's update thread sometimes dies with a NullPointerException when
 * by-reference geometry is updated on every frame (docs/gui.md, "How it works"), which
 * freezes the view. Frames published in between are skipped, never torn: the
 * {@link FrameBuffer} hands over whole frames only.
 */
final class FrameUpdateBehavior extends Behavior {
    private final WakeupOnElapsedFrames everyOtherFrame = new WakeupOnElapsedFrames(1);
    private final FrameBuffer buffer;
    private final List<BodyShapes> shapes;
    private volatile double shownTime;
    private volatile long shownStep;

    FrameUpdateBehavior(FrameBuffer buffer, List<BodyShapes> shapes) {
        this.buffer = buffer;
        this.shapes = shapes;
    }

    @Override
    public void initialize() {
        wakeupOn(everyOtherFrame);
    }

    @Override
    public void processStimulus(Iterator<WakeupCriterion> criteria) {
        FrameBuffer.Frame f = buffer.takeNewer();
        if (f != null) {
            int marked = buffer.live() == null ? -1 : buffer.live().body();
            for (int b = 0; b < shapes.size(); b++) {
                shapes.get(b).update(f.positions[b], b == marked ? f.marks : null);
            }
            shownTime = f.time;
            shownStep = f.step;
        }
        wakeupOn(everyOtherFrame);
    }

    /** Simulated time of the frame on screen, s. */
    double shownTime() {
        return shownTime;
    }

    /** Step count of the frame on screen. */
    long shownStep() {
        return shownStep;
    }
}

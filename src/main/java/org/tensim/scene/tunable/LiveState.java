package org.tensim.scene.tunable;

import java.util.List;
import org.tensim.solver.Simulation;

/**
 * What a scene shows of its running state beside the positions: a mark per node of one body, drawn in the mark's
 * colour over the body's own (e.g. the nodes touching a bone this step), and a few figures (readouts, e.g. the descent
 * of each dome). {@link #measure} is called on the simulation thread after every step, from the state the step left,
 * into buffers handed to the view and the window with the positions ({@link FrameBuffer}): it must not allocate and
 * must not change the model.
 */
public interface LiveState {
    /** A mark with its colour, or a colour of the body's own, for the legend. */
    record Legend(String label, float[] rgb) {
    }

    /**
     * A figure shown beside the view.
     *
     * @param label for people
     * @param unit  its unit ({@code mm}, {@code mm^2}, {@code %})
     * @param key   its name in a summary, as the headless run's where it has one (e.g. {@code right_dome_descent_mm})
     */
    record Readout(String label, String unit, String key) {
    }

    /** Index of the body whose nodes are marked (in {@link ViewScene#bodies()}). */
    int body();

    /**
     * The colours of marks 1, 2, ... (index 0, "no mark", is unused: such nodes keep the body's own colour), RGB in
     * [0, 1].
     */
    float[][] markColours();

    /** What each colour of the drawing means, the body's own and the marks', in the order shown. */
    List<Legend> legend();

    /** The figures {@link #measure} writes, in order. */
    List<Readout> readouts();

    /**
     * Marks the body's nodes (0: none, k: colour k of {@link #markColours()}; one byte per node) and writes the
     * readouts, from the state after a step. Simulation thread; no allocation.
     */
    void measure(Simulation sim, byte[] marks, double[] readouts);

    /**
     * The colours to draw: the body's own where a node has no mark, the mark's colour where it has one (3 floats per
     * node into {@code out}). For the view, on its own thread; allocation-free.
     */
    static void paint(float[] own, byte[] marks, float[][] markColours, float[] out) {
        int n = out.length / 3;
        for (int i = 0; i < n; i++) {
            int m = marks == null || i >= marks.length ? 0 : marks[i];
            float[] c = m > 0 && m < markColours.length ? markColours[m] : null;
            for (int k = 0; k < 3; k++) {
                out[3 * i + k] = c != null ? c[k] : own[3 * i + k];
            }
        }
    }
}

package org.tensim.sweep;

import java.io.Serializable;
import java.util.Map;

/**
 * An extra measurement taken during each run of a sweep (e.g. the distance of the
 * diaphragm to a target surface at one breathing phase). A measure is a serializable
 * description shipped to the workers; {@link #start} makes the stateful probe of one run.
 */
public interface Measure extends Serializable {
    /** A fresh probe for one run of the diaphragm scene. */
    Probe start(DiaphragmRunView run);

    /** Observes one run. */
    interface Probe {
        /** Called at t = 0 and after every step with the simulated time (s) and positions (m). */
        void afterStep(double t, double[] x);

        /** Adds this probe's fields to the run's summary (called once, also after a divergence). */
        void finish(Map<String, Double> fields);
    }

    /**
     * What a probe may read of the run: rest positions and the diaphragm's surface.
     *
     * @param rest           positions at rest, m (3 per node)
     * @param diaphragmNodes nodes 0 .. diaphragmNodes-1 are the diaphragm's mesh vertices
     * @param triangles      the diaphragm's triangles (both faces), as node ids
     * @param upper          for each diaphragm node, whether it is on the upper (thoracic) face
     */
    record DiaphragmRunView(double[] rest, int diaphragmNodes, int[] triangles, boolean[] upper) {
    }
}

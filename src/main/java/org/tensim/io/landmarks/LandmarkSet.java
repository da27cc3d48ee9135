package org.tensim.io.landmarks;

import java.util.List;

/**
 * Landmarks followed over phases of the breath: the same anatomical points, each at every phase.
 *
 * @param name      what the set is, e.g. {@code case1 300 ee-ei} (for reports)
 * @param ids       each landmark's number in its file
 * @param phases    the phases' names in file order, e.g. {@code [ee, ei]} or {@code [t00, ..., t50]}
 * @param positions positions by phase, then landmark: {@code positions[p][3 i + a]}, m, in the scan's frame
 * @param superior  unit vector of the frame pointing to the head (DIR-Lab: {@code (0, 0, -1)}, its z increasing
 *                  towards the feet)
 */
public record LandmarkSet(String name, int[] ids, List<String> phases, double[][] positions, double[] superior) {
    public LandmarkSet {
        if (positions.length != phases.size()) {
            throw new IllegalArgumentException(name + ": " + positions.length + " position sets for " + phases.size()
                    + " phases");
        }
        for (double[] p : positions) {
            if (p.length != 3 * ids.length) {
                throw new IllegalArgumentException(name + ": " + p.length / 3 + " positions for " + ids.length
                        + " landmarks");
            }
        }
        double n = Math.sqrt(superior[0] * superior[0] + superior[1] * superior[1] + superior[2] * superior[2]);
        if (Math.abs(n - 1) > 1e-12) {
            throw new IllegalArgumentException(name + ": the superior direction must be a unit vector, got length "
                    + n);
        }
        ids = ids.clone();
        phases = List.copyOf(phases);
        superior = superior.clone();
    }

    /** Number of landmarks. */
    public int count() {
        return ids.length;
    }

    /** Index of the phase named {@code phase}; refused, naming the phases there are, when absent. */
    public int phase(String phase) {
        int p = phases.indexOf(phase);
        if (p < 0) {
            throw new IllegalArgumentException(name + " has no phase '" + phase + "': its phases are " + phases);
        }
        return p;
    }

    /** The positions at the named phase, m ({@code 3 i + a}; a copy). */
    public double[] at(String phase) {
        return positions[phase(phase)].clone();
    }

    /** Displacements from phase {@code from} to phase {@code to}, m, landmark by landmark ({@code 3 i + a}). */
    public double[] displacement(String from, String to) {
        double[] a = positions[phase(from)];
        double[] b = positions[phase(to)];
        double[] d = new double[a.length];
        for (int k = 0; k < d.length; k++) {
            d[k] = b[k] - a[k];
        }
        return d;
    }

    /** Mean of the landmarks' 3D displacement lengths from {@code from} to {@code to}, m. */
    public double meanDisplacement(String from, String to) {
        double[] d = displacement(from, to);
        double sum = 0;
        for (int i = 0; i < ids.length; i++) {
            sum += Math.sqrt(d[3 * i] * d[3 * i] + d[3 * i + 1] * d[3 * i + 1] + d[3 * i + 2] * d[3 * i + 2]);
        }
        return sum / ids.length;
    }

    /** Standard deviation (n - 1) of the displacement lengths from {@code from} to {@code to}, m. */
    public double displacementSd(String from, String to) {
        double[] d = displacement(from, to);
        double mean = meanDisplacement(from, to);
        double ss = 0;
        for (int i = 0; i < ids.length; i++) {
            double l = Math.sqrt(d[3 * i] * d[3 * i] + d[3 * i + 1] * d[3 * i + 1] + d[3 * i + 2] * d[3 * i + 2]);
            ss += (l - mean) * (l - mean);
        }
        return Math.sqrt(ss / (ids.length - 1));
    }

    /** The largest displacement length from {@code from} to {@code to}, m. */
    public double maxDisplacement(String from, String to) {
        double[] d = displacement(from, to);
        double max = 0;
        for (int i = 0; i < ids.length; i++) {
            max = Math.max(max, Math.sqrt(d[3 * i] * d[3 * i] + d[3 * i + 1] * d[3 * i + 1]
                    + d[3 * i + 2] * d[3 * i + 2]));
        }
        return max;
    }
}

package org.tensim.scene.diaphragm;

import java.util.Arrays;
import java.util.HashSet;
import java.util.Set;
import org.tensim.model.Topology;

/**
 * Springs collected before they are added to the topology (package-private): the
 * axial damping of every spring depends on the highest frequency of the whole
 * network, known only once all springs are there. Duplicate node pairs are refused
 * silently (the first one wins).
 */
final class SpringList implements ShellNetwork.Sink {
    private int[] a = new int[1024];
    private int[] b = new int[1024];
    private double[] k = new double[1024];
    private int n;
    private final Set<Long> pairs = new HashSet<>();

    /** Adds a spring of stiffness k (N/m) between nodes i and j; returns false for a duplicate. */
    @Override
    public boolean add(int i, int j, double stiffness) {
        if (i == j || !pairs.add(key(i, j))) {
            return false;
        }
        if (n == a.length) {
            a = Arrays.copyOf(a, 2 * n);
            b = Arrays.copyOf(b, 2 * n);
            k = Arrays.copyOf(k, 2 * n);
        }
        a[n] = i;
        b[n] = j;
        k[n] = stiffness;
        n++;
        return true;
    }

    @Override
    public boolean contains(int i, int j) {
        return pairs.contains(key(i, j));
    }

    int size() {
        return n;
    }

    private static long key(int i, int j) {
        return ((long) Math.min(i, j) << 32) | Math.max(i, j);
    }

    /**
     * Gershgorin bound on the highest angular frequency, rad/s:
     * {@code w_max^2 <= max_i 2 sum_j k_ij / m_i} over the free nodes (PHYSICS.md).
     */
    double omegaMaxBound(Topology t, java.util.List<int[]> extraPairs, java.util.List<Double> extraK) {
        double[] sum = new double[t.nodeCount()];
        for (int s = 0; s < n; s++) {
            sum[a[s]] += k[s];
            sum[b[s]] += k[s];
        }
        for (int s = 0; s < extraPairs.size(); s++) {
            sum[extraPairs.get(s)[0]] += extraK.get(s);
            sum[extraPairs.get(s)[1]] += extraK.get(s);
        }
        double w2 = 0;
        for (int i = 0; i < sum.length; i++) {
            var node = t.node(i);
            if (!node.isFixed() && !node.isDriven()) {
                w2 = Math.max(w2, 2 * sum[i] / node.mass());
            }
        }
        return Math.sqrt(w2);
    }

    /** Adds every spring to t, rest length = current distance, axial damping beta * k (N s/m). */
    void addTo(Topology t, double betaS) {
        for (int s = 0; s < n; s++) {
            t.addSpring(t.node(a[s]), t.node(b[s]), k[s], betaS * k[s]);
        }
    }
}

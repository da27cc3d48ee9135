package org.tensim.scene.diaphragm;

import java.util.Arrays;
import java.util.HashSet;
import java.util.Set;
import org.tensim.model.Topology;
import org.tensim.solver.stability.CriticalTimeStep;

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
     * Gershgorin bound on the highest angular frequency of these springs and the
     * extra ones, rad/s: {@code w_max^2 <= max_i 2 sum_j k_ij / m_i} over the free
     * nodes ({@link CriticalTimeStep#gershgorin}, rows form; PHYSICS.md).
     */
    double omegaMaxBound(Topology t, java.util.List<int[]> extraPairs, java.util.List<Double> extraK) {
        int total = n + extraPairs.size();
        int[] sa = Arrays.copyOf(a, total);
        int[] sb = Arrays.copyOf(b, total);
        double[] sk = Arrays.copyOf(k, total);
        for (int s = 0; s < extraPairs.size(); s++) {
            sa[n + s] = extraPairs.get(s)[0];
            sb[n + s] = extraPairs.get(s)[1];
            sk[n + s] = extraK.get(s);
        }
        double[] mass = new double[t.nodeCount()];
        boolean[] free = new boolean[t.nodeCount()];
        for (int i = 0; i < mass.length; i++) {
            var node = t.node(i);
            mass[i] = node.mass();
            free[i] = !node.isFixed() && !node.isDriven();
        }
        return CriticalTimeStep.gershgorin(mass.length, sa, sb, sk, total, mass, free, CriticalTimeStep.Form.ROWS);
    }

    /** Adds every spring to t, rest length = current distance, axial damping beta * k (N s/m). */
    void addTo(Topology t, double betaS) {
        for (int s = 0; s < n; s++) {
            t.addSpring(t.node(a[s]), t.node(b[s]), k[s], betaS * k[s]);
        }
    }
}

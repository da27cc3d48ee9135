package org.tensim.scene.diaphragm;

import java.util.Arrays;
import java.util.HashSet;
import java.util.Set;
import org.tensim.model.Topology;
import org.tensim.scene.shell.ShellNetwork;
import org.tensim.solver.SystemState;
import org.tensim.solver.stability.CriticalTimeStep;
import org.tensim.solver.stability.ExtraStiffness;

/**
 * Springs and membrane triangles collected before they are added to the topology
 * (package-private): the damping of every spring and triangle depends on the highest
 * frequency of the whole network, known only once all of them are there. Duplicate
 * spring node pairs are refused silently (the first one wins).
 */
final class SpringList implements ShellNetwork.Sink {
    private int[] a = new int[1024];
    private int[] b = new int[1024];
    private double[] k = new double[1024];
    private int n;
    private final Set<Long> pairs = new HashSet<>();
    private final java.util.List<Triangle> triangles = new java.util.ArrayList<>();

    /** A membrane triangle waiting for its damping. */
    private record Triangle(int[] p, int[] q, double thicknessM, double youngPa, double poisson) {
    }

    /** A transverse shear element waiting for its damping. */
    private record Shear(int[] upper, int[] lower, double kappaGPa, double thicknessM) {
    }

    private final java.util.List<Shear> shears = new java.util.ArrayList<>();

    @Override
    public void shear(int[] upper, int[] lower, double kappaGPa, double thicknessM) {
        shears.add(new Shear(upper.clone(), lower.clone(), kappaGPa, thicknessM));
    }

    @Override
    public void triangle(int[] p, int[] q, double thicknessM, double youngPa, double poisson) {
        triangles.add(new Triangle(p.clone(), q.clone(), thicknessM, youngPa, poisson));
    }

    int triangleCount() {
        return triangles.size();
    }

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
     * Gershgorin bound on the highest angular frequency of these springs, triangles and the
     * extra springs, rad/s: {@code w_max^2 <= max_i 2 sum_j k_ij / m_i} over the free
     * nodes ({@link CriticalTimeStep#gershgorin}, rows form; docs/physics.md), a triangle's
     * 3 x 3 node blocks counted by their norms.
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
        return CriticalTimeStep.gershgorin(mass.length, sa, sb, sk, total, mass, free, CriticalTimeStep.Form.ROWS,
                triangleStiffness(t));
    }

    /** The triangles' and shear elements' stiffness at rest, on a copy of t's nodes (their own topology, compiled). */
    private ExtraStiffness triangleStiffness(Topology t) {
        if (triangles.isEmpty() && shears.isEmpty()) {
            return ExtraStiffness.NONE;
        }
        Topology copy = new Topology();
        for (var node : t.nodes()) {
            copy.addNode(node.position(), node.mass());
        }
        addElements(copy, 0);
        return SystemState.compile(copy).elementStiffness();
    }

    private void addElements(Topology t, double betaS) {
        for (Triangle tr : triangles) {
            t.addTriangle(tr.p, tr.q, tr.thicknessM, tr.youngPa, tr.poisson, betaS);
        }
        for (Shear sh : shears) {
            t.addShear(sh.upper, sh.lower, sh.kappaGPa, sh.thicknessM, betaS);
        }
    }

    /**
     * Adds every spring to t, rest length = current distance, axial damping beta * k (N s/m), and
     * every triangle and transverse shear element with the Kelvin-Voigt damping time beta (s).
     */
    void addTo(Topology t, double betaS) {
        for (int s = 0; s < n; s++) {
            t.addSpring(t.node(a[s]), t.node(b[s]), k[s], betaS * k[s]);
        }
        addElements(t, betaS);
    }
}

package org.tensim.model;

import java.util.Arrays;

/**
 * Points carried by the nodes of a model: fine point i is {@code p_i = sum_k w_ik x_{n(i,k)}}, a fixed weighted sum
 * of some of the model's node positions (SOFA's {@code BarycentricMapping}, ArtiSynth's embedded points). A lattice
 * carries an embedded surface with the trilinear weights of the cell each vertex lies in; a coarse shell can carry a
 * fine one with the barycentric weights of its triangles. The weights of every point sum to 1.
 *
 * <p>What the weights give, by linearity:
 * <ul>
 * <li>{@link #apply} maps positions and, with the same call, velocities (the weights are constant in time);</li>
 * <li>an affine motion of the nodes {@code x -> A x + b} moves every point by the same map, exactly, because the
 * weights sum to 1 (a point is an affine combination of its nodes);</li>
 * <li>{@link #addTranspose} carries forces on the points back to the nodes, {@code F_j += sum_i w_ij f_i}: the
 * nodal forces do on any nodal motion the work the point forces do on the mapped motion (virtual work). Their sum
 * equals the points' total force (weights summing to 1), and their moment about any origin, taken at the node
 * positions, equals the points' moment taken at the mapped positions, {@code sum_j x_j x F_j = sum_i p_i x f_i}.</li>
 * </ul>
 *
 * <p>The weights are stored row by row (compressed rows); {@link #apply} and {@link #addTranspose} read and write flat
 * arrays of 3 doubles per node or point and never allocate, so they can run at every step.
 */
public final class LinearMapping {
    /** A point's weights must sum to 1 within this (dimensionless). */
    public static final double WEIGHT_SUM_TOLERANCE = 1e-9;

    private final int nodeCount;
    private final int[] start;
    private final int[] node;
    private final double[] weight;

    /**
     * @param nodeCount the number of nodes of the model the indices refer to (node ids are in [0, nodeCount))
     * @param start     point i's entries are {@code start[i] .. start[i + 1] - 1}; length points + 1, non-decreasing,
     *                  {@code start[0] = 0}, {@code start[points] = node.length}
     * @param node      node id of each entry
     * @param weight    weight of each entry (dimensionless); a point's weights sum to 1 (may be negative: an
     *                  extrapolated point)
     * @throws IllegalArgumentException naming the point when its entries are empty, out of range or do not sum to 1
     */
    public LinearMapping(int nodeCount, int[] start, int[] node, double[] weight) {
        if (start.length < 1 || start[0] != 0 || start[start.length - 1] != node.length
                || node.length != weight.length) {
            throw new IllegalArgumentException("mapping rows must start at 0 and end at the entry count " + node.length
                    + " (weights: " + weight.length + "), got starts " + (start.length > 0 ? start[0] + ".."
                    + start[start.length - 1] : "none"));
        }
        this.nodeCount = Check.atLeast("mapping node count", nodeCount, 1);
        for (int i = 0; i + 1 < start.length; i++) {
            if (start[i + 1] <= start[i]) {
                throw new IllegalArgumentException("mapped point " + i + " has no node: every point needs at least"
                        + " one weight");
            }
            double sum = 0;
            for (int e = start[i]; e < start[i + 1]; e++) {
                Check.index("mapped point " + i + "'s node", node[e], nodeCount);
                Check.finite("mapped point " + i + "'s weight", "", weight[e]);
                sum += weight[e];
            }
            if (Math.abs(sum - 1) > WEIGHT_SUM_TOLERANCE) {
                throw new IllegalArgumentException("mapped point " + i + "'s weights sum to " + sum
                        + ": expected 1 (the mapping must carry a rigid motion exactly)");
            }
        }
        this.start = start.clone();
        this.node = node.clone();
        this.weight = weight.clone();
    }

    /**
     * Collects a mapping point by point (a coarse shell's barycentric weights, say), then {@link #build}s it,
     * checked as the constructor checks.
     */
    public static final class Builder {
        private final int nodeCount;
        private int[] start = new int[17];
        private int[] node = new int[64];
        private double[] weight = new double[64];
        private int points;

        /** @param nodeCount the number of nodes of the carrying model */
        public Builder(int nodeCount) {
            this.nodeCount = nodeCount;
        }

        /** Adds the next point on the given nodes with the given weights (summing to 1); returns its index. */
        public int add(int[] nodes, double[] weights) {
            if (nodes.length != weights.length) {
                throw new IllegalArgumentException("mapped point " + points + " has " + nodes.length + " nodes but "
                        + weights.length + " weights");
            }
            int at = start[points];
            if (at + nodes.length > node.length) {
                node = Arrays.copyOf(node, Math.max(2 * node.length, at + nodes.length));
                weight = Arrays.copyOf(weight, node.length);
            }
            System.arraycopy(nodes, 0, node, at, nodes.length);
            System.arraycopy(weights, 0, weight, at, weights.length);
            if (points + 2 > start.length) {
                start = Arrays.copyOf(start, 2 * start.length);
            }
            start[points + 1] = at + nodes.length;
            return points++;
        }

        /** The mapping of the points added. */
        public LinearMapping build() {
            int entries = start[points];
            return new LinearMapping(nodeCount, Arrays.copyOf(start, points + 1), Arrays.copyOf(node, entries),
                    Arrays.copyOf(weight, entries));
        }
    }

    /** Number of mapped (fine) points. */
    public int pointCount() {
        return start.length - 1;
    }

    /** Number of nodes of the carrying model. */
    public int nodeCount() {
        return nodeCount;
    }

    /** Number of nodes carrying point i. */
    public int entries(int point) {
        Check.index("mapped point", point, pointCount());
        return start[point + 1] - start[point];
    }

    /** Node id of point i's entry k. */
    public int node(int point, int k) {
        return node[entry(point, k)];
    }

    /** Weight of point i's entry k (dimensionless). */
    public double weight(int point, int k) {
        return weight[entry(point, k)];
    }

    /** Point i's entry k's index in the flat arrays; the refusal's message built only on a refusal (no allocation). */
    private int entry(int point, int k) {
        int n = entries(point);
        if (k < 0 || k >= n) {
            throw new IndexOutOfBoundsException("entry of mapped point " + point + " " + k
                    + " is out of range: expected 0 <= index < " + n);
        }
        return start[point] + k;
    }

    /**
     * Maps node values to the points: {@code out[3 i + a] = sum_k w_ik in[3 n(i,k) + a]}. For positions (m) and
     * velocities (m/s) alike.
     *
     * @param nodeValues  3 per node (length at least 3 nodeCount)
     * @param pointValues written, 3 per point (length at least 3 pointCount)
     */
    public void apply(double[] nodeValues, double[] pointValues) {
        for (int i = 0, n = pointCount(); i < n; i++) {
            double x = 0;
            double y = 0;
            double z = 0;
            for (int e = start[i]; e < start[i + 1]; e++) {
                int o = 3 * node[e];
                double w = weight[e];
                x += w * nodeValues[o];
                y += w * nodeValues[o + 1];
                z += w * nodeValues[o + 2];
            }
            pointValues[3 * i] = x;
            pointValues[3 * i + 1] = y;
            pointValues[3 * i + 2] = z;
        }
    }

    /**
     * Adds the points' forces to the nodes through the transpose: {@code nodeForces[3 j + a] += sum_i w_ij
     * pointForces[3 i + a]} (N). Adds, never overwrites, so that it can run inside a force pass.
     *
     * @param pointForces 3 per point, N
     * @param nodeForces  3 per node, N, added to
     */
    public void addTranspose(double[] pointForces, double[] nodeForces) {
        for (int i = 0, n = pointCount(); i < n; i++) {
            double fx = pointForces[3 * i];
            double fy = pointForces[3 * i + 1];
            double fz = pointForces[3 * i + 2];
            for (int e = start[i]; e < start[i + 1]; e++) {
                int o = 3 * node[e];
                double w = weight[e];
                nodeForces[o] += w * fx;
                nodeForces[o + 1] += w * fy;
                nodeForces[o + 2] += w * fz;
            }
        }
    }

    /** The mapped points of a model: {@link #apply} on its nodes' rest positions (m), 3 per point. */
    public double[] restPoints(Topology t) {
        if (t.nodeCount() < nodeCount) {
            throw new IllegalArgumentException("the mapping refers to " + nodeCount + " nodes but the topology has "
                    + t.nodeCount());
        }
        double[] x = new double[3 * nodeCount];
        for (int j = 0; j < nodeCount; j++) {
            Vec3 p = t.node(j).position();
            x[3 * j] = p.x();
            x[3 * j + 1] = p.y();
            x[3 * j + 2] = p.z();
        }
        double[] out = new double[3 * pointCount()];
        apply(x, out);
        return out;
    }

    @Override
    public String toString() {
        return "LinearMapping[" + pointCount() + " points on " + nodeCount + " nodes, " + node.length + " weights"
                + (pointCount() > 0 ? ", first row " + Arrays.toString(Arrays.copyOfRange(node, 0, start[1])) : "")
                + "]";
    }
}

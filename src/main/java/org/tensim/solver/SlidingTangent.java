package org.tensim.solver;

import org.tensim.model.LinearMapping;

/**
 * The tangent stiffness of {@link SurfaceSliding} for the implicit integrators' products: the Gauss-Newton part of
 * {@code K = -df/dx} at the pairing and planes of one linearisation.
 *
 * <p>With follower i's displacement {@code (V z)_i} (its node's, or its mapped point's) and the surface points'
 * {@code (W z)_p}, a paired follower (unit normal n, barycentric coordinates beta of its projection on triangle
 * (a, b, c), stiffness k) sees its distance change by {@code n . u}, {@code u = (V z)_i - sum_c beta_c (W z)_c}, so
 * <pre>
 *   (K z)_i  =  k n (n . u)            carried to the nodes by V^T
 *   (K z)_c  = -beta_c k n (n . u)     carried to the nodes by W^T
 * </pre>
 * the exact stiffness of the penalty along the normal with the plane's rotation and the projection's slide left out
 * (terms of order k pen / size, small against k while the followers stay near their gaps). It is symmetric and
 * positive semi-definite, so Newton-Krylov keeps a positive-definite system; the residual it solves is the exact
 * force, so leaving these terms out changes the iterations' count, not the answer. A CONTACT follower counts only
 * where it touches at the linearisation (pen &gt; 0, on the surface).
 *
 * <p>Merged rows: the three corners of a triangle are rows of W over neighbouring nodes (48 entries each on
 * average where the pleura's carriers are blended, docs/lungs.md), and most of their nodes are shared. At each
 * {@link #set} the follower's own row and the three corner rows are merged into one sparse row
 * {@code a_j = sum_c beta_c W_cj - V_ij} (one entry per node, in the order the nodes first appear), so that
 * {@code u = -sum_j a_j z_j} and the products walk one row once for the gather and once for the scatter rather than
 * four rows twice. The merged rows live in arrays sized once at construction to the largest sum of three corners'
 * row lengths over the triangles plus the longest follower row, so any triangle a follower walks to fits; a
 * node-to-slot scratch (one int per node of either mapping) finds a node's entry and is reset after each merge.
 * Allocation-free after construction.
 */
final class SlidingTangent {
    private final LinearMapping followers;
    private final double[] stiffness;
    private final LinearMapping mapping;
    private final SurfacePairing surface;
    private final int[] tri; // per follower: its triangle at the linearisation, -1 when it takes no force
    private final double[] normal; // 3 per follower
    private final int capacity; // entries of a merged row: the largest sum of a triangle's three row lengths
    private final int[] rowLength; // per follower: entries of its merged row
    private final int[] rowNode; // capacity per follower: node of each merged entry
    private final double[] rowCoef; // capacity per follower: a_j = sum_c beta_c W_cj (dimensionless)
    private final int[] slot; // per node of the mapping: its entry in the row being merged, -1 when none

    SlidingTangent(LinearMapping followers, double[] stiffness, LinearMapping mapping, SurfacePairing surface) {
        this.followers = followers;
        int count = followers.pointCount();
        this.stiffness = stiffness;
        this.mapping = mapping;
        this.surface = surface;
        this.tri = new int[count];
        java.util.Arrays.fill(tri, -1);
        this.normal = new double[3 * count];
        int own = 0;
        for (int e = 0; e < count; e++) {
            own = Math.max(own, followers.entries(e));
        }
        int widest = 0;
        for (int t = 0; t < surface.triangleCount(); t++) {
            int sum = 0;
            for (int c = 0; c < 3; c++) {
                sum += mapping.entries(surface.corner(t, c));
            }
            widest = Math.max(widest, sum);
        }
        this.capacity = widest + own;
        this.rowLength = new int[count];
        this.rowNode = new int[count * capacity];
        this.rowCoef = new double[count * capacity];
        this.slot = new int[Math.max(mapping.nodeCount(), followers.nodeCount())];
        java.util.Arrays.fill(slot, -1);
    }

    /**
     * Records follower e's plane for the products: its triangle {@code t} (or -1: no force at the linearisation) and
     * {@code plane} = (n, d, beta) as {@link SurfacePairing#plane} writes it; merges the triangle's three corner rows
     * weighted by beta into the follower's row.
     */
    void set(int e, int t, double[] plane) {
        tri[e] = t;
        final int base = e * capacity;
        int length = 0;
        for (int k = 0, m = followers.entries(e); k < m; k++) {
            length = merge(base, length, followers.node(e, k), -followers.weight(e, k));
        }
        if (t >= 0) {
            for (int a = 0; a < 3; a++) {
                normal[3 * e + a] = plane[a];
            }
            for (int c = 0; c < 3; c++) {
                final int p = surface.corner(t, c);
                final double b = plane[4 + c];
                for (int k = 0, m = mapping.entries(p); k < m; k++) {
                    length = merge(base, length, mapping.node(p, k), b * mapping.weight(p, k));
                }
            }
        }
        for (int k = 0; k < length; k++) {
            slot[rowNode[base + k]] = -1;
        }
        rowLength[e] = length;
    }

    /** Adds coefficient c of node n to the row at base holding length entries; returns the new length. */
    private int merge(int base, int length, int n, double c) {
        final int s = slot[n];
        if (s < 0) {
            slot[n] = length;
            rowNode[base + length] = n;
            rowCoef[base + length] = c;
            return length + 1;
        }
        rowCoef[base + s] += c;
        return length;
    }

    /** {@code y += w K z}, layouts as {@link ForceTerm#multiplyAdd}. */
    void multiplyAdd(double[] z, double[] y, int[] offset, double w) {
        for (int e = 0; e < tri.length; e++) {
            if (tri[e] < 0) {
                continue;
            }
            final double nx = normal[3 * e];
            final double ny = normal[3 * e + 1];
            final double nz = normal[3 * e + 2];
            final int base = e * capacity;
            final int end = base + rowLength[e];
            double nu = 0;
            for (int k = base; k < end; k++) {
                final int n = rowNode[k];
                final int o = offset == null ? 3 * n : offset[n];
                if (o >= 0) {
                    nu -= rowCoef[k] * (nx * z[o] + ny * z[o + 1] + nz * z[o + 2]);
                }
            }
            final double s = w * stiffness[e] * nu;
            if (s == 0) {
                continue;
            }
            for (int k = base; k < end; k++) {
                final int n = rowNode[k];
                final int o = offset == null ? 3 * n : offset[n];
                if (o >= 0) {
                    final double q = -rowCoef[k] * s;
                    y[o] += q * nx;
                    y[o + 1] += q * ny;
                    y[o + 2] += q * nz;
                }
            }
        }
    }

    /**
     * Adds each node's isotropic part, the trace of its diagonal block over 3, at the planes recorded (every follower
     * counted as touching). Follower e contributes {@code K_e = k a a^T (x) n n^T} with {@code a} its merged row,
     * so node j's diagonal block is {@code k a_j^2 n n^T}, trace / 3 = {@code k a_j^2 / 3} (N/m): k / 3 on a node
     * follower, and the square of the node's merged coefficient, not the sum of its rows' squares, on a node that
     * carries several corners. A follower whose plane is unknown counts its own row alone.
     */
    void addIsotropicStiffness(double[] perNode) {
        for (int e = 0; e < tri.length; e++) {
            final double k = stiffness[e];
            for (int q = e * capacity, end = q + rowLength[e]; q < end; q++) {
                final double a = rowCoef[q];
                perNode[rowNode[q]] += a * a * k / 3;
            }
        }
    }
}

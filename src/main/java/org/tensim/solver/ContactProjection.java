package org.tensim.solver;

/**
 * The contact's projection stage on hard bodies ({@link org.tensim.model.ContactBody#hard()}, bones): after each
 * step, every node that went deeper than its gap g is put back on it along the body's normal, frictionless (only
 * the normal component moves) and one-sided, as {@link RigidLinkProjection} puts the links back to their lengths.
 *
 * <p><b>A line search, not one move.</b> The node moves along the unit direction u = m / |m| of the distance's
 * gradient where it is, by a search on that line for {@code phi(x + s u) = g}: first s = g - d (exact for an exact
 * distance, |grad phi| = 1), then secant moves until it is within {@link #TOLERANCE} of its penetration of its gap,
 * kept inside the bracket once a move went past the gap. Why: a sampled distance grows slower than the path near a
 * thin bone's middle (a trilinear grid rounds the ridge of the distance over a cell; on the shared thorax's rib 11,
 * 0.3-0.5 mm per mm at 1-2 mm deep), so that a single move of g - d fell short there by half or more (the plate of
 * ContactProjectionTest: by more than half). A node's search stops if phi
 * stops growing along u (a rate below {@link #MIN_RATE}: a flat spot of the field, where going on would throw the
 * node out) or after {@link #MOVES} moves, and never takes it farther than {@link #MAX_FACTOR} times its penetration
 * from where it was.
 *
 * <p>Reads the pairs' arrays of its {@link ContactForces} (shared, never written); allocation-free, simulation
 * thread.
 */
final class ContactProjection {
    /** A node's search stops when it is within this fraction of its penetration of its gap. */
    static final double TOLERANCE = 1e-6;
    /** Most moves of one node's search in one projection round. */
    static final int MOVES = 12;
    /** Slowest growth of the distance along the search's line, m per m moved, at which the search goes on. */
    static final double MIN_RATE = 0.05;
    /** Farthest one round moves a node, in multiples of its penetration g - d. */
    static final double MAX_FACTOR = 5;

    private final ContactForces contacts;
    private final int[] node3; // per pair: 3 x node id
    private final int[] body; // per pair: body index
    private final double[] gap; // per pair: g, m
    private final boolean[] hard; // per body
    private final int[] hardNodes; // node ids with a pair on a hard body, each once, ascending
    private final double[] normal = new double[4];
    private final double[] probe = new double[4];

    ContactProjection(ContactForces contacts, int[] node3, int[] body, double[] gap, boolean[] hard) {
        this.contacts = contacts;
        this.node3 = node3;
        this.body = body;
        this.gap = gap;
        this.hard = hard;
        hardNodes = java.util.stream.IntStream.range(0, node3.length).filter(e -> hard[body[e]])
                .map(e -> node3[e] / 3).distinct().sorted().toArray();
    }

    /** Node ids with a pair on a hard body, each once, ascending (a copy). */
    int[] hardNodes() {
        return hardNodes.clone();
    }

    /**
     * Projects every hard pair's node at time t (s), positions x (m, changed in place); nodes of zero inverse mass
     * (fixed, driven) are left where they are.
     *
     * @return the largest penetration found, g - d, m (0 when none)
     */
    double project(double t, double[] x, double[] invMass) {
        double largest = 0;
        for (int e = 0; e < node3.length; e++) {
            final int i = node3[e];
            if (!hard[body[e]] || invMass[i / 3] == 0) {
                continue;
            }
            final double p = gap[e] - contacts.distance(e, t, x, normal);
            final double m2 = normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2];
            if (p <= 0 || m2 == 0) {
                continue;
            }
            search(e, i, t, x, p, 1 / Math.sqrt(m2));
            largest = Math.max(largest, p);
        }
        return largest;
    }

    /**
     * The search of pair e's node (x index i) on the line {@code x0 + s u}, u the unit normal {@code normal / |m|},
     * for {@code f(s) = phi - g = 0} from {@code f(0) = -p}: secant moves, kept inside the bracket once a move has
     * overshot (then false position between the bracket's ends, so that a field whose growth quickens beyond a
     * rounded ridge cannot throw the node out).
     */
    private void search(int e, int i, double t, double[] x, double p, double invM) {
        final double ux = normal[0] * invM;
        final double uy = normal[1] * invM;
        final double uz = normal[2] * invM;
        final double x0 = x[i];
        final double y0 = x[i + 1];
        final double z0 = x[i + 2];
        double sPrev = 0;
        double fPrev = -p;
        double lo = 0;
        double fLo = -p;
        double hi = Double.NaN;
        double fHi = Double.NaN;
        double s = p;
        for (int move = 0; move < MOVES; move++) {
            x[i] = x0 + s * ux;
            x[i + 1] = y0 + s * uy;
            x[i + 2] = z0 + s * uz;
            final double f = contacts.distance(e, t, x, probe) - gap[e];
            if (Math.abs(f) <= TOLERANCE * p) {
                return;
            }
            if (f < 0) {
                lo = s;
                fLo = f;
            } else {
                hi = s;
                fHi = f;
            }
            double next = s - f * (s - sPrev) / (f - fPrev);
            if (!Double.isNaN(hi) && !(next > lo && next < hi)) {
                next = lo - fLo * (hi - lo) / (fHi - fLo);
            } else if (Double.isNaN(hi) && !((f - fPrev) / (s - sPrev) >= MIN_RATE)) {
                return; // the field stopped growing along u: going on would throw the node out
            }
            sPrev = s;
            fPrev = f;
            s = Math.min(next, MAX_FACTOR * p);
            if (s == sPrev) {
                return;
            }
        }
    }
}

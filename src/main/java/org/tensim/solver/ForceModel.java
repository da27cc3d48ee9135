package org.tensim.solver;

/**
 * The right-hand side of m a = f for a {@link SystemState}: gravity, global
 * viscous damping, external nodal forces, linear springs with axial damping, and the
 * membrane triangles ({@link TriangleKernels}, undamped: the shell's damping is the global one) and the
 * active fibre tensions ({@link FibreTension}), the transverse shear elements ({@link ShearElements}), the
 * frictionless contacts with moving rigid bodies ({@link ContactForces}) and the volume elements
 * ({@link VolumeElements}).
 * Forces are written for every node; integrators multiply by the inverse mass,
 * which is zero for fixed and driven nodes.
 *
 * <p>Spring law (force on end a; end b gets the opposite):
 * {@code f_a = (k (l - L) + c (v_b - v_a).u) u}, {@code u = (x_b - x_a) / l}.
 * It is minus the gradient of {@code E = k (l - L)^2 / 2} (tested).
 */
public final class ForceModel {
    private final SystemState s;
    private final int[] springA3;
    private final int[] springB3;
    private long evaluations;
    private SpringForcePass springPass;
    private TriangleForcePass trianglePass;
    private NodeLoops nodeLoops = NodeLoops.SERIAL;
    private ForceTerm[] terms = new ForceTerm[0];
    private int termVersion;

    public ForceModel(SystemState state) {
        this.s = state;
        // Spring ends as array offsets (3 x node id), computed once for the shared kernels.
        this.springA3 = new int[state.springA.length];
        this.springB3 = new int[state.springB.length];
        for (int i = 0; i < springA3.length; i++) {
            springA3[i] = 3 * state.springA[i];
            springB3[i] = 3 * state.springB[i];
        }
    }

    public SystemState state() {
        return s;
    }

    /**
     * Adds a term to every force pass from the next one on, after the built-in forces ({@link ForceTerm}); its
     * energy joins {@link #elasticEnergy(double, double[])}. Not for the hot path: call it while building.
     */
    public void addTerm(ForceTerm term) {
        if (term == null) {
            throw new IllegalArgumentException("a force term cannot be null");
        }
        ForceTerm[] t = java.util.Arrays.copyOf(terms, terms.length + 1);
        t[terms.length] = term;
        terms = t;
        termVersion++;
    }

    /** Removes a term added by {@link #addTerm} (no effect if absent). */
    public void removeTerm(ForceTerm term) {
        terms = java.util.Arrays.stream(terms).filter(x -> x != term).toArray(ForceTerm[]::new);
        termVersion++;
    }

    /**
     * Each term's projection stage ({@link ForceTerm#project}) at time t (s) on positions x (m); returns the largest
     * correction, m. Allocation-free (the simulation's projection stage).
     */
    public double projectTerms(double t, double[] x, double[] invMass) {
        double moved = 0;
        for (ForceTerm term : terms) {
            moved = Math.max(moved, term.project(t, x, invMass));
        }
        return moved;
    }

    /** The nodes the terms' projections may move, each once, ascending. */
    public int[] projectedNodes() {
        return java.util.Arrays.stream(terms).flatMapToInt(term -> java.util.Arrays.stream(term.projectedNodes()))
                .distinct().sorted().toArray();
    }

    /** Changes whenever a term is added or removed (for those who cache what the terms need). */
    public int termVersion() {
        return termVersion;
    }

    /** Number of added terms. */
    public int termCount() {
        return terms.length;
    }

    /** Added term i, in order (allocation-free, for the integrators' tangent products). */
    public ForceTerm term(int i) {
        return terms[i];
    }

    /** The added terms, in order (a copy). */
    public java.util.List<ForceTerm> terms() {
        return java.util.List.of(terms);
    }

    /** Number of force passes made so far (the cost measure of integrators). */
    public long evaluations() {
        return evaluations;
    }

    /**
     * Replaces the built-in spring loops by {@code pass} (null restores them), e.g. a
     * multi-threaded pass; takes effect at the next force evaluation.
     */
    public void setSpringPass(SpringForcePass pass) {
        springPass = pass;
    }

    /** The spring pass in use, or null for the built-in loops. */
    public SpringForcePass springPass() {
        return springPass;
    }

    /**
     * Sets who runs the integrators' node loops (null restores {@link NodeLoops#SERIAL}),
     * e.g. a multi-threaded runner; takes effect at the next step.
     */
    public void setNodeLoops(NodeLoops loops) {
        nodeLoops = loops == null ? NodeLoops.SERIAL : loops;
    }

    /** The runner of the integrators' node loops (never null). */
    public NodeLoops nodeLoops() {
        return nodeLoops;
    }

    /**
     * Computes all forces (N) at time t for positions px and velocities pv into f
     * (overwritten). Allocation-free.
     */
    public void computeForces(double t, double[] px, double[] pv, double[] f) {
        evaluations++;
        final int n = s.nodeCount;
        final double[] m = s.mass;
        final double gx = s.gx;
        final double gy = s.gy;
        final double gz = s.gz;
        final double c = s.viscousDamping;
        if (c == 0) {
            for (int i = 0; i < n; i++) {
                double mi = m[i];
                f[3 * i] = mi * gx;
                f[3 * i + 1] = mi * gy;
                f[3 * i + 2] = mi * gz;
            }
        } else {
            for (int i = 0; i < n; i++) {
                double mi = m[i];
                f[3 * i] = mi * gx - c * pv[3 * i];
                f[3 * i + 1] = mi * gy - c * pv[3 * i + 1];
                f[3 * i + 2] = mi * gz - c * pv[3 * i + 2];
            }
        }
        for (int i = 0; i < s.forceNode.length; i++) {
            s.forceLaw[i].addTo(t, f, 3 * s.forceNode[i]);
        }
        // The undamped loop is about a third cheaper; it is used when no spring is damped.
        if (springPass != null) {
            springPass.addSpringForces(px, pv, f);
        } else if (s.axialDamping) {
            springsDamped(px, pv, f);
        } else {
            springs(px, f);
        }
        // The spring pass covers springs only: the triangles have their own (serial unless replaced).
        final double[] tv = s.triangleDamping || s.shears.damped() ? pv : null;
        if (trianglePass != null) {
            trianglePass.addTriangleForces(px, tv, f);
        } else {
            TriangleKernels.forces(s.triP3, s.triQ3, s.triRest, s.triMu, s.triLambda, s.triDamping,
                    s.triangleCount(), px, tv, f);
        }
        // The muscle's active fibre tension (none unless the scene has fibres), after the triangles.
        s.fibres.forces(t, px, f);
        // Contact with the rigid bodies (none unless the scene has contact pairs), after the fibres.
        s.contacts.forces(t, px, f);
        // The two-surface shell's transverse shear (none unless the scene has shear elements), unless
        // the triangle pass adds it.
        if (trianglePass == null || !trianglePass.addsShearForces()) {
            s.shears.forces(px, s.shears.damped() ? pv : null, f);
        }
        // The volume material's volumetric term (none unless the scene has volume elements), serial.
        s.volumes.forces(px, s.volumes.damped() ? pv : null, f);
        // The scene's own terms (couplings, mapped contacts), last.
        for (ForceTerm term : terms) {
            term.addForces(t, px, pv, f);
        }
        // Coordinates held on an axis (Node#hold): the hold's reaction cancels every force on them, so they do not
        // accelerate; Simulation#step puts them back at rest after the step (the implicit integrators' coupling).
        for (int k : s.heldDof) {
            f[k] = 0;
        }
    }

    /**
     * Replaces the serial loop over the membrane triangles by {@code pass} (null restores it),
     * e.g. a multi-threaded pass; takes effect at the next force evaluation.
     */
    public void setTrianglePass(TriangleForcePass pass) {
        trianglePass = pass;
    }

    /** The triangle pass in use, or null for the serial loop. */
    public TriangleForcePass trianglePass() {
        return trianglePass;
    }

    /** Membrane triangle elastic forces only (no damping), added to f. */
    public void triangles(double[] px, double[] f) {
        TriangleKernels.forces(s.triP3, s.triQ3, s.triRest, s.triMu, s.triLambda, s.triDamping, s.triangleCount(),
                px, null, f);
    }

    /** Elastic energy of the membrane triangles at positions px, J. */
    public double triangleEnergy(double[] px) {
        return TriangleKernels.energy(s.triP3, s.triQ3, s.triRest, s.triMu, s.triLambda, s.triangleCount(), px);
    }

    /** Elastic energy of springs, membrane triangles, transverse shear and volume elements at positions px, J. */
    public double elasticEnergy(double[] px) {
        return springEnergy(px) + triangleEnergy(px) + s.shears.energy(px) + s.volumes.energy(px);
    }

    /**
     * Elastic energy at time t (s) and positions px (m), J: {@link #elasticEnergy(double[])} plus the contacts'
     * penalty energy {@code sum k max(0, g - d)^2 / 2} (which needs t: the bodies move).
     */
    public double elasticEnergy(double t, double[] px) {
        double e = elasticEnergy(px) + s.contacts.energy(t, px);
        for (ForceTerm term : terms) {
            e += term.energy(t, px);
        }
        return e;
    }

    /** Spring forces only, added to f: the hot loop, without axial damping. */
    public void springs(double[] px, double[] f) {
        SpringKernels.springs(springA3, springB3, s.springK, s.springL, springA3.length, px, 0, f);
    }

    /** Spring forces with axial damping, added to f. */
    public void springsDamped(double[] px, double[] pv, double[] f) {
        SpringKernels.springsDamped(springA3, springB3, s.springK, s.springL, s.springC, springA3.length, px, pv, 0,
                f);
    }

    /** Elastic energy of the springs at positions px, J. */
    public double springEnergy(double[] px) {
        double e = 0;
        for (int i = 0; i < s.springA.length; i++) {
            int a = 3 * s.springA[i];
            int b = 3 * s.springB[i];
            double dx = px[b] - px[a];
            double dy = px[b + 1] - px[a + 1];
            double dz = px[b + 2] - px[a + 2];
            double ext = Math.sqrt(dx * dx + dy * dy + dz * dz) - s.springL[i];
            e += 0.5 * s.springK[i] * ext * ext;
        }
        return e;
    }

    /** Kinetic energy of the free nodes, J. */
    public double kineticEnergy() {
        double e = 0;
        for (int i = 0; i < s.nodeCount; i++) {
            if (s.invMass[i] != 0) {
                double vx = s.v[3 * i];
                double vy = s.v[3 * i + 1];
                double vz = s.v[3 * i + 2];
                e += 0.5 * s.mass[i] * (vx * vx + vy * vy + vz * vz);
            }
        }
        return e;
    }

    /** Gravitational potential energy of the free nodes, J ({@code -m g . x}). */
    public double gravityEnergy() {
        double e = 0;
        for (int i = 0; i < s.nodeCount; i++) {
            if (s.invMass[i] != 0) {
                e -= s.mass[i] * (s.gx * s.x[3 * i] + s.gy * s.x[3 * i + 1] + s.gz * s.x[3 * i + 2]);
            }
        }
        return e;
    }

    /** Kinetic + elastic (springs, triangles) + gravity energy of the current state, J (external forces excluded). */
    public double totalEnergy() {
        return kineticEnergy() + elasticEnergy(s.x) + gravityEnergy();
    }
}

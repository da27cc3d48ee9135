package org.tensim.solver;

import java.util.List;
import org.tensim.model.Check;
import org.tensim.model.ForceLaw;
import org.tensim.model.Motion;
import org.tensim.model.Node;
import org.tensim.model.RigidLink;
import org.tensim.model.Spring;
import org.tensim.model.Topology;
import org.tensim.model.TriangleElement;
import org.tensim.model.Vec3;
import org.tensim.solver.stability.CriticalTimeStep;
import org.tensim.solver.stability.ExtraStiffness;

/**
 * The compiled, flat simulation state of a {@link Topology}: arrays of doubles
 * indexed by node (3 per node, interleaved x, y, z) and int arrays of spring and
 * link end points. Allocated once by {@link #compile(Topology)}; the solver never
 * allocates per step. Node ids are those of the topology.
 *
 * <p>Fields are public for the hot loops of integrators and views; they are read
 * by listeners between steps and written only by the simulation thread.
 */
public final class SystemState {
    /** Number of nodes. */
    public final int nodeCount;
    /** Positions, m: node i at [3i, 3i+1, 3i+2]. */
    public final double[] x;
    /** Velocities, m/s, same layout. */
    public final double[] v;
    /** Initial (rest) positions, m, same layout. */
    public final double[] x0;
    /** Masses, kg. */
    public final double[] mass;
    /** Inverse masses, 1/kg; 0 for fixed and driven nodes (they are not integrated). */
    public final double[] invMass;

    /** Spring end points (node ids). */
    public final int[] springA;
    public final int[] springB;
    /** Spring stiffness, N/m. */
    public final double[] springK;
    /** Spring rest length, m. */
    public final double[] springL;
    /** Spring axial damping, N s/m. */
    public final double[] springC;

    /**
     * Membrane triangles ({@link TriangleElement}, {@link TriangleKernels}): corner k of element e is
     * the midpoint of nodes {@code triP[3e+k]} and {@code triQ[3e+k]}; triP3, triQ3 the same as array
     * offsets (3 x node id).
     */
    public final int[] triP;
    public final int[] triQ;
    public final int[] triP3;
    public final int[] triQ3;
    /** Rest-frame inverse {@code D_m^-1} per element, row-major, 1/m (4 per element). */
    public final double[] triRest;
    /** {@code A t mu} and {@code A t lambda} (plane stress) per element, J. */
    public final double[] triMu;
    public final double[] triLambda;
    /** Kelvin-Voigt damping time beta per element, s (0: undamped). */
    public final double[] triDamping;

    /** Rigid link end points (node ids). */
    public final int[] linkA;
    public final int[] linkB;
    /** Rigid link lengths, m. */
    public final double[] linkL;
    /** Ids of the nodes that belong to at least one rigid link, each once. */
    public final int[] linkNodes;

    /** Active fibre tensions ({@link FibreTension}; count 0 when the topology has none). */
    public final FibreTension fibres;
    /** Frictionless contacts with moving rigid bodies ({@link ContactForces}; count 0 when none). */
    public final ContactForces contacts;
    /** Transverse shear elements of the two-surface shell ({@link ShearElements}; count 0 when none). */
    public final ShearElements shears;
    /** Volume elements ({@link VolumeElements}; count 0 when none). */ public final VolumeElements volumes;

    /** Nodes that carry external forces, and the laws (parallel arrays). */
    public final int[] forceNode;
    public final ForceLaw[] forceLaw;

    /** Driven nodes, their motions and rest positions (parallel arrays). */
    public final int[] drivenNode;
    public final Motion[] drivenMotion;
    final Vec3[] drivenRest;

    /** Fixed nodes. */ public final int[] fixedNode;
    /** Coordinates 3 i + axis of free nodes held on an axis ({@link Node#hold}). */ public final int[] heldDof;

    /** True when at least one spring has axial damping (selects the force loop). */ boolean axialDamping;
    /** True when at least one membrane triangle is damped. */ boolean triangleDamping;

    double gx;
    double gy;
    double gz;
    double viscousDamping;

    /** Incremented by every parameter setter (stiffness, damping, gravity). */
    private long parameterVersion;
    /** Cached critical-step estimate at the rest positions (null until asked or after a stiffness change). */
    private CriticalTimeStep criticalTimeStep;

    private SystemState(Topology t) {
        nodeCount = t.nodeCount();
        x = new double[3 * nodeCount];
        v = new double[3 * nodeCount];
        x0 = new double[3 * nodeCount];
        mass = new double[nodeCount];
        invMass = new double[nodeCount];
        int nFixed = 0;
        int nDriven = 0;
        for (Node n : t.nodes()) {
            int i = n.id();
            x[3 * i] = n.position().x();
            x[3 * i + 1] = n.position().y();
            x[3 * i + 2] = n.position().z();
            mass[i] = n.mass();
            invMass[i] = (n.isFixed() || n.isDriven()) ? 0 : 1 / n.mass();
            nFixed += n.isFixed() ? 1 : 0;
            nDriven += n.isDriven() ? 1 : 0;
        }
        System.arraycopy(x, 0, x0, 0, x.length);
        fixedNode = new int[nFixed];
        drivenNode = new int[nDriven];
        drivenMotion = new Motion[nDriven];
        drivenRest = new Vec3[nDriven];
        int f = 0;
        int d = 0;
        for (Node n : t.nodes()) {
            if (n.isFixed()) {
                fixedNode[f++] = n.id();
            } else if (n.isDriven()) {
                drivenNode[d] = n.id();
                drivenMotion[d] = n.motion();
                drivenRest[d++] = n.position();
            }
        }

        heldDof = t.nodes().stream().filter(n -> !n.isFixed()).flatMapToInt(n -> java.util.stream.IntStream.range(0, 3)
                .filter(a -> (n.heldAxes() >> a & 1) != 0).map(a -> 3 * n.id() + a)).toArray();
        List<Spring> s = t.springs();
        springA = new int[s.size()];
        springB = new int[s.size()];
        springK = new double[s.size()];
        springL = new double[s.size()];
        springC = new double[s.size()];
        for (int i = 0; i < s.size(); i++) {
            Spring sp = s.get(i);
            springA[i] = sp.a();
            springB[i] = sp.b();
            springK[i] = sp.stiffness();
            springL[i] = sp.restLength();
            springC[i] = sp.damping();
            axialDamping |= sp.damping() != 0;
        }

        List<TriangleElement> tris = t.triangles();
        triP = new int[3 * tris.size()];
        triQ = new int[3 * tris.size()];
        triP3 = new int[3 * tris.size()];
        triQ3 = new int[3 * tris.size()];
        triRest = new double[4 * tris.size()];
        triMu = new double[tris.size()];
        triLambda = new double[tris.size()];
        triDamping = new double[tris.size()];
        for (int e = 0; e < tris.size(); e++) {
            TriangleElement te = tris.get(e);
            for (int k = 0; k < 3; k++) {
                triP[3 * e + k] = te.p(k);
                triQ[3 * e + k] = te.q(k);
                triP3[3 * e + k] = 3 * te.p(k);
                triQ3[3 * e + k] = 3 * te.q(k);
            }
            for (int k = 0; k < 4; k++) {
                triRest[4 * e + k] = te.restInverse(k);
            }
            triMu[e] = te.muVolume();
            triLambda[e] = te.lambdaVolume();
            triDamping[e] = te.dampingS();
            triangleDamping |= te.dampingS() != 0;
        }
        fibres = new FibreTension(t.fibres());
        contacts = new ContactForces(t.contactBodies(), t.contacts());
        shears = new ShearElements(t.shears(), x0);
        volumes = new VolumeElements(t.volumeElements());

        List<RigidLink> l = t.rigidLinks();
        linkA = new int[l.size()];
        linkB = new int[l.size()];
        linkL = new double[l.size()];
        boolean[] inLink = new boolean[nodeCount];
        int nLinkNodes = 0;
        for (int i = 0; i < l.size(); i++) {
            RigidLink rl = l.get(i);
            linkA[i] = rl.a();
            linkB[i] = rl.b();
            linkL[i] = rl.length();
            for (int e : new int[] {rl.a(), rl.b()}) {
                if (!inLink[e]) {
                    inLink[e] = true;
                    nLinkNodes++;
                }
            }
        }
        linkNodes = new int[nLinkNodes];
        for (int i = 0, k = 0; i < nodeCount; i++) {
            if (inLink[i]) {
                linkNodes[k++] = i;
            }
        }

        List<Topology.NodalForce> fs = t.forces();
        forceNode = new int[fs.size()];
        forceLaw = new ForceLaw[fs.size()];
        for (int i = 0; i < fs.size(); i++) {
            forceNode[i] = fs.get(i).node();
            forceLaw[i] = fs.get(i).law();
        }
        gx = t.gravity().x();
        gy = t.gravity().y();
        gz = t.gravity().z();
        viscousDamping = t.viscousDamping();
    }

    /** Compiles a topology into a new flat state at its initial positions, at rest. */
    public static SystemState compile(Topology t) {
        return new SystemState(t);
    }

    public int springCount() {
        return springA.length;
    }

    /** Number of membrane triangles. */
    public int triangleCount() {
        return triMu.length;
    }

    public int linkCount() {
        return linkA.length;
    }

    /** Writes node i's displacement from its initial position (m) into out[0..2]. */
    public void displacement(int node, double[] out) {
        Check.index("node", node, nodeCount);
        out[0] = x[3 * node] - x0[3 * node];
        out[1] = x[3 * node + 1] - x0[3 * node + 1];
        out[2] = x[3 * node + 2] - x0[3 * node + 2];
    }

    /** Component {@code axis} (0 = x, 1 = y, 2 = z) of node i's position, m. */
    public double position(int node, int axis) {
        return x[3 * node + axis];
    }

    /** Gravity acceleration, m/s^2. */
    public Vec3 gravity() {
        return new Vec3(gx, gy, gz);
    }

    /** Sets gravity, m/s^2 (takes effect at the next force pass). */
    public void setGravity(Vec3 g) {
        gx = g.x();
        gy = g.y();
        gz = g.z();
        parameterVersion++;
    }

    /** Whether any force depends on the velocities (spring axial damping or global viscous damping). */
    public boolean velocityDependentForces() {
        return axialDamping || triangleDamping || shears.damped() || volumes.damped() || viscousDamping != 0;
    }

    /** Global viscous damping, N s/m per node. */
    public double viscousDamping() {
        return viscousDamping;
    }

    public void setViscousDamping(double nsPerM) {
        viscousDamping = Check.nonNegative("viscous damping", "N s/m", nsPerM);
        parameterVersion++;
    }

    /** Sets the stiffness (N/m, >= 0) of spring s; takes effect at the next force pass. */
    public void setSpringStiffness(int s, double k) {
        Check.index("spring", s, springK.length);
        springK[s] = Check.nonNegative("spring " + s + " stiffness", "N/m", k);
        parameterVersion++;
        criticalTimeStep = null;
    }

    /**
     * Gives membrane triangle e the constants of {@code te} (moduli, thickness, damping; its corners
     * and rest shape must be the same); takes effect at the next force pass.
     */
    public void setTriangleConstants(int e, TriangleElement te) {
        Check.index("triangle", e, triMu.length);
        for (int k = 0; k < 3; k++) {
            if (te.p(k) != triP[3 * e + k] || te.q(k) != triQ[3 * e + k]) {
                throw new IllegalArgumentException("triangle " + e + " has other corners in the new constants: only"
                        + " constants may change, not the topology");
            }
        }
        triMu[e] = te.muVolume();
        triLambda[e] = te.lambdaVolume();
        triDamping[e] = te.dampingS();
        triangleDamping |= te.dampingS() != 0;
        parameterVersion++;
        criticalTimeStep = null;
    }

    /** Gives shear element e the stiffness of {@code ts} (the same nodes); takes effect at the next force pass. */
    public void setShearConstants(int e, org.tensim.model.TransverseShear ts) {
        shears.setConstants(e, ts);
        parameterVersion++;
        criticalTimeStep = null;
    }

    /** Sets the axial damping (N s/m, >= 0) of spring s. */
    public void setSpringDamping(int s, double c) {
        Check.index("spring", s, springC.length);
        springC[s] = Check.nonNegative("spring " + s + " damping", "N s/m", c);
        axialDamping |= c != 0;
        parameterVersion++;
    }

    /**
     * Counts parameter changes made through the setters of this state (stiffness, damping, gravity): an integrator
     * that reuses a force from the previous step knows by it that the forces may have changed.
     */
    public long parameterVersion() {
        return parameterVersion;
    }

    /**
     * The critical time step estimate of this state, linearised at the rest positions (Gershgorin bound and power
     * iteration on M^-1 K; see {@link CriticalTimeStep}). Computed on first use and kept until a stiffness changes.
     */
    public CriticalTimeStep criticalTimeStep() {
        if (criticalTimeStep == null) {
            criticalTimeStep = estimateCriticalTimeStep();
        }
        return criticalTimeStep;
    }

    /**
     * A new critical time step estimate (springs, triangles and shear elements at the rest positions, every contact
     * pair as if in contact: {@link ContactForces#worstCaseStiffness()}), not cached: for another thread.
     */
    public CriticalTimeStep estimateCriticalTimeStep() {
        ExtraStiffness all = ExtraStiffness.sum(elementStiffness(), contacts.worstCaseStiffness());
        return CriticalTimeStep.estimate(nodeCount, springA, springB, springK, mass, invMass, x0, all);
    }

    /** The stiffness of the triangles, shear and volume elements linearised at the rest positions (new objects). */
    public ExtraStiffness elementStiffness() {
        ExtraStiffness tri = triangleCount() == 0 ? ExtraStiffness.NONE : new TriangleTangent(this);
        ExtraStiffness vol = volumes.count() == 0 ? ExtraStiffness.NONE : volumes.restStiffness();
        return ExtraStiffness.sum(ExtraStiffness.sum(tri, vol),
                shears.count() == 0 ? ExtraStiffness.NONE : new ShearStiffness(shears, x0));
    }

    /** Total momentum of the free nodes, kg m/s, into out[0..2]. */
    public void momentum(double[] out) {
        out[0] = 0;
        out[1] = 0;
        out[2] = 0;
        for (int i = 0; i < nodeCount; i++) {
            if (invMass[i] != 0) {
                out[0] += mass[i] * v[3 * i];
                out[1] += mass[i] * v[3 * i + 1];
                out[2] += mass[i] * v[3 * i + 2];
            }
        }
    }

    /**
     * Applies the prescribed motions of driven nodes at time t to positions
     * {@code px} and velocities {@code pv} (central difference of the motion).
     */
    public void applyMotions(double t, double[] px, double[] pv, double[] scratch6) {
        for (int d = 0; d < drivenNode.length; d++) {
            int o = 3 * drivenNode[d];
            Motion m = drivenMotion[d];
            m.position(t, drivenRest[d], px, o);
            if (pv != null) {
                final double eps = 1e-6;
                m.position(t + eps, drivenRest[d], scratch6, 0);
                m.position(t - eps, drivenRest[d], scratch6, 3);
                pv[o] = (scratch6[0] - scratch6[3]) / (2 * eps);
                pv[o + 1] = (scratch6[1] - scratch6[4]) / (2 * eps);
                pv[o + 2] = (scratch6[2] - scratch6[5]) / (2 * eps);
            }
        }
    }
}

package org.tensim.model;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * How a scene is authored: nodes (mass points), springs, membrane triangles
 * ({@link TriangleElement}), rigid links, external nodal forces, gravity and global
 * viscous damping. A topology is compiled into a
 * flat simulation state by the solver ({@code org.tensim.solver.SystemState});
 * authoring objects are never touched while a simulation runs.
 *
 * <p>Units are SI throughout: m, kg, s, N.
 */
public final class Topology {
    /** An external force law applied to one node. */
    public record NodalForce(int node, ForceLaw law) {
    }

    private final List<Node> nodes = new ArrayList<>();
    private final List<Spring> springs = new ArrayList<>();
    private final List<RigidLink> links = new ArrayList<>();
    private final List<TriangleElement> triangles = new ArrayList<>();
    private final List<ActiveFibre> fibres = new ArrayList<>();
    private final List<TransverseShear> shears = new ArrayList<>();
    private final List<NodalForce> forces = new ArrayList<>();
    private final List<VolumeElement> volumes = new ArrayList<>();
    private final List<ContactBody> contactBodies = new ArrayList<>();
    private final List<ContactPair> contacts = new ArrayList<>();
    private Vec3 gravity = Vec3.ZERO;
    private double viscousDamping;

    /**
     * Adds a node at (x, y, z) m with the given mass.
     *
     * @param massKg mass, kg, finite and > 0
     * @return the new node; its id is the number of nodes added before it
     */
    public Node addNode(double x, double y, double z, double massKg) {
        Vec3 p;
        try {
            p = new Vec3(x, y, z);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("node " + nodes.size() + " position: " + e.getMessage(), e);
        }
        Node n = new Node(nodes.size(), p, massKg);
        nodes.add(n);
        return n;
    }

    /** Adds a node at {@code p}, m. */
    public Node addNode(Vec3 p, double massKg) {
        return addNode(p.x(), p.y(), p.z(), massKg);
    }

    /**
     * Adds a spring whose rest length is the nodes' current distance.
     *
     * @param stiffness N/m, >= 0
     * @param damping   N s/m along the spring's axis, >= 0
     */
    public Spring addSpring(Node a, Node b, double stiffness, double damping) {
        own(a);
        own(b);
        return addSpring(a.id(), b.id(), stiffness, a.position().distance(b.position()), damping);
    }

    /** Adds a spring between node ids with an explicit rest length (m). */
    public Spring addSpring(int a, int b, double stiffness, double restLength, double damping) {
        Check.index("spring end node", a, nodes.size());
        Check.index("spring end node", b, nodes.size());
        Spring s = new Spring(a, b, stiffness, restLength, damping);
        springs.add(s);
        return s;
    }

    /**
     * Adds a membrane triangle on three nodes, at rest in their current positions.
     *
     * @param thicknessM t, m (&gt; 0)
     * @param youngPa    Young's modulus E, Pa (&gt; 0)
     * @param poisson    Poisson's ratio nu, in (-1, 0.5]
     */
    public TriangleElement addTriangle(int a, int b, int c, double thicknessM, double youngPa, double poisson) {
        int[] corners = {a, b, c};
        return addTriangle(corners, corners, thicknessM, youngPa, poisson, 0);
    }

    /**
     * Adds a membrane triangle whose corner k is the midpoint of nodes {@code p[k]} and {@code q[k]}
     * (equal for a plain corner), at rest in their current positions; see {@link TriangleElement}.
     *
     * @param thicknessM t, m (&gt; 0)
     * @param youngPa    Young's modulus E, Pa (&gt; 0)
     * @param poisson    Poisson's ratio nu, in (-1, 0.5]
     * @param dampingS   stiffness-proportional (Kelvin-Voigt) damping time beta, s (&gt;= 0; 0 undamped)
     */
    public TriangleElement addTriangle(int[] p, int[] q, double thicknessM, double youngPa, double poisson,
            double dampingS) {
        if (p.length != 3 || q.length != 3) {
            throw new IllegalArgumentException("a triangle element needs 3 corners, got " + p.length + " and "
                    + q.length + " node ids");
        }
        Vec3[] rest = new Vec3[3];
        for (int k = 0; k < 3; k++) {
            Check.index("triangle corner node", p[k], nodes.size());
            Check.index("triangle corner node", q[k], nodes.size());
            rest[k] = nodes.get(p[k]).position().plus(nodes.get(q[k]).position()).times(0.5);
        }
        TriangleElement e = new TriangleElement(p, q, rest, thicknessM, youngPa, poisson, dampingS);
        triangles.add(e);
        return e;
    }

    /**
     * Adds an active fibre tension on a triangle whose corner k is the midpoint of nodes {@code p[k]}
     * and {@code q[k]}, at rest in their current positions; see {@link ActiveFibre}.
     *
     * @param direction  fibre direction (its in-plane part is used)
     * @param thicknessM thickness of muscle the triangle stands for, m (&gt; 0)
     * @param stressPa   active stress over time, Pa (allocation-free)
     */
    public ActiveFibre addFibre(int[] p, int[] q, Vec3 direction, double thicknessM,
            java.util.function.DoubleUnaryOperator stressPa) {
        if (p.length != 3 || q.length != 3) {
            throw new IllegalArgumentException("an active fibre needs a triangle of 3 corners, got " + p.length
                    + " and " + q.length + " node ids");
        }
        Vec3[] rest = new Vec3[3];
        for (int k = 0; k < 3; k++) {
            Check.index("fibre triangle corner node", p[k], nodes.size());
            Check.index("fibre triangle corner node", q[k], nodes.size());
            rest[k] = nodes.get(p[k]).position().plus(nodes.get(q[k]).position()).times(0.5);
        }
        ActiveFibre e = new ActiveFibre(p, q, rest, direction, thicknessM, stressPa);
        fibres.add(e);
        return e;
    }

    /**
     * Adds a transverse shear element on the upper triangle {@code upper} whose corners' partners on
     * the lower face are {@code lower} (corner by corner), at rest in the nodes' current positions; see
     * {@link TransverseShear}.
     *
     * @param kappaGPa   kappa G, Pa (&gt; 0)
     * @param thicknessM t, m (&gt; 0)
     */
    public TransverseShear addShear(int[] upper, int[] lower, double kappaGPa, double thicknessM) {
        return addShear(upper, lower, kappaGPa, thicknessM, 0);
    }

    /**
     * As {@link #addShear(int[], int[], double, double)} with Kelvin-Voigt damping.
     *
     * @param dampingS stiffness-proportional damping time beta, s (&gt;= 0; 0 undamped)
     */
    public TransverseShear addShear(int[] upper, int[] lower, double kappaGPa, double thicknessM, double dampingS) {
        if (upper.length != 3 || lower.length != 3) {
            throw new IllegalArgumentException("a transverse shear element needs 3 upper corners and 3 partners, got "
                    + upper.length + " and " + lower.length + " node ids");
        }
        int[] ids = {upper[0], upper[1], upper[2], lower[0], lower[1], lower[2]};
        Vec3[] rest = new Vec3[6];
        for (int a = 0; a < 6; a++) {
            Check.index("transverse shear node", ids[a], nodes.size());
            rest[a] = nodes.get(ids[a]).position();
        }
        TransverseShear e = new TransverseShear(ids, rest, kappaGPa, thicknessM, dampingS);
        shears.add(e);
        return e;
    }

    /**
     * Puts {@code s} in the place of spring {@code index}, on the same two nodes: a scene's zone giving part of a
     * body its own stiffness before the topology is compiled. The spring's position in the list is kept, so a
     * compiled state's order (and its results, to the bit) is that of the unchanged springs.
     */
    public void replaceSpring(int index, Spring s) {
        Spring old = springs.get(Check.index("spring", index, springs.size()));
        if (old.a() != s.a() || old.b() != s.b()) {
            throw new IllegalArgumentException("spring " + index + " joins nodes " + old.a() + "-" + old.b()
                    + "; its replacement must join the same, got " + s.a() + "-" + s.b());
        }
        springs.set(index, s);
    }

    /** As {@link #replaceSpring} for membrane triangle {@code index}: the same corners p and q. */
    public void replaceTriangle(int index, TriangleElement e) {
        TriangleElement old = triangles.get(Check.index("triangle", index, triangles.size()));
        for (int k = 0; k < 3; k++) {
            if (old.p(k) != e.p(k) || old.q(k) != e.q(k)) {
                throw new IllegalArgumentException("triangle " + index + "'s replacement must have the same corners"
                        + " (corner " + k + ": " + old.p(k) + "/" + old.q(k) + ", got " + e.p(k) + "/" + e.q(k) + ")");
            }
        }
        triangles.set(index, e);
    }

    /** As {@link #replaceSpring} for transverse shear element {@code index}: the same six nodes. */
    public void replaceShear(int index, TransverseShear e) {
        TransverseShear old = shears.get(Check.index("transverse shear element", index, shears.size()));
        for (int a = 0; a < 6; a++) {
            if (old.node(a) != e.node(a)) {
                throw new IllegalArgumentException("transverse shear element " + index + "'s replacement must have"
                        + " the same nodes (node " + a + ": " + old.node(a) + ", got " + e.node(a) + ")");
            }
        }
        shears.set(index, e);
    }

    /**
     * Adds a penalty on the volume change of a tet (4 nodes) or a hexahedral cell (8, in the corner order of
     * {@link VolumeElement}), at rest in the nodes' current positions; see {@link VolumeElement}.
     *
     * @param modulusPa K, Pa (&gt; 0)
     * @param dampingS  Kelvin-Voigt damping time beta, s (&gt;= 0; 0 undamped)
     */
    public VolumeElement addVolumeElement(int[] nodeIds, double modulusPa, double dampingS) {
        Vec3[] rest = new Vec3[nodeIds.length];
        for (int a = 0; a < nodeIds.length; a++) {
            Check.index("volume element node", nodeIds[a], nodes.size());
            rest[a] = nodes.get(nodeIds[a]).position();
        }
        VolumeElement e = new VolumeElement(nodeIds, rest, modulusPa, dampingS);
        volumes.add(e);
        return e;
    }

    /** The volume elements, in the order added. */
    public List<VolumeElement> volumeElements() {
        return Collections.unmodifiableList(volumes);
    }

    /** Adds a rigid link whose length is the nodes' current distance (must be > 0). */
    public RigidLink addRigidLink(Node a, Node b) {
        own(a);
        own(b);
        double len = a.position().distance(b.position());
        if (a != b && !(len > 0)) {
            throw new IllegalArgumentException("rigid link " + a.id() + "-" + b.id()
                    + " would have zero length: its nodes are at the same position " + a.position());
        }
        return addRigidLink(a.id(), b.id(), len);
    }

    /** Adds a rigid link between node ids with an explicit length (m, > 0). */
    public RigidLink addRigidLink(int a, int b, double length) {
        Check.index("rigid link end node", a, nodes.size());
        Check.index("rigid link end node", b, nodes.size());
        RigidLink l = new RigidLink(a, b, length);
        links.add(l);
        return l;
    }

    /** Applies a time-dependent external force to a node. Several forces on a node add up. */
    public void applyForce(Node node, ForceLaw law) {
        own(node);
        if (law == null) {
            throw new IllegalArgumentException("force law on node " + node.id() + " must not be null");
        }
        forces.add(new NodalForce(node.id(), law));
    }

    /** Gravity acceleration, m/s^2 (e.g. (0, -9.81, 0) for y up). Zero by default (off). */
    public void setGravity(Vec3 g) {
        gravity = g;
    }

    public Vec3 gravity() {
        return gravity;
    }

    /**
     * Global viscous damping coefficient c, N s/m: each free node feels
     * {@code -c v}. Zero by default.
     */
    public void setViscousDamping(double nsPerM) {
        viscousDamping = Check.nonNegative("viscous damping", "N s/m", nsPerM);
    }

    public double viscousDamping() {
        return viscousDamping;
    }

    public Node node(int id) {
        Check.index("node", id, nodes.size());
        return nodes.get(id);
    }

    public List<Node> nodes() {
        return Collections.unmodifiableList(nodes);
    }

    public List<Spring> springs() {
        return Collections.unmodifiableList(springs);
    }

    /** The membrane triangles, in the order added. */
    public List<TriangleElement> triangles() {
        return Collections.unmodifiableList(triangles);
    }

    /** Adds a rigid contact body; returns its index for {@link #addContact}. */
    public int addContactBody(ContactBody body) {
        if (body == null) {
            throw new IllegalArgumentException("contact body must not be null");
        }
        contactBodies.add(body);
        return contactBodies.size() - 1;
    }

    /** Lets a node touch a contact body (frictionless, one-sided; see {@link ContactPair}). */
    public ContactPair addContact(int node, int body, double stiffnessNPerM, double gapM) {
        Check.index("contact node", node, nodes.size());
        Check.index("contact body", body, contactBodies.size());
        ContactPair c = new ContactPair(node, body, stiffnessNPerM, gapM);
        contacts.add(c);
        return c;
    }

    /**
     * Removes every contact pair (the bodies stay): for a coarse model whose contact is carried by a fine surface
     * mapped from it instead (the pairs are then the fine surface's). Returns how many were removed.
     */
    public int clearContacts() {
        int n = contacts.size();
        contacts.clear();
        return n;
    }

    /** The contact bodies, in the order added. */
    public List<ContactBody> contactBodies() {
        return Collections.unmodifiableList(contactBodies);
    }

    /** The node-body contact pairs, in the order added. */
    public List<ContactPair> contacts() {
        return Collections.unmodifiableList(contacts);
    }

    /** The active fibre tensions, in the order added. */
    public List<ActiveFibre> fibres() {
        return Collections.unmodifiableList(fibres);
    }

    /** The transverse shear elements, in the order added. */
    public List<TransverseShear> shears() {
        return Collections.unmodifiableList(shears);
    }

    public List<RigidLink> rigidLinks() {
        return Collections.unmodifiableList(links);
    }

    public List<NodalForce> forces() {
        return Collections.unmodifiableList(forces);
    }

    public int nodeCount() {
        return nodes.size();
    }

    /** Total mass of all nodes, kg. */
    public double totalMass() {
        double m = 0;
        for (Node n : nodes) {
            m += n.mass();
        }
        return m;
    }

    private void own(Node n) {
        if (n == null) {
            throw new IllegalArgumentException("node must not be null");
        }
        if (n.id() >= nodes.size() || nodes.get(n.id()) != n) {
            throw new IllegalArgumentException("node " + n.id() + " does not belong to this topology");
        }
    }

    @Override
    public String toString() {
        return "Topology[" + nodes.size() + " nodes, " + springs.size() + " springs, " + triangles.size()
                + " triangles, " + shears.size() + " shear elements, " + volumes.size() + " volume elements, "
                + links.size()
                + " rigid links, " + forces.size() + " forces]";
    }
}

package org.tensim.scene.tunable;

import org.tensim.model.Node;
import org.tensim.model.Spring;
import org.tensim.model.Topology;
import org.tensim.model.Topology.NodalForce;

/**
 * The mass-spring variant of a tensegrity topology, for comparing the two models
 * of the same tissue: a copy in which every rigid link becomes a spring of the
 * same rest length. Nodes (positions, masses, fixed, held on some axes or driven), springs, forces,
 * gravity and viscous damping are copied as they are; motions and force laws are
 * shared with the original (they are read-only functions of time and controls).
 *
 * <p>The spring that replaces a link gets the mean stiffness and the mean axial
 * damping of the springs that touch its two end nodes: as stiff as the tissue
 * around it, so the node's highest frequency, and with it the stable time step,
 * stays about the same.
 */
public final class RigidLinksAsSprings {
    private RigidLinksAsSprings() {
    }

    /** The copy; the original is not changed. */
    public static Topology of(Topology t) {
        Topology c = new Topology();
        for (Node n : t.nodes()) {
            Node m = c.addNode(n.position(), n.mass());
            if (n.isFixed()) {
                m.fix();
            } else if (n.isDriven()) {
                m.drive(n.motion());
            } else if (n.heldAxes() != 0) {
                m.hold(n.heldAxes());
            }
        }
        int nodes = t.nodeCount();
        double[] sumK = new double[nodes];
        double[] sumC = new double[nodes];
        int[] count = new int[nodes];
        for (Spring s : t.springs()) {
            c.addSpring(s.a(), s.b(), s.stiffness(), s.restLength(), s.damping());
            for (int e : new int[] {s.a(), s.b()}) {
                sumK[e] += s.stiffness();
                sumC[e] += s.damping();
                count[e]++;
            }
        }
        for (var l : t.rigidLinks()) {
            int n = count[l.a()] + count[l.b()];
            double k = n == 0 ? 0 : (sumK[l.a()] + sumK[l.b()]) / n;
            double d = n == 0 ? 0 : (sumC[l.a()] + sumC[l.b()]) / n;
            c.addSpring(l.a(), l.b(), k, l.length(), d);
        }
        for (NodalForce f : t.forces()) {
            c.applyForce(c.node(f.node()), f.law());
        }
        c.setGravity(t.gravity());
        c.setViscousDamping(t.viscousDamping());
        return c;
    }
}

package org.tensim.scene;

import java.util.List;
import java.util.Random;
import org.tensim.model.Node;
import org.tensim.model.RigidLink;
import org.tensim.model.Spring;
import org.tensim.model.Topology;

/**
 * The same physical scene with its node ids and its spring and link order
 * shuffled, as a mesh imported from a file that numbers its vertices arbitrarily.
 * Used to measure and test cache-aware orderings: the physics is unchanged, only
 * the memory layout is worse.
 */
public final class ShuffledScene {
    private ShuffledScene() {
    }

    /**
     * A copy of t with a random node numbering (seeded) and springs and links in a
     * random order. Fixed nodes, gravity and viscous damping are kept; driven nodes
     * and external forces are not supported (an exception says so).
     */
    public static Topology shuffle(Topology t, long seed) {
        if (!t.forces().isEmpty()) {
            throw new IllegalArgumentException("shuffle: scenes with external nodal forces are not supported");
        }
        Random rnd = new Random(seed);
        int n = t.nodeCount();
        int[] newId = permutation(n, rnd);
        Node[] byNew = new Node[n];
        for (Node node : t.nodes()) {
            if (node.isDriven()) {
                throw new IllegalArgumentException("shuffle: scenes with driven nodes are not supported");
            }
            byNew[newId[node.id()]] = node;
        }
        Topology out = new Topology();
        for (Node node : byNew) {
            Node m = out.addNode(node.position(), node.mass());
            if (node.isFixed()) {
                m.fix();
            }
        }
        List<Spring> springs = t.springs();
        for (int i : permutation(springs.size(), rnd)) {
            Spring s = springs.get(i);
            out.addSpring(newId[s.a()], newId[s.b()], s.stiffness(), s.restLength(), s.damping());
        }
        List<RigidLink> links = t.rigidLinks();
        for (int i : permutation(links.size(), rnd)) {
            RigidLink l = links.get(i);
            out.addRigidLink(newId[l.a()], newId[l.b()], l.length());
        }
        out.setGravity(t.gravity());
        out.setViscousDamping(t.viscousDamping());
        return out;
    }

    /** A uniformly random permutation of 0..n-1 (Fisher-Yates). */
    static int[] permutation(int n, Random rnd) {
        int[] p = new int[n];
        for (int i = 0; i < n; i++) {
            p[i] = i;
        }
        for (int i = n - 1; i > 0; i--) {
            int j = rnd.nextInt(i + 1);
            int tmp = p[i];
            p[i] = p[j];
            p[j] = tmp;
        }
        return p;
    }
}

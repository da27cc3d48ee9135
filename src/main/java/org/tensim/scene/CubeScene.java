package org.tensim.scene;

import java.util.ArrayList;
import java.util.List;
import org.tensim.model.ForceLaw;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;

/**
 * The paper's cube (Fig. 3): a 10 x 10 x 10 m cube, y up, bottom face at y = 0.
 * Its eight corners are joined by the twelve edge springs; inside, one
 * {@link TensegrityElement} whose twelve nodes lie two per face of the cube,
 * each tied by springs to the four corners of its face. The nodes on the bottom
 * face (four corners and the feet of the two vertical struts) are fixed. The same
 * sinusoidal force acts on the two upper element nodes (on the top face, the heads
 * of the vertical struts), pointing down and tilted by
 * {@link CubeParameters#forceTiltDeg()} towards +x; point P is the first of them.
 *
 * <p>The mass-spring cube (MSS) and the tensegrity cube (TS) are built by the
 * same code and are identical but for the six rigid links (the struts) of the TS.
 */
public final class CubeScene {
    /** The authored topology. */
    public final Topology topology;
    /** The nodes that carry the sinusoidal force. */
    public final List<Node> loaded;
    /** Point P, whose displacement the paper plots. */
    public final Node probe;
    /** Whether this is the tensegrity cube. */
    public final boolean tensegrity;
    public final CubeParameters parameters;

    private CubeScene(Topology t, List<Node> loaded, Node probe, boolean tensegrity, CubeParameters p) {
        this.topology = t;
        this.loaded = loaded;
        this.probe = probe;
        this.tensegrity = tensegrity;
        this.parameters = p;
    }

    /** The mass-spring cube. */
    public static CubeScene massSpring(CubeParameters p) {
        return build(p, false);
    }

    /** The tensegrity cube. */
    public static CubeScene tensegrity(CubeParameters p) {
        return build(p, true);
    }

    public static CubeScene build(CubeParameters p, boolean rigid) {
        Topology t = new Topology();
        double a = p.sideM();
        Node[] corner = addStructure(t, a, p.nodeMassKg(), p.stiffnessNPerM(), p.dampingNsPerM(), true, rigid);
        List<Node> top = new ArrayList<>();
        for (Node n : t.nodes()) {
            double y = n.position().y();
            if (Math.abs(y) < 1e-9 * a) {
                n.fix();
            } else if (Math.abs(y - a) < 1e-9 * a && !isCorner(n, corner)) {
                top.add(n);
            }
        }
        ForceLaw law = ForceLaw.sinusoid(p.forceAmplitudeN(), p.forceFrequencyHz(), 0, p.forceDirection());
        for (Node n : top) {
            t.applyForce(n, law);
        }
        return new CubeScene(t, List.copyOf(top), top.get(0), rigid, p);
    }

    /**
     * Adds the cube's nodes and springs to a topology, without fixed nodes or loads: the eight corners first
     * (node i at ((i&1) a, (i>>1&1) a, (i>>2&1) a)), joined by the twelve edge springs, then, with
     * {@code element}, the twelve nodes of the {@link TensegrityElement} (half size a/2, half spacing a/4,
     * centred), each tied to the four corners of its face. Returns the corners.
     *
     * @param a       side, m
     * @param m       mass of every node, kg
     * @param k       stiffness of every spring, N/m
     * @param c       axial damping of every spring, N s/m
     * @param element whether the element is inside
     * @param rigid   whether its six struts are rigid links (the tensegrity cube) or absent (mass-spring)
     */
    public static Node[] addStructure(Topology t, double a, double m, double k, double c, boolean element,
            boolean rigid) {
        double h = a / 2;
        Node[] corner = new Node[8];
        for (int i = 0; i < 8; i++) {
            corner[i] = t.addNode((i & 1) * a, ((i >> 1) & 1) * a, ((i >> 2) & 1) * a, m);
        }
        for (int i = 0; i < 8; i++) {
            for (int bit = 1; bit < 8; bit <<= 1) {
                if ((i & bit) == 0) {
                    t.addSpring(corner[i], corner[i | bit], k, c);
                }
            }
        }
        if (!element) {
            return corner;
        }
        TensegrityElement e = TensegrityElement.build(t, new Vec3(h, h, h), h, h / 2, m, k, c, rigid);
        // Tie each element node to the four corners of the cube face it lies on.
        for (Node n : e.nodes) {
            Vec3 q = n.position();
            double[] coord = {q.x(), q.y(), q.z()};
            for (int axis = 0; axis < 3; axis++) {
                boolean onLow = Math.abs(coord[axis]) < 1e-9 * a;
                boolean onHigh = Math.abs(coord[axis] - a) < 1e-9 * a;
                if (!onLow && !onHigh) {
                    continue;
                }
                int bit = 1 << axis;
                for (int i = 0; i < 8; i++) {
                    if (((i & bit) != 0) == onHigh) {
                        t.addSpring(n, corner[i], k, c);
                    }
                }
            }
        }
        return corner;
    }

    private static boolean isCorner(Node n, Node[] corners) {
        for (Node c : corners) {
            if (c == n) {
                return true;
            }
        }
        return false;
    }
}

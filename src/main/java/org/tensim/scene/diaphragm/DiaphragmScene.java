package org.tensim.scene.diaphragm;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.solver.Simulation;

/**
 * The paper's diaphragm (section 3.2), built from two boundary surfaces: muscle as a
 * mass-spring system, the central tendon as tensegrity (rigid links across the
 * thickness), attached to rigid ribs moved by finite-helical-axis laws and to a
 * very stiff sternum-cartilage mass-spring, and contracted by vertical action lines.
 * One call ({@link #build}) returns everything a run, a test or a viewer needs.
 *
 * <p>Node ids: {@code 0 .. diaphragmNodes()-1} are the mesh's vertices, in mesh
 * order; the sternum and rib nodes follow.
 *
 * <p><b>Mass.</b> {@code m_i = rho A_i t / 2}: A_i is the vertex's third of the
 * area of its triangles, t the shell thickness (each face carries half).
 *
 * <p><b>Springs.</b> Every mesh edge is a spring of stiffness
 * {@code k_e = E (t / 2) sum(A_T) / |e|^2} over the triangles T on the edge (Van
 * Gelder 1998's membrane formula; for an equilateral triangle it gives
 * {@code sqrt(3)/4 E h} per triangle, Lloyd, Szekely and Harders 2007), E of the
 * muscle or, when both ends are tendon, of the tendon (in-plane: the tendon's fibres
 * run in the surface). Across the thickness
 * (computed at start, as the paper does) each upper node u is joined to its nearest
 * lower node and to the nearest lower nodes of its upper neighbours (diagonals that
 * resist the faces sliding over each other); these n_u springs share the node's
 * column, {@code k = E_muscle A_u / (n_u L)} (in the tendon too, whose thickness the
 * rigid links hold).
 *
 * <p><b>Tendon and rigid links.</b> Nodes on the side of the plane that its normal
 * points to are tendon. Heuristic for the rigid links: candidate pairs are each
 * tendon node with its nearest node on the other surface (also tendon); they are
 * taken shortest first, each node at most once, and only when their length is
 * 0.3 to 2.5 times the thickness. Each node therefore carries at most one rigid
 * link: the struts are disjoint, which is the tensegrity principle ("compression
 * discontinuous", paper section 2.1), and it makes the projection exact in a single
 * Gauss-Seidel sweep. A spring along a rigid link is left out.
 *
 * <p><b>Damping.</b> Axial damping {@code c = beta k} on every spring, with
 * {@code beta = 2 zeta_high / w_max}, gives the highest mode the damping ratio
 * zeta_high (RK2 needs damping, PHYSICS.md); global viscous damping
 * {@code c = alpha m_mean} stands for the surrounding organs and damps the slow modes.
 */
public final class DiaphragmScene {
    /** Node labels for viewers and VTK output. */
    public static final int MUSCLE = 0;
    public static final int TENDON = 1;
    public static final int RIB = 2;
    public static final int STERNUM_CARTILAGE = 3;

    private final Topology topology;
    private final TwoSurfaces surfaces;
    private final int[] labels;
    private final RibCage cage;
    private final int apex;
    private final DiaphragmControls controls;
    private final BreathingCycle cycle;
    private final ActionLines actionLines;
    private final int attachedToRibs;
    private final int attachedToCartilage;
    private final int attachedToSpine;
    private final boolean[] attached;
    private final double omegaMax;
    private final double timeStep;
    private final double tendonAreaFraction;
    private final int firstAnchor;

    private DiaphragmScene(Builder b) {
        this.topology = b.t;
        this.surfaces = b.surfaces;
        this.labels = b.labels;
        this.cage = b.cage;
        this.apex = b.apex;
        this.controls = b.controls;
        this.cycle = b.cycle;
        this.actionLines = b.lines;
        this.attachedToRibs = b.attachedRibs;
        this.attachedToCartilage = b.attachedCartilage;
        this.attachedToSpine = b.attachedSpine;
        this.attached = b.attached;
        this.omegaMax = b.omegaMax;
        this.timeStep = b.dt;
        this.tendonAreaFraction = b.tendonFraction;
        this.firstAnchor = b.firstAnchor;
    }

    /**
     * Builds the scene.
     *
     * @param surfaces the diaphragm's two boundary surfaces (metres)
     * @param boxes    rib and sternum boxes, metres (see {@link RibCage})
     * @param lines    action lines; null for the default (see {@link #defaultActionLines})
     */
    public static DiaphragmScene build(TwoSurfaces surfaces, Map<String, double[]> boxes, DiaphragmParameters p,
            BreathingCycle cycle, DiaphragmControls controls, List<ActionLines.Line> lines) {
        Builder b = new Builder(surfaces, p, cycle, controls);
        b.nodes();
        b.tendon();
        b.meshSprings();
        b.rigidLinks();
        b.thicknessSprings();
        b.cage = RibCage.build(b.t, b.springs, boxes, p, cycle, controls);
        b.attach();
        b.muscle(lines == null ? defaultActionLines(surfaces) : lines);
        b.support();
        b.damping();
        return new DiaphragmScene(b);
    }

    /**
     * Two action lines through the highest points of the right and left halves of the
     * upper surface (the domes), each with a radius of action of 0.3 times the
     * mesh's transverse width.
     */
    public static List<ActionLines.Line> defaultActionLines(TwoSurfaces s) {
        TriangleMesh m = s.mesh();
        double[] bounds = m.bounds();
        double cx = 0.5 * (bounds[0] + bounds[3]);
        double radius = 0.3 * (bounds[3] - bounds[0]);
        int[] top = {-1, -1};
        for (int v = 0; v < m.vertexCount(); v++) {
            if (!s.isUpper(v)) {
                continue;
            }
            int side = m.coord(v, 0) < cx ? 0 : 1;
            if (top[side] < 0 || m.coord(v, 2) > m.coord(top[side], 2)) {
                top[side] = v;
            }
        }
        List<ActionLines.Line> l = new ArrayList<>();
        for (int v : top) {
            if (v >= 0) {
                l.add(new ActionLines.Line(m.coord(v, 0), m.coord(v, 1), radius));
            }
        }
        return l;
    }

    /** A new simulation of this scene with the paper's RK2 integrator, at rest at t = 0. */
    public Simulation newSimulation() {
        Simulation sim = Simulation.of(topology);
        // Disjoint links: one sweep is exact; a tolerance still guards the general case.
        sim.projection().setTolerance(1e-9).setMaxIterations(50);
        return sim;
    }

    public Topology topology() {
        return topology;
    }

    public TwoSurfaces surfaces() {
        return surfaces;
    }

    /** Number of diaphragm nodes (the mesh's vertices: node ids 0 .. n-1). */
    public int diaphragmNodes() {
        return surfaces.mesh().vertexCount();
    }

    /** Triangles of the upper surface, as node ids (3 per triangle), for a viewer. */
    public int[] upperTriangles() {
        int[] ut = surfaces.upperTriangles();
        int[] out = new int[3 * ut.length];
        for (int i = 0; i < ut.length; i++) {
            for (int k = 0; k < 3; k++) {
                out[3 * i + k] = surfaces.mesh().corner(ut[i], k);
            }
        }
        return out;
    }

    /** All mesh triangles (both faces), as node ids. */
    public int[] allTriangles() {
        return surfaces.mesh().triangles();
    }

    /**
     * Nodes {@code 0 .. simulatedNodes()-1} are the diaphragm and the cage; the fixed anchors of the
     * abdominal support follow (they never move and are left out of outputs).
     */
    public int simulatedNodes() {
        return firstAnchor;
    }

    /** Fixed anchor nodes of the abdominal support. */
    public int anchorNodes() {
        return topology.nodeCount() - firstAnchor;
    }

    /** Label per node: {@link #MUSCLE}, {@link #TENDON}, {@link #RIB}, {@link #STERNUM_CARTILAGE}. */
    public int[] labels() {
        return labels.clone();
    }

    public boolean isTendon(int node) {
        return labels[node] == TENDON;
    }

    public RibCage cage() {
        return cage;
    }

    /** The dome apex probe: the highest upper-surface node at rest that is not attached. */
    public int apexNode() {
        return apex;
    }

    public DiaphragmControls controls() {
        return controls;
    }

    public BreathingCycle cycle() {
        return cycle;
    }

    public ActionLines actionLines() {
        return actionLines;
    }

    /** Diaphragm nodes attached to ribs (driven rigidly with their rib). */
    public int attachedToRibs() {
        return attachedToRibs;
    }

    /** Diaphragm nodes tied by springs to cartilage or sternum. */
    public int attachedToCartilage() {
        return attachedToCartilage;
    }

    /** Diaphragm nodes fixed to the spine (crura). */
    public int attachedToSpine() {
        return attachedToSpine;
    }

    /** Whether diaphragm node v is attached to ribs, cartilage, sternum or spine (its origins). */
    public boolean isAttached(int v) {
        return v < attached.length && attached[v];
    }

    public int attachedNodes() {
        return attachedToRibs + attachedToCartilage + attachedToSpine;
    }

    /** Share of the upper surface's area that is tendon. */
    public double tendonAreaFraction() {
        return tendonAreaFraction;
    }

    /** Gershgorin bound on the highest angular frequency of the network, rad/s. */
    public double omegaMaxBound() {
        return omegaMax;
    }

    /** The recommended time step for RK2, s (see {@link Rk2Step}). */
    public double recommendedTimeStep() {
        return timeStep;
    }

    /** Collects the pieces while building (one concept: the build order). */
    private static final class Builder {
        final TwoSurfaces surfaces;
        final TriangleMesh mesh;
        final DiaphragmParameters p;
        final BreathingCycle cycle;
        final DiaphragmControls controls;
        final Topology t = new Topology();
        final SpringList springs = new SpringList();
        final int nv;
        final double thickness;
        double[] area;
        int[] labels;
        boolean[] linked;
        Set<Long> linkPairs = new HashSet<>();
        RibCage cage;
        int apex = -1;
        ActionLines lines;
        int attachedRibs;
        int attachedCartilage;
        int attachedSpine;
        boolean[] attached;
        double omegaMax;
        double dt;
        double tendonFraction;
        int firstAnchor;
        final List<int[]> supportSprings = new ArrayList<>();
        final List<Double> supportK = new ArrayList<>();

        Builder(TwoSurfaces s, DiaphragmParameters p, BreathingCycle c, DiaphragmControls ctl) {
            this.surfaces = s;
            this.mesh = s.mesh();
            this.p = p;
            this.cycle = c;
            this.controls = ctl;
            this.nv = mesh.vertexCount();
            this.thickness = s.thicknessM();
        }

        void nodes() {
            area = SurfaceGeometry.vertexAreas(mesh);
            for (int v = 0; v < nv; v++) {
                double m = p.densityKgPerM3() * area[v] * thickness / 2;
                if (!(m > 0)) {
                    throw new IllegalArgumentException("mesh vertex " + v + " belongs to no triangle of positive area;"
                            + " clean the mesh first");
                }
                t.addNode(mesh.coord(v, 0), mesh.coord(v, 1), mesh.coord(v, 2), m);
            }
        }

        void tendon() {
            Vec3 n = p.tendonNormal();
            double cut;
            if (p.tendonPoint() != null) {
                cut = n.dot(p.tendonPoint());
            } else {
                // The plane's offset that leaves tendonAreaFraction of the upper area on its positive side.
                Integer[] order = new Integer[nv];
                double total = 0;
                int k = 0;
                for (int v = 0; v < nv; v++) {
                    if (surfaces.isUpper(v)) {
                        order[k++] = v;
                        total += area[v];
                    }
                }
                Integer[] up = Arrays.copyOf(order, k);
                Arrays.sort(up, (a, b) -> Double.compare(height(n, b), height(n, a)));
                double acc = 0;
                cut = height(n, up[0]);
                for (Integer v : up) {
                    acc += area[v];
                    cut = height(n, v);
                    if (acc >= p.tendonAreaFraction() * total) {
                        break;
                    }
                }
            }
            labels = new int[nv];
            double tendonArea = 0;
            double upperArea = 0;
            for (int v = 0; v < nv; v++) {
                labels[v] = height(n, v) >= cut ? TENDON : MUSCLE;
                if (surfaces.isUpper(v)) {
                    upperArea += area[v];
                    tendonArea += labels[v] == TENDON ? area[v] : 0;
                }
            }
            tendonFraction = tendonArea / upperArea;
        }

        private double height(Vec3 n, int v) {
            return n.x() * mesh.coord(v, 0) + n.y() * mesh.coord(v, 1) + n.z() * mesh.coord(v, 2);
        }

        private double young(int a, int b) {
            return labels[a] == TENDON && labels[b] == TENDON ? p.tendonYoungPa() : p.muscleYoungPa();
        }

        void meshSprings() {
            // sum of the areas of the triangles on each edge, then k = E (t/2) sum / |e|^2
            java.util.Map<Long, double[]> edgeArea = new java.util.HashMap<>();
            for (int tr = 0; tr < mesh.triangleCount(); tr++) {
                double a = mesh.area(tr);
                for (int k = 0; k < 3; k++) {
                    int i = mesh.corner(tr, k);
                    int j = mesh.corner(tr, (k + 1) % 3);
                    edgeArea.computeIfAbsent(key(i, j), x -> new double[1])[0] += a;
                }
            }
            List<Long> keys = new ArrayList<>(edgeArea.keySet());
            Collections.sort(keys); // deterministic order
            for (long e : keys) {
                int i = (int) (e >>> 32);
                int j = (int) e;
                double len = TwoSurfaces.distance(mesh, i, j);
                springs.add(i, j, young(i, j) * (thickness / 2) * edgeArea.get(e)[0] / (len * len));
            }
            bendingSprings(edgeArea);
        }

        /**
         * Across every edge shared by two triangles of the same face, a spring between the two
         * opposite vertices: it resists folding about the edge (as in cloth models), which keeps
         * the thin compressed walls from buckling at the scale of the mesh.
         */
        private void bendingSprings(java.util.Map<Long, double[]> edgeArea) {
            if (p.bendingFactor() == 0) {
                return;
            }
            java.util.Map<Long, Integer> firstOpposite = new java.util.HashMap<>();
            for (int tr = 0; tr < mesh.triangleCount(); tr++) {
                for (int k = 0; k < 3; k++) {
                    int i = mesh.corner(tr, k);
                    int j = mesh.corner(tr, (k + 1) % 3);
                    int o = mesh.corner(tr, (k + 2) % 3);
                    if (surfaces.isUpper(i) != surfaces.isUpper(o) || surfaces.isUpper(j) != surfaces.isUpper(o)
                            || surfaces.isUpper(i) != surfaces.isUpper(j)) {
                        continue;
                    }
                    Integer other = firstOpposite.putIfAbsent(key(i, j), o);
                    if (other != null && other != o) {
                        double len = TwoSurfaces.distance(mesh, o, other);
                        double a = edgeArea.get(key(i, j))[0];
                        springs.add(o, other, p.bendingFactor() * young(o, other) * (thickness / 2) * a / (len * len));
                    }
                }
            }
        }

        void rigidLinks() {
            linked = new boolean[nv];
            List<int[]> cand = new ArrayList<>();
            for (int v = 0; v < nv; v++) {
                int q = surfaces.partner(v);
                if (labels[v] == TENDON && q >= 0 && labels[q] == TENDON) {
                    cand.add(surfaces.isUpper(v) ? new int[] {v, q} : new int[] {q, v});
                }
            }
            cand.sort((x, y) -> Double.compare(TwoSurfaces.distance(mesh, x[0], x[1]),
                    TwoSurfaces.distance(mesh, y[0], y[1])));
            for (int[] c : cand) {
                double len = TwoSurfaces.distance(mesh, c[0], c[1]);
                if (linked[c[0]] || linked[c[1]] || len < 0.3 * thickness || len > 2.5 * thickness) {
                    continue;
                }
                linked[c[0]] = true;
                linked[c[1]] = true;
                linkPairs.add(key(c[0], c[1]));
                t.addRigidLink(t.node(c[0]), t.node(c[1]));
            }
        }

        void thicknessSprings() {
            List<Set<Integer>> neighbours = new ArrayList<>();
            for (int v = 0; v < nv; v++) {
                neighbours.add(new HashSet<>());
            }
            for (int tr = 0; tr < mesh.triangleCount(); tr++) {
                for (int k = 0; k < 3; k++) {
                    int i = mesh.corner(tr, k);
                    int j = mesh.corner(tr, (k + 1) % 3);
                    neighbours.get(i).add(j);
                    neighbours.get(j).add(i);
                }
            }
            boolean[] connected = new boolean[nv];
            double maxLen = 3 * thickness;
            for (int u = 0; u < nv; u++) {
                if (!surfaces.isUpper(u)) {
                    continue;
                }
                Set<Integer> targets = new java.util.TreeSet<>();
                targets.add(surfaces.partner(u));
                for (int j : neighbours.get(u)) {
                    if (surfaces.isUpper(j)) {
                        targets.add(surfaces.partner(j));
                    }
                }
                final int up = u;
                targets.removeIf(l -> l < 0 || surfaces.isUpper(l) || springs.contains(up, l)
                        || linkPairs.contains(key(up, l)) || TwoSurfaces.distance(mesh, up, l) > maxLen);
                for (int l : targets) {
                    double len = TwoSurfaces.distance(mesh, u, l);
                    // Across the thickness the tendon is held by its rigid links; its springs there are muscle-like.
                    springs.add(u, l, p.muscleYoungPa() * area[u] / (targets.size() * len));
                    connected[u] = true;
                    connected[l] = true;
                }
                connected[u] |= linked[u];
            }
            for (int l = 0; l < nv; l++) {
                int u = surfaces.partner(l);
                if (surfaces.isUpper(l) || connected[l] || linked[l] || u < 0 || springs.contains(u, l)) {
                    continue;
                }
                double len = TwoSurfaces.distance(mesh, u, l);
                if (len > 0 && len <= maxLen) {
                    springs.add(u, l, p.muscleYoungPa() * area[l] / len);
                }
            }
        }

        void attach() {
            attached = new boolean[nv];
            List<RibCage.Segment> segs = cage.segments();
            for (int v = 0; v < nv; v++) {
                Vec3 q = t.node(v).position();
                RibCage.Segment best = null;
                double bestD = Double.POSITIVE_INFINITY;
                for (RibCage.Segment s : segs) {
                    double d = RibCage.distance(t, s, q);
                    if (d < bestD) {
                        bestD = d;
                        best = s;
                    }
                }
                if (best == null || bestD > p.attachThresholdM()) {
                    continue;
                }
                attached[v] = true;
                if (best.kind() == RibCage.Kind.RIB) {
                    t.node(v).drive(best.motion());
                    attachedRibs++;
                } else if (best.kind() == RibCage.Kind.SPINE) {
                    t.node(v).fix();
                    attachedSpine++;
                } else {
                    springs.add(v, best.a(), p.attachStiffness());
                    springs.add(v, best.b(), p.attachStiffness());
                    attachedCartilage++;
                }
            }
            int[] all = new int[t.nodeCount()];
            System.arraycopy(labels, 0, all, 0, nv);
            for (int i : cage.sternumNodes()) {
                all[i] = STERNUM_CARTILAGE;
            }
            for (int i : cage.ribNodes()) {
                all[i] = RIB;
            }
            for (int i : cage.spineNodes()) {
                all[i] = RIB;
            }
            labels = all;
            for (int v = 0; v < nv; v++) {
                Node n = t.node(v);
                if (surfaces.isUpper(v) && !n.isDriven() && !n.isFixed() && (apex < 0 || mesh.coord(v, 2) > mesh.coord(apex, 2))) {
                    apex = v;
                }
            }
        }

        void muscle(List<ActionLines.Line> l) {
            lines = new ActionLines(l, cycle, controls);
            for (int v = 0; v < nv; v++) {
                if (labels[v] != MUSCLE || t.node(v).isDriven() || t.node(v).isFixed()) {
                    continue;
                }
                double w = lines.weight(mesh.coord(v, 0), mesh.coord(v, 1));
                if (w > 0) {
                    t.applyForce(t.node(v), lines.lawFor(w * area[v] / 2));
                }
            }
        }

        /** Anchors (fixed nodes, added last) and zero-length springs K A_i for the free lower-surface nodes. */
        void support() {
            firstAnchor = t.nodeCount();
            if (p.abdominalSupportPaPerM() == 0) {
                return;
            }
            for (int v = 0; v < nv; v++) {
                Node n = t.node(v);
                if (surfaces.isUpper(v) || n.isDriven() || n.isFixed()) {
                    continue;
                }
                Node anchor = t.addNode(n.position(), n.mass()).fix();
                supportSprings.add(new int[] {v, anchor.id()});
                supportK.add(p.abdominalSupportPaPerM() * area[v] / 2);
            }
        }

        void damping() {
            omegaMax = springs.omegaMaxBound(t, supportSprings, supportK);
            double beta = 2 * p.highDampingRatio() / omegaMax;
            springs.addTo(t, beta);
            for (int i = 0; i < supportSprings.size(); i++) {
                int[] pair = supportSprings.get(i);
                double k = supportK.get(i);
                t.addSpring(pair[0], pair[1], k, 0, beta * k);
            }
            double meanMass = 0;
            for (int v = 0; v < nv; v++) {
                meanMass += t.node(v).mass();
            }
            meanMass /= nv;
            double alpha = p.viscousPerS();
            t.setViscousDamping(alpha * meanMass);
            dt = Rk2Step.stable(omegaMax, beta, alpha) * Rk2Step.SAFETY;
        }

        private static long key(int i, int j) {
            return ((long) Math.min(i, j) << 32) | Math.max(i, j);
        }
    }
}

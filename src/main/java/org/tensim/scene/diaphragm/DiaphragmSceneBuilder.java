package org.tensim.scene.diaphragm;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;

/**
 * Builds a {@link DiaphragmScene} step by step, in this order: nodes, tendon, membrane and
 * bending springs, rigid links, thickness springs, cage, attachment, muscle, abdominal
 * support, damping (package-private; the formulas are documented on DiaphragmScene, the
 * attachment band on {@link AttachmentBand}, the muscle's load on {@link MusclePressure}).
 */
final class DiaphragmSceneBuilder {

    final TwoSurfaces surfaces;
    final TriangleMesh mesh;
    final DiaphragmParameters p;
    final BreathingCycle cycle;
    final DiaphragmControls controls;
    final BoundaryConditions bc;
    final Topology t = new Topology();
    final SpringList springs = new SpringList();
    final int nv;
    final double thickness;
    /** Smallest node mass, as a fraction of the median node's. */
    static final double MASS_FLOOR = 0.3;
    double addedMass;
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
    /** Offset of the tendon plane: points x with {@code normal . x >= tendonCut} are tendon, m. */
    double tendonCut;
    int firstAnchor = -1;
    /** Zero-length springs to anchor nodes (abdominal support, attachment band) and their stiffness, N/m. */
    final List<int[]> supportSprings = new ArrayList<>();
    final List<Double> supportK = new ArrayList<>();

    DiaphragmSceneBuilder(TwoSurfaces s, DiaphragmParameters p, BreathingCycle c, DiaphragmControls ctl,
            BoundaryConditions bc) {
        this.bc = bc;
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
        // Mass floor: a few vertices of sliver triangles (real meshes) would carry almost no mass and
        // set the highest frequency alone; their mass is raised to MASS_FLOOR times the median's.
        double[] sorted = area.clone();
        Arrays.sort(sorted);
        double floor = MASS_FLOOR * sorted[sorted.length / 2];
        for (int v = 0; v < nv; v++) {
            if (!(area[v] > 0)) {
                throw new IllegalArgumentException("mesh vertex " + v + " belongs to no triangle of positive area;"
                        + " clean the mesh first");
            }
            double m = p.densityKgPerM3() * Math.max(area[v], floor) * thickness / 2;
            addedMass += p.densityKgPerM3() * (Math.max(area[v], floor) - area[v]) * thickness / 2;
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
        tendonCut = cut;
        labels = new int[nv];
        double tendonArea = 0;
        double upperArea = 0;
        for (int v = 0; v < nv; v++) {
            labels[v] = height(n, v) >= cut ? DiaphragmScene.TENDON : DiaphragmScene.MUSCLE;
            if (surfaces.isUpper(v)) {
                upperArea += area[v];
                tendonArea += labels[v] == DiaphragmScene.TENDON ? area[v] : 0;
            }
        }
        tendonFraction = tendonArea / upperArea;
    }

    private double height(Vec3 n, int v) {
        return n.x() * mesh.coord(v, 0) + n.y() * mesh.coord(v, 1) + n.z() * mesh.coord(v, 2);
    }

    private double young(int a, int b) {
        return labels[a] == DiaphragmScene.TENDON && labels[b] == DiaphragmScene.TENDON ? p.tendonYoungPa() : p.muscleYoungPa();
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
            if (labels[v] == DiaphragmScene.TENDON && q >= 0 && labels[q] == DiaphragmScene.TENDON) {
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
            double longestEdge = 0;
            for (int j : neighbours.get(u)) {
                longestEdge = Math.max(longestEdge, TwoSurfaces.distance(mesh, u, j));
                if (surfaces.isUpper(j)) {
                    targets.add(surfaces.partner(j));
                }
            }
            // The diagonals couple the two faces in shear: they must exist at every element size, so the
            // cap (against a partner found on the far side of a badly paired mesh) grows with the local
            // edge length. A cap of 3 thicknesses alone dropped every diagonal on meshes coarser than
            // about 7 mm and left the faces free to slide (docs/diaphragm.md, resolution study).
            final double cap = 3 * (thickness + longestEdge);
            final int up = u;
            targets.removeIf(l -> l < 0 || surfaces.isUpper(l) || springs.contains(up, l)
                    || linkPairs.contains(key(up, l)) || TwoSurfaces.distance(mesh, up, l) > cap);
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
        if (bc.attachment() == BoundaryConditions.Attachment.BAND) {
            AttachmentBand.attach(this, bc);
        } else {
            ThresholdAttachment.attach(this);
        }
        int[] all = new int[t.nodeCount()];
        System.arraycopy(labels, 0, all, 0, nv);
        for (int i : cage.sternumNodes()) {
            all[i] = DiaphragmScene.STERNUM_CARTILAGE;
        }
        for (int i : cage.ribNodes()) {
            all[i] = DiaphragmScene.RIB;
        }
        for (int i : cage.spineNodes()) {
            all[i] = DiaphragmScene.RIB;
        }
        labels = all;
        for (int v = 0; v < nv; v++) {
            Node n = t.node(v);
            boolean held = n.isDriven() || n.isFixed() || (bc.attachment() == BoundaryConditions.Attachment.BAND
                    && attached[v]);
            if (surfaces.isUpper(v) && !held && (apex < 0 || mesh.coord(v, 2) > mesh.coord(apex, 2))) {
                apex = v;
            }
        }
    }

    /** Nodes added from now on are anchors (fixed or driven; left out of outputs). */
    void markFirstAnchor() {
        if (firstAnchor < 0) {
            firstAnchor = t.nodeCount();
        }
    }

    /** A zero-length spring of stiffness k (N/m) from diaphragm node v to anchor node a. */
    void tie(int v, int a, double k) {
        supportSprings.add(new int[] {v, a});
        supportK.add(k);
    }

    void muscle(List<ActionLines.Line> l) {
        lines = new ActionLines(l, cycle, controls);
        double[] w = MusclePressure.weights(mesh, lines, bc.muscleLoad(), p.tendonNormal(), tendonCut, labels, area);
        for (int v = 0; v < nv; v++) {
            if (w[v] > 0 && !t.node(v).isDriven() && !t.node(v).isFixed()) {
                t.applyForce(t.node(v), lines.lawFor(w[v]));
            }
        }
    }

    /** Anchors (fixed nodes, added last) and zero-length springs K A_i for the free lower-surface nodes. */
    void support() {
        markFirstAnchor();
        if (p.abdominalSupportPaPerM() == 0) {
            return;
        }
        for (int v = 0; v < nv; v++) {
            Node n = t.node(v);
            if (surfaces.isUpper(v) || n.isDriven() || n.isFixed()) {
                continue;
            }
            tie(v, t.addNode(n.position(), n.mass()).fix().id(), p.abdominalSupportPaPerM() * area[v] / 2);
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

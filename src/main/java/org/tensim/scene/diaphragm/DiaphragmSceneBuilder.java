package org.tensim.scene.diaphragm;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.shell.ShellMaterial;
import org.tensim.scene.shell.ShellNetwork;
import org.tensim.scene.shell.SurfaceGeometry;
import org.tensim.scene.shell.TwoSurfaces;
import org.tensim.solver.stability.ModalBounds;

/**
 * Builds a {@link DiaphragmScene}: {@link #build} runs the named steps in their order (nodes,
 * tendon, membrane and bending springs, rigid links, thickness springs, cage, attachment,
 * thickness columns, muscle, abdominal support, damping) on private state, and hands everything
 * the scene holds back as one {@link DiaphragmParts} record. The formulas are documented on
 * DiaphragmScene, the attachment band on {@link AttachmentBand}, the muscle's load on
 * {@link MusclePressure} or {@link MuscleFibres}. The few fields left package-visible are the attachment strategies'
 * view of the build ({@link AttachmentBand}, {@link ThresholdAttachment}): the mesh, the
 * topology and springs being built, the node areas and the cage, and what they record.
 */
final class DiaphragmSceneBuilder {
    /** Runs every step, in its order, and returns what the scene holds. */
    static DiaphragmParts build(TwoSurfaces surfaces, Map<String, double[]> boxes, Bones bones,
            org.tensim.io.mesh.VertexLabel[] vertexLabels, DiaphragmSpec spec, BreathingCycle cycle,
            DiaphragmControls controls, List<ActionLines.Line> actionLines) {
        if (vertexLabels != null && vertexLabels.length != surfaces.mesh().vertexCount()) {
            throw new IllegalArgumentException("the label file has " + vertexLabels.length + " labels for a mesh of "
                    + surfaces.mesh().vertexCount() + " vertices");
        }
        DiaphragmParameters p = spec.tissue();
        DiaphragmSceneBuilder b = new DiaphragmSceneBuilder(surfaces, p, cycle, controls, spec.boundary());
        b.bones = bones;
        b.spec = spec;
        b.vertexLabels = vertexLabels;
        b.nodes();
        b.tendon();
        b.meshSprings();
        b.rigidLinks();
        b.thicknessSprings();
        boolean sweptCage = spec.cage().surfaces() && spec.cage().thorax() == null; // --cage surfaces
        if (bones != null && !sweptCage) {
            ThoraxCage.Built tc = ThoraxCage.build(b.t, b.springs, bones, p, cycle, controls);
            b.cage = tc.cage();
            b.boneMotions = tc.motions();
        } else {
            b.cage = RibCage.build(b.t, b.springs, boxes, p, cycle, controls);
            b.boneMotions = bones == null ? null : ParametricBones.motions(bones, b.cage, b.t);
        }
        b.attach();
        b.contact();
        b.columnLinks();
        b.muscle(actionLines);
        if (spec.breathing().abdominalPressurePa() > 0) {
            AbdominalPressure.add(b.t, surfaces, b.area, cycle, spec.breathing().abdominalPressurePa(), null);
        }
        if (bones != null && spec.cage().contact() && spec.cage().appositionPressurePa() > 0) {
            // The rise follows the muscle's live action: P at the load's default amplitude, none with the muscle off.
            b.appositionArea = AbdominalPressure.add(b.t, surfaces, b.area, cycle, spec.cage().appositionPressurePa(),
                    AppositionZone.lowerVertices(surfaces, bones), controls,
                    DiaphragmSetup.defaultMusclePa(spec.boundary().muscleLoad()));
        }
        b.support();
        b.damping();
        return new DiaphragmParts(p, b.t, surfaces, b.labels, b.cage, b.apex, controls, cycle, b.lines, b.attachedRibs,
                b.attachedCartilage, b.attachedSpine, b.attached, b.modes, b.tendonFraction, b.firstAnchor,
                b.addedMass, b.attachedPerBone, b.contactPairs, b.appositionArea);
    }

    // Inputs.
    final TwoSurfaces surfaces;
    final TriangleMesh mesh;
    final DiaphragmParameters p;
    private final BreathingCycle cycle;
    private final DiaphragmControls controls;
    private final BoundaryConditions bc;
    final int nv;
    private final double thickness;
    /** Smallest node mass, as a fraction of the median node's. */
    private static final double MASS_FLOOR = 0.3;

    private Bones bones;
    private DiaphragmSpec spec;
    /** Per vertex, a label file's labels (null: the rules). */
    private org.tensim.io.mesh.VertexLabel[] vertexLabels;
    /** Per vertex, tendon by a label file or the geodesic rule (null: the plane's cap). */
    private boolean[] tendonRegion;
    /** The geodesic rule's signed distance to the tendon's edge per vertex, m ({@link GeodesicTendon.Region#level}). */
    private double[] tendonLevel;
    private org.tensim.model.RigidMotion[] boneMotions;
    private Map<String, double[]> attachedPerBone = Map.of();
    private Map<String, Integer> contactPairs = Map.of();
    /** The lower-face area the pressure on the zone of apposition acts on, m^2 (0: none). */
    private double appositionArea;

    // Built by the steps; the attachment strategies read and extend the package-visible ones.
    final Topology t = new Topology();
    final SpringList springs = new SpringList();
    double[] area;
    RibCage cage;
    boolean[] attached;
    /** Per diaphragm node, distance to the nearest cage segment the band ties to, m (null: no band). */
    double[] originDistance;
    int attachedRibs;
    int attachedCartilage;
    int attachedSpine;
    private double addedMass;
    private int[] labels;
    private boolean[] linked;
    private final Set<Long> linkPairs = new HashSet<>();
    private ShellNetwork network;
    private final List<int[]> pendingColumns = new ArrayList<>();
    private int apex = -1;
    private ActionLines lines;
    private double omegaMax;
    private ModalBounds modes;
    private double tendonFraction;
    /** Offset of the tendon plane: points x with {@code normal . x >= tendonCut} are tendon, m. */
    private double tendonCut;
    private int firstAnchor = -1;
    /** Zero-length springs to anchor nodes (abdominal support, attachment band) and their stiffness, N/m. */
    private final List<int[]> supportSprings = new ArrayList<>();
    private final List<Double> supportK = new ArrayList<>();

    private DiaphragmSceneBuilder(TwoSurfaces s, DiaphragmParameters p, BreathingCycle c, DiaphragmControls ctl,
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

    private void nodes() {
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

    private void tendon() {
        if (vertexLabels != null || spec.tendonRule() == TendonRule.GEODESIC) {
            tendonRegion = new boolean[nv];
            if (vertexLabels != null) {
                for (int v = 0; v < nv; v++) {
                    tendonRegion[v] = vertexLabels[v] == org.tensim.io.mesh.VertexLabel.TENDON;
                }
            } else {
                GeodesicTendon.Region r = GeodesicTendon.grow(surfaces, p.tendonAreaFraction());
                tendonRegion = r.tendon();
                tendonLevel = r.level();
            }
        }
        planeTendon();
        if (tendonRegion == null) {
            return;
        }
        for (int v = 0; v < nv; v++) {
            labels[v] = tendonRegion[v] ? DiaphragmScene.TENDON : DiaphragmScene.MUSCLE;
        }
        tendonFraction = tendonShare();
    }

    /** The share of the upper surface's area labelled tendon. */
    private double tendonShare() {
        double tendonArea = 0;
        double upperArea = 0;
        for (int v = 0; v < nv; v++) {
            if (surfaces.isUpper(v)) {
                upperArea += area[v];
                tendonArea += labels[v] == DiaphragmScene.TENDON ? area[v] : 0;
            }
        }
        return tendonArea / upperArea;
    }

    /** The paper's rule: the tendon is the cap on the positive side of a plane. */
    private void planeTendon() {
        Vec3 n = p.tendonNormal();
        double cut;
        if (p.tendonPoint() != null) {
            cut = n.dot(p.tendonPoint());
        } else {
            cut = TendonPlane.offsetForShare(surfaces, area, n, p.tendonAreaFraction());
        }
        tendonCut = cut;
        labels = new int[nv];
        for (int v = 0; v < nv; v++) {
            labels[v] = TendonPlane.height(surfaces, n, v) >= cut ? DiaphragmScene.TENDON : DiaphragmScene.MUSCLE;
        }
        tendonFraction = tendonShare();
    }

    private double young(int a, int b) {
        return labels[a] == DiaphragmScene.TENDON && labels[b] == DiaphragmScene.TENDON ? p.tendonYoungPa() : p.muscleYoungPa();
    }

    /** The faces' springs, by the tissue model (see {@link ShellNetwork}). */
    private void meshSprings() {
        network = new ShellNetwork(surfaces, area, this::young,
                new ShellMaterial(p.muscleYoungPa(), p.poissonRatio(), thickness, p.densityKgPerM3()),
                p.tissueModel(), p.bendingFactor());
        network.membrane(springs);
    }

    /**
     * The struts across the thickness ({@link ShellNetwork#columnPairs}): the tendon's, made now; in the
     * material model also the muscle's, made after the attachment ({@link #columnLinks}).
     */
    private void rigidLinks() {
        linked = new boolean[nv];
        boolean all = p.tissueModel().rigidColumns();
        for (int[] c : ShellNetwork.columnPairs(surfaces, v -> all || labels[v] == DiaphragmScene.TENDON)) {
            linked[c[0]] = true;
            linked[c[1]] = true;
            linkPairs.add(ShellNetwork.key(c[0], c[1]));
            if (labels[c[0]] == DiaphragmScene.TENDON && labels[c[1]] == DiaphragmScene.TENDON) {
                t.addRigidLink(t.node(c[0]), t.node(c[1]));
            } else {
                pendingColumns.add(c);
            }
        }
    }

    /**
     * The muscle's rigid columns (material model), once the attachment and the contact are known: a column whose
     * two ends are both driven or fixed (by different ribs, say) cannot be projected, and one with an end that
     * starts inside a bone (a hard contact pair of negative gap: the registered bone lies in the sheet's
     * thickness there) can be asked by the contact to put its ends out on opposite faces of the bone, farther
     * apart than its length; so either is a spring {@code E A / L} instead.
     */
    private void columnLinks() {
        boolean[] inside = new boolean[nv];
        for (org.tensim.model.ContactPair pair : t.contacts()) {
            if (pair.node() < nv && pair.gapM() < 0 && t.contactBodies().get(pair.body()).hard()) {
                inside[pair.node()] = true;
            }
        }
        for (int[] c : pendingColumns) {
            Node a = t.node(c[0]);
            Node b = t.node(c[1]);
            if ((a.isDriven() || a.isFixed()) && (b.isDriven() || b.isFixed()) || inside[c[0]] || inside[c[1]]) {
                double len = TwoSurfaces.distance(mesh, c[0], c[1]);
                springs.add(c[0], c[1], young(c[0], c[1]) * area[c[0]] / len);
            } else {
                t.addRigidLink(a, b);
            }
        }
    }

    private void thicknessSprings() {
        network.thickness(springs, linkPairs, linked);
    }

    private void attach() {
        attached = new boolean[nv];
        if (bones != null) {
            boolean[] seeds = null;
            if (vertexLabels != null) {
                seeds = new boolean[nv];
                for (int v = 0; v < nv; v++) {
                    seeds[v] = vertexLabels[v].isOrigin();
                }
            }
            attachedPerBone = OriginAttachment.attach(this, bones, boneMotions, seeds, bc.bandStiffnessPaPerM());
        } else if (bc.attachment() == BoundaryConditions.Attachment.BAND) {
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
                    || bones != null) && attached[v];
            if (surfaces.isUpper(v) && !held && (apex < 0 || mesh.coord(v, 2) > mesh.coord(apex, 2))) {
                apex = v;
            }
        }
    }

    /** Sliding contact on the bones' surfaces where the diaphragm is not attached (a thorax, contact on). */
    private void contact() {
        if (bones != null && spec.cage().contact()) {
            contactPairs = BoneContact.add(this, bones, boneMotions, spec.cage().contactStiffnessPaPerM(),
                    spec.cage().liverSupportPaPerM());
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

    private void muscle(List<ActionLines.Line> l) {
        lines = new ActionLines(l, cycle, controls);
        if (bc.muscleLoad() == BoundaryConditions.MuscleLoad.FIBRES) {
            boolean[] tendon = new boolean[nv];
            for (int v = 0; v < nv; v++) {
                tendon[v] = labels[v] == DiaphragmScene.TENDON;
            }
            double[] height = new double[nv];
            for (int v = 0; v < nv; v++) {
                // The fibres are clipped at a continuous edge (the plane's, or the geodesic distance's), so that
                // the muscle's share of a triangle cut by it does not depend on which corners are tendon.
                height[v] = tendonRegion == null ? TendonPlane.height(surfaces, p.tendonNormal(), v) - tendonCut
                        : tendonLevel != null ? tendonLevel[v] : tendon[v] ? 1 : -1;
            }
            MuscleFibres.add(t, mesh, height, tendon, area, thickness, lines,
                    FibreInsertion.activation(mesh, surfaces, originDistance, FibreInsertion.DEFAULT_LENGTH_M));
            return;
        }
        double[] w = MusclePressure.weights(mesh, lines, bc.muscleLoad(), p.tendonNormal(), tendonCut, labels, area);
        for (int v = 0; v < nv; v++) {
            if (w[v] > 0 && !t.node(v).isDriven() && !t.node(v).isFixed()) {
                t.applyForce(t.node(v), lines.lawFor(w[v]));
            }
        }
    }

    /** Anchors (fixed nodes, added last) and zero-length springs K A_i for the free lower-surface nodes. */
    private void support() {
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

    private void damping() {
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
        modes = new ModalBounds(omegaMax, beta, alpha, "Gershgorin bound");
    }
}

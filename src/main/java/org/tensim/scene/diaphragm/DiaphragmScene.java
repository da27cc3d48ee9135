package org.tensim.scene.diaphragm;

import java.util.List;
import java.util.Map;
import org.tensim.model.Topology;
import org.tensim.scene.shell.ShellNetwork;
import org.tensim.scene.shell.SurfaceGeometry;
import org.tensim.scene.shell.TissueModel;
import org.tensim.scene.shell.TwoSurfaces;
import org.tensim.solver.Integrator;
import org.tensim.solver.Simulation;
import org.tensim.solver.integrators.Integrators;
import org.tensim.solver.stability.ButcherTableau;
import org.tensim.solver.stability.ModalBounds;
import org.tensim.solver.stability.TimeStep;
import org.tensim.solver.stability.TimeStepPolicy;

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
 * area of its triangles, t the shell thickness (each face carries half). A_i is at
 * least 0.3 times the median's: vertices of sliver triangles would otherwise carry
 * almost no mass and alone set the stable step ({@link #addedMassKg()} says how much
 * this adds).
 *
 * <p><b>Springs</b> ({@link ShellNetwork}, by the {@link TissueModel}). Material model (default):
 * identified from E, nu and t element by element ({@link org.tensim.scene.shell.SandwichShell}): the
 * faces' edge springs carry the share of Van Gelder's membrane ({@code E t sum(A_T) / |e|^2}) that gives
 * Kirchhoff's bending rigidity, the prisms' diagonals the rest, and every column across the thickness is
 * a rigid link. Paper model: each face {@code E (t/2) sum(A_T) / |e|^2}, folding springs, and columns
 * plus diagonals sharing {@code E_muscle A_u / L}. E is the muscle's or, when both ends are tendon, the
 * tendon's.
 *
 * <p><b>Tendon and rigid links.</b> Nodes on the side of the plane that its normal
 * points to are tendon. Heuristic for the rigid links: candidate pairs are each
 * tendon node (each node, in the material model) with its nearest node on the other surface; they are
 * taken shortest first, each node at most once, and only when their length is
 * 0.3 to 2.5 times the thickness. Each node therefore carries at most one rigid
 * link: the struts are disjoint, which is the tensegrity principle ("compression
 * discontinuous", paper section 2.1), and it makes the projection exact in a single
 * Gauss-Seidel sweep. A spring along a rigid link is left out.
 *
 * <p><b>Damping.</b> Axial damping {@code c = beta k} on every spring, with
 * {@code beta = 2 zeta_high / w_max}, gives the highest mode the damping ratio
 * zeta_high (RK2 needs damping, docs/physics.md); global viscous damping
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
    private final ModalBounds modes;
    private final double timeStep;
    private final Map<String, double[]> boxes;
    private final DiaphragmSpec spec;
    private final Bones bones;
    private final DiaphragmParts parts;
    private final org.tensim.io.mesh.VertexLabel[] vertexLabels;
    /** Terms of bodies built into this scene's topology after it (the organs' couplings). */
    private final List<org.tensim.solver.ForceTerm> terms = new java.util.ArrayList<>();
    private RunRecorder recorder;

    private DiaphragmScene(DiaphragmParts b, Map<String, double[]> boxes, DiaphragmSpec spec, Bones bones,
            org.tensim.io.mesh.VertexLabel[] vertexLabels) {
        this.vertexLabels = vertexLabels;
        this.parts = b;
        this.spec = spec;
        this.bones = bones;
        this.boxes = boxes;
        this.topology = b.topology();
        this.surfaces = b.surfaces();
        this.labels = b.labels();
        this.modes = b.modes();
        this.timeStep = TimeStepPolicy.recommend(Integrators.DEFAULT, ButcherTableau.MIDPOINT, true, modes).seconds();
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
        return build(surfaces, boxes, p, cycle, controls, lines, BoundaryConditions.defaults());
    }

    /**
     * As {@link #build(TwoSurfaces, Map, DiaphragmParameters, BreathingCycle, DiaphragmControls, List)}
     * with the attachment and muscle-load models ({@link BoundaryConditions#paper()} for the paper's).
     */
    public static DiaphragmScene build(TwoSurfaces surfaces, Map<String, double[]> boxes, DiaphragmParameters p,
            BreathingCycle cycle, DiaphragmControls controls, List<ActionLines.Line> lines, BoundaryConditions bc) {
        // The fibres' tension has no action lines: lines given with it are not used (the scene's own default
        // lines still mark the domes for viewers).
        DiaphragmSpec spec = DiaphragmSpec.defaults().withTissue(p).withBoundary(bc)
                .withActionLines(bc.muscleLoad() == BoundaryConditions.MuscleLoad.FIBRES ? null : lines)
                .withBreathing(new DiaphragmSpec.Breathing(cycle.periodS(), cycle.expirationRatio(),
                        controls.ribAmplitude(), controls.muscleAmplitudePa(), 0, cycle.pauseShare()));
        return build(surfaces, spec, boxes, null, null, cycle, controls);
    }

    /**
     * Builds the scene a spec defines on its surfaces (read by {@link DiaphragmSetup#build}), with the live
     * controls given (a GUI's, kept across rebuilds).
     *
     * @param boxes the cage's rib and sternum boxes, metres (the parametric cage's or a file's)
     * @param bones the thorax's bone surfaces, or the boxes' cage swept into surfaces when the spec's cage says
     *              {@code surfaces} ({@link DiaphragmSetup#read} makes them); null for the band on the cage's segments
     * @param vertexLabels per mesh vertex, a label file's labels (tendon, muscle, origins); null for the rules
     */
    public static DiaphragmScene build(TwoSurfaces surfaces, DiaphragmSpec spec, Map<String, double[]> boxes,
            Bones bones, org.tensim.io.mesh.VertexLabel[] vertexLabels, DiaphragmControls controls) {
        return build(surfaces, spec, boxes, bones, vertexLabels, spec.breathing().cycle(), controls);
    }

    private static DiaphragmScene build(TwoSurfaces surfaces, DiaphragmSpec spec, Map<String, double[]> boxes,
            Bones bones, org.tensim.io.mesh.VertexLabel[] vertexLabels, BreathingCycle cycle,
            DiaphragmControls controls) {
        List<ActionLines.Line> lines = spec.actionLines();
        return new DiaphragmScene(DiaphragmSceneBuilder.build(surfaces, boxes, bones, vertexLabels, spec, cycle,
                controls, lines == null ? defaultActionLines(surfaces) : lines), boxes, spec, bones, vertexLabels);
    }

    /**
     * The tops of the two domes at rest, {x, y} in m, right (x below the mesh's centre) then left; null for
     * a half without one ({@link DomeTops}: the highest point of each half's upper surface, on the surface).
     */
    public double[][] domeTops() {
        double[] b = surfaces.mesh().bounds();
        return DomeTops.tops(surfaces, 0.5 * (b[0] + b[3]));
    }

    /** The definition this scene was built from. */
    public DiaphragmSpec spec() {
        return spec;
    }

    /**
     * Per origin bone (by name), the diaphragm area attached to it, m^2 (each face's nodes carry half their
     * area), and the number of attached nodes; empty for a cage made from boxes.
     */
    public Map<String, double[]> attachedPerBone() {
        return parts.attachedPerBone();
    }

    /**
     * The lower-face area that the abdominal pressure on the zone of apposition presses on the chest wall, m^2
     * ({@link DiaphragmSpec.Cage#appositionPressurePa}); 0 without bone surfaces, contact or that pressure.
     */
    public double appositionAreaM2() {
        return parts.appositionAreaM2();
    }

    /** Per bone (by name), the number of node-bone contact pairs; empty without contact. */
    public Map<String, Integer> contactPairsPerBone() {
        return parts.contactPairsPerBone();
    }

    /** The diaphragm area attached at the origins, m^2: the sum of {@link #attachedPerBone()} (0 for a cage made from boxes). */
    public double attachedAreaM2() {
        double sum = 0;
        for (double[] e : parts.attachedPerBone().values()) {
            sum += e[0];
        }
        return sum;
    }

    /**
     * Per diaphragm node, its lumped share of the diaphragm's area, m^2: half of its third of its triangles' areas
     * (each face carries half the sheet, as the contact and attachment stiffnesses count it).
     */
    public double[] nodeAreasM2() {
        double[] a = SurfaceGeometry.vertexAreas(surfaces.mesh());
        for (int v = 0; v < a.length; v++) {
            a[v] /= 2;
        }
        return a;
    }

    /**
     * The labels of the mesh's vertices as this scene has them, for a label file ({@link SceneVertexLabels#of}).
     */
    public org.tensim.io.mesh.VertexLabel[] currentVertexLabels() {
        return SceneVertexLabels.of(this);
    }

    /** The labels of the label file this scene was built from, or null. */
    org.tensim.io.mesh.VertexLabel[] fileLabels() {
        return vertexLabels;
    }

    /**
     * Whether contact body {@code body} ({@link Topology#contactBodies()}) is a bone, which the diaphragm must not
     * enter, rather than the liver's compliant support, which it presses in by design.
     */
    public boolean isBoneContact(int body) {
        if (bones == null) {
            return true;
        }
        String name = parts.topology().contactBodies().get(body).name();
        for (Bones.Bone b : bones.all()) {
            if (b.name().equals(name)) {
                return b.kind() != Bones.Kind.LIVER;
            }
        }
        return true;
    }

    /** The thorax's bones or the cage's swept surfaces ({@code --cage surfaces}); null for the band on segments. */
    public Bones bones() {
        return bones;
    }

    /**
     * The same scene built again, by the same rules as {@link #build}, with other parameters: same
     * surfaces, cage, action lines, breathing cycle and (live) controls. Parameters that set only
     * constants (moduli, damping) give the same topology, node for node and spring for spring, so a
     * running simulation can take the new scene's constants ({@link #copyConstantsTo}).
     */
    public DiaphragmScene rebuiltWith(DiaphragmParameters p) {
        return build(surfaces, spec.withTissue(p), boxes, bones, vertexLabels, parts.cycle(), parts.controls());
    }

    /** The parameters this scene was built with. */
    public DiaphragmParameters parameters() {
        return parts.parameters();
    }

    /** The default action lines of a mesh ({@link DefaultActionLines#of}). */
    public static List<ActionLines.Line> defaultActionLines(TwoSurfaces s) {
        return DefaultActionLines.of(s);
    }

    /**
     * The farthest any node of the scene may move from its rest position before a run is stopped as
     * diverged ({@link Simulation#setDisplacementLimit}): 0.15 m. Deep breathing moves the dome 7.0 +/-
     * 1.1 cm (men, M-mode ultrasound; Boussuges et al., Chest 135:391, 2009), and the model's largest
     * controls move it a few centimetres; a node 15 cm from its rest position is a run gone astray, however
     * slowly it got there.
     */
    public static final double MAX_DISPLACEMENT_M = 0.15;

    /**
     * A new simulation of this scene with the paper's RK2 integrator, at rest at t = 0, stopped as diverged
     * if a node moves farther than {@link #MAX_DISPLACEMENT_M} from its rest position.
     */
    public Simulation newSimulation() {
        Simulation sim = Simulation.of(topology);
        for (org.tensim.solver.ForceTerm term : terms) {
            sim.forces().addTerm(term);
        }
        sim.setDisplacementLimit(MAX_DISPLACEMENT_M);
        // Disjoint links: one sweep is exact; a tolerance still guards the general case.
        sim.apply(sim.settings().withProjection(1e-9, 50));
        return sim;
    }

    /**
     * Adds a force term on this scene's state (a coupling of bodies built into {@link #topology()} after the
     * scene's own nodes, the organs): every {@link #newSimulation()} from now on has it. A term is stateful (its
     * pairing), so one scene runs one simulation at a time with it.
     */
    public void addTerm(org.tensim.solver.ForceTerm term) {
        terms.add(term);
    }

    /** What records the bodies added to this scene during a run (their own outputs), or null. */
    public RunRecorder recorder() {
        return recorder;
    }

    /** Sets what records the added bodies during a run (null: nothing). */
    public void setRecorder(RunRecorder r) {
        recorder = r;
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
     * Nodes {@code 0 .. simulatedNodes()-1} are the diaphragm and the cage; the anchors of the
     * attachment band (fixed, or driven with a rib) and of the abdominal support (fixed) follow
     * (they are not free and are left out of outputs).
     */
    public int simulatedNodes() {
        return parts.firstAnchor();
    }

    /** Anchor nodes of the attachment band and the abdominal support. */
    public int anchorNodes() {
        return topology.nodeCount() - parts.firstAnchor();
    }

    /**
     * Label per node, for nodes {@code 0 .. simulatedNodes()-1}: {@link #MUSCLE}, {@link #TENDON},
     * {@link #RIB} (ribs and spine), {@link #STERNUM_CARTILAGE}.
     */
    public int[] labels() {
        return labels.clone();
    }

    public boolean isTendon(int node) {
        return labels[node] == TENDON;
    }

    public RibCage cage() {
        return parts.cage();
    }

    /** The dome apex probe: the highest upper-surface node at rest that is not attached (driven, fixed, in the band). */
    public int apexNode() {
        return parts.apex();
    }

    public DiaphragmControls controls() {
        return parts.controls();
    }

    public BreathingCycle cycle() {
        return parts.cycle();
    }

    public ActionLines actionLines() {
        return parts.actionLines();
    }

    /** Diaphragm nodes attached to ribs (driven rigidly with their rib, or tied to it by the band). */
    public int attachedToRibs() {
        return parts.attachedToRibs();
    }

    /** Diaphragm nodes tied by springs to cartilage or sternum. */
    public int attachedToCartilage() {
        return parts.attachedToCartilage();
    }

    /** Diaphragm nodes fixed or tied to the spine (crura). */
    public int attachedToSpine() {
        return parts.attachedToSpine();
    }

    /** Whether diaphragm node v is attached to ribs, cartilage, sternum or spine (its origins). */
    public boolean isAttached(int v) {
        return v < parts.attached().length && parts.attached()[v];
    }

    public int attachedNodes() {
        return attachedToRibs() + attachedToCartilage() + attachedToSpine();
    }

    /** Share of the upper surface's area that is tendon. */
    public double tendonAreaFraction() {
        return parts.tendonAreaFraction();
    }

    /** Mass added by the mass floor, kg. */
    public double addedMassKg() {
        return parts.addedMassKg();
    }

    /** Gershgorin bound on the highest angular frequency of the network, rad/s. */
    public double omegaMaxBound() {
        return modes.omegaMax();
    }

    /** The recommended time step of the paper's RK2 on this scene, s ({@link TimeStepPolicy}). */
    public double recommendedTimeStep() {
        return timeStep;
    }

    /**
     * The step to run {@code integrator} with: {@code requestedS} when > 0 (given with
     * {@code --dt}), else the recommendation of {@link TimeStepPolicy} for it on this
     * scene; says which.
     */
    public TimeStep timeStep(Integrator integrator, double requestedS) {
        return TimeStepPolicy.choose(requestedS, "--dt", integrator.name(), integrator.stability(),
                integrator.explicit(), modes);
    }
}

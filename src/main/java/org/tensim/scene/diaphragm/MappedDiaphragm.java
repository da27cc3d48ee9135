package org.tensim.scene.diaphragm;

import org.tensim.model.ContactPair;
import org.tensim.model.LinearMapping;
import org.tensim.model.Topology;
import org.tensim.solver.ForceModel;
import org.tensim.solver.Integrator;
import org.tensim.solver.MappedContact;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;

/**
 * Mechanics at one resolution, the body at another: a coarse diaphragm scene runs the mechanics while the fine
 * scene's nodes (the paper's 43-ring mesh, say) are carried by it, as SOFA's {@code BarycentricMapping} carries a
 * visual model. The fine diaphragm's vertices are carried by the coarse shell's wedges ({@link ShellMapping}: exact
 * for affine motions); the cage's nodes (ribs, sternum, cartilage), the same in both scenes, are carried one to one.
 * What is drawn, probed, measured and exported is the fine scene's nodes; its springs are never stepped.
 *
 * <p>The carried nodes live in a simulation of their own ({@link #newCarried}): every node fixed (never integrated),
 * no springs, at the mapped rest positions, so that the fine scene's measuring (dome tops, extents, VTK frames) reads
 * it as it reads a full run. The mapped rest differs from the fine mesh only where the mapping leaves an offset out
 * ({@link ShellMapping#residualM}: {@link #maxResidualM}); displacements are then exactly the mapped displacements.
 *
 * <p><b>Contact on the fine surface.</b> When the fine scene touches bones (a thorax), its contact pairs are the
 * fine surface's: the coarse scene's own pairs are removed, and the fine pairs act on the coarse nodes through the
 * mapping's transpose ({@link MappedContact}, added to the mechanics by {@link #newMechanics}). The carried nodes'
 * simulation has the fine pairs too (never stepped: its nodes are fixed), so that what a run measures of contact
 * (penetration, contact area) is measured on the fine surface.
 */
public final class MappedDiaphragm {
    /** The cage's nodes must agree between the two scenes to this, m: they are the same generated cage. */
    private static final double SAME_CAGE_M = 1e-9;

    private final DiaphragmScene coarse;
    private final DiaphragmScene fine;
    private final ShellMapping shell;
    private final LinearMapping mapping;
    private final MappedContact contact;

    private MappedDiaphragm(DiaphragmScene coarse, DiaphragmScene fine, ShellMapping shell, LinearMapping mapping,
            MappedContact contact) {
        this.coarse = coarse;
        this.fine = fine;
        this.shell = shell;
        this.mapping = mapping;
        this.contact = contact;
    }

    /**
     * The fine scene carried by the coarse one.
     *
     * @throws IllegalArgumentException when the two scenes' cages differ (other boxes, a thorax in one only): a
     *                                  cage node cannot be carried by another cage
     */
    public static MappedDiaphragm of(DiaphragmScene coarse, DiaphragmScene fine) {
        ShellMapping shell = ShellMapping.of(coarse.surfaces(), fine.surfaces());
        int cd = coarse.diaphragmNodes();
        int fd = fine.diaphragmNodes();
        int cageC = coarse.simulatedNodes() - cd;
        int cageF = fine.simulatedNodes() - fd;
        if (cageC != cageF) {
            throw new IllegalArgumentException("the coarse scene's cage has " + cageC + " nodes and the fine one's "
                    + cageF + ": a mapped diaphragm needs the same cage in both");
        }
        double[] cx = positions(coarse.topology(), coarse.simulatedNodes());
        double[] fx = positions(fine.topology(), fine.simulatedNodes());
        LinearMapping d = shell.mapping();
        LinearMapping.Builder b = new LinearMapping.Builder(coarse.simulatedNodes());
        for (int i = 0; i < fd; i++) {
            int n = d.entries(i);
            int[] ids = new int[n];
            double[] w = new double[n];
            for (int k = 0; k < n; k++) {
                ids[k] = d.node(i, k);
                w[k] = d.weight(i, k);
            }
            b.add(ids, w);
        }
        for (int k = 0; k < cageC; k++) {
            for (int a = 0; a < 3; a++) {
                double e = Math.abs(cx[3 * (cd + k) + a] - fx[3 * (fd + k) + a]);
                if (!(e <= SAME_CAGE_M)) {
                    throw new IllegalArgumentException("cage node " + k + " is " + e + " m apart in the coarse and"
                            + " fine scenes: a mapped diaphragm needs the same cage in both");
                }
            }
            b.add(new int[] {cd + k}, new double[] {1});
        }
        LinearMapping all = b.build();
        MappedContact contact = null;
        if (!fine.topology().contacts().isEmpty()) {
            // the fine surface touches: the coarse scene's own pairs would touch twice
            coarse.topology().clearContacts();
            contact = new MappedContact(all, fine.topology().contactBodies(), fine.topology().contacts());
        }
        return new MappedDiaphragm(coarse, fine, shell, all, contact);
    }

    /**
     * The fine scene carried by a coarse model of the same mesh: the fine scene's surfaces decimated by quadric-error
     * edge collapse to about the given edge length ({@link Decimation#QUADRIC}), built with the fine scene's spec,
     * live controls, cage and bones (read once: {@code in}).
     *
     * @param in    what the fine scene was built from ({@link DiaphragmSetup#read})
     * @param edgeM the coarse model's target edge length, m (&gt; 0)
     * @throws IllegalArgumentException when the fine scene has a label file (labels name the fine mesh's vertices)
     */
    public static MappedDiaphragm decimated(DiaphragmSetup.Inputs in, DiaphragmScene fine, double edgeM) {
        if (in.labels() != null) {
            throw new IllegalArgumentException("a label file names the vertices of " + fine.spec().mesh().describe()
                    + ": a coarse model of it cannot take them; run it unmapped");
        }
        org.tensim.scene.shell.TwoSurfaces c = Decimation.QUADRIC.coarsen(in.surfaces().surfaces(), edgeM);
        DiaphragmSetup.Inputs coarseIn = new DiaphragmSetup.Inputs(new DiaphragmSetup.Surfaces(c,
                DiaphragmSetup.SurfaceMode.SHELL), null, in.boxes(), in.bones(), null, String.format(
                java.util.Locale.ROOT, "%s decimated to %.1f mm edges", in.source(), 1e3 * edgeM));
        DiaphragmScene cs = DiaphragmSetup.build(coarseIn, fine.spec(), fine.controls()).scene();
        return of(cs, fine);
    }

    /**
     * A simulation of the coarse scene that runs the mechanics, with the fine surface's contact when there is one
     * ({@link #contact}). Its integrator is the scene's default: set the one to run.
     */
    public Simulation newMechanics() {
        Simulation s = coarse.newSimulation();
        if (contact != null) {
            s.forces().addTerm(contact);
        }
        return s;
    }

    /** The fine surface's contact on the coarse nodes, or null when the fine scene touches nothing. */
    public MappedContact contact() {
        return contact;
    }

    private static double[] positions(Topology t, int n) {
        double[] x = new double[3 * n];
        for (int i = 0; i < n; i++) {
            x[3 * i] = t.node(i).position().x();
            x[3 * i + 1] = t.node(i).position().y();
            x[3 * i + 2] = t.node(i).position().z();
        }
        return x;
    }

    /** The scene whose nodes run the mechanics. */
    public DiaphragmScene coarse() {
        return coarse;
    }

    /** The scene whose nodes are drawn and measured (its first {@link DiaphragmScene#simulatedNodes} nodes). */
    public DiaphragmScene fine() {
        return fine;
    }

    /** The shell mapping of the diaphragm's nodes (its residuals and depths). */
    public ShellMapping shell() {
        return shell;
    }

    /**
     * Fine node i (diaphragm, then cage; {@code fine().simulatedNodes()} in all) from the coarse scene's simulated
     * nodes: apply it to the coarse state's {@code x} (m) or {@code v} (m/s), whole arrays.
     */
    public LinearMapping mapping() {
        return mapping;
    }

    /** Nodes drawn and measured: the fine scene's diaphragm nodes. */
    public int drawnNodes() {
        return fine.diaphragmNodes();
    }

    /** Nodes that run the mechanics: the coarse scene's diaphragm nodes. */
    public int mechanicalNodes() {
        return coarse.diaphragmNodes();
    }

    /** The largest distance between a fine node at rest and where the coarse shell carries it, m. */
    public double maxResidualM() {
        double m = 0;
        for (int i = 0; i < shell.pointCount(); i++) {
            m = Math.max(m, shell.residualM(i));
        }
        return m;
    }

    /**
     * A simulation of the carried nodes: the fine scene's simulated nodes, all fixed, at the positions the mapping
     * gives {@code mechanics}' rest positions, without springs. Its positions follow
     * {@code mechanics} when the carrier is set as its integrator ({@link #carrier}) or when {@link #follow} is
     * called after each of the mechanics' steps.
     */
    public Simulation newCarried(Simulation mechanics) {
        double[] rest = new double[3 * mapping.pointCount()];
        mapping.apply(mechanics.state().x0, rest);
        Topology t = new Topology();
        for (int i = 0; i < mapping.pointCount(); i++) {
            t.addNode(rest[3 * i], rest[3 * i + 1], rest[3 * i + 2], 1).fix();
        }
        // the fine pairs on the carried nodes (the fine scene's node ids): measured there, never acting (fixed)
        for (org.tensim.model.ContactBody body : fine.topology().contactBodies()) {
            t.addContactBody(body);
        }
        for (ContactPair p : fine.topology().contacts()) {
            t.addContact(p.node(), p.body(), p.stiffnessNPerM(), p.gapM());
        }
        Simulation s = new Simulation(SystemState.compile(t));
        follow(mechanics, s);
        return s;
    }

    /**
     * Sets the carried nodes' positions from the mechanics' (allocation-free). Their velocities stay 0: the nodes
     * are fixed, their motion is the mechanics' (whose velocities {@link #mapping} carries when asked), and a
     * simulation of fixed nodes with velocities would count a kinetic energy no force balances.
     */
    public void follow(Simulation mechanics, Simulation carried) {
        mapping.apply(mechanics.state().x, carried.state().x);
    }

    /**
     * The integrator of a carried simulation for a headless run: each of its steps is one step of
     * {@code mechanics} (with the mechanics' own integrator, links and contacts), then the mapping. Named as the
     * mechanics' integrator, so that a run's summary says which solver ran.
     */
    public Integrator carrier(Simulation mechanics) {
        return new Integrator() {
            @Override
            public String name() {
                return mechanics.integrator().name();
            }

            @Override
            public int order() {
                return mechanics.integrator().order();
            }

            @Override
            public boolean explicit() {
                return false; // the mechanics check their own step
            }

            @Override
            public void step(ForceModel model, double t, double dt) {
                mechanics.step(dt);
                mapping.apply(mechanics.state().x, model.state().x);
            }
        };
    }
}

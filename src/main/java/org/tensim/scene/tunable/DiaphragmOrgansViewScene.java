package org.tensim.scene.tunable;

import java.util.List;
import org.tensim.model.LinearMapping;
import org.tensim.model.Vec3;
import org.tensim.solver.Simulation;

/**
 * The diaphragm with the lungs and the liver in its state ({@link DiaphragmOrgans}): the diaphragm's scene (its
 * parameters, rebuilds, controls and readouts those of its {@link DiaphragmViewScene}) and a second body, the organs'
 * surfaces, drawn translucent in a layer of their own ({@link #organBodies()}) and set from the state after every
 * step. The organs' lattice nodes are simulated but not drawn: they are nodes of the first body past its visible ones.
 */
public final class DiaphragmOrgansViewScene implements ViewScene {
    private final DiaphragmViewScene diaphragm;
    private final DiaphragmOrgans.Built built;
    private final List<Body> bodies;

    DiaphragmOrgansViewScene(DiaphragmViewScene diaphragm, DiaphragmOrgans.Built built) {
        this.diaphragm = diaphragm;
        this.built = built;
        Body d = diaphragm.bodies().get(0);
        Simulation mechanics = d.simulation();
        LinearMapping drawn = built.drawnMapping(mechanics.state().nodeCount);
        Simulation carried = DiaphragmOrgans.newCarried(drawn, mechanics);
        // Stepped after the mechanics (the runner steps the bodies in order): follow them, then the frame is taken.
        carried.addListener(s -> DiaphragmOrgans.follow(drawn, mechanics, carried));
        Body organs = new Body(built.organs().liver() == null ? "lungs" : "lungs and liver", carried,
                built.triangles(), built.colours(), Vec3.ZERO, probeVertex(carried), carried.state().nodeCount,
                new int[0]);
        this.bodies = List.of(d, organs);
    }

    /** The lowest drawn vertex (the base of a lung or the liver's): the organs' probe, which moves most. */
    private static int probeVertex(Simulation carried) {
        double[] x = carried.state().x0;
        int best = 0;
        for (int i = 1; 3 * i < x.length; i++) {
            if (x[3 * i + 2] < x[3 * best + 2]) {
                best = i;
            }
        }
        return best;
    }

    /** The organs as built into the running scene. */
    public org.tensim.scene.lungs.ThoraxOrgans organs() {
        return built.organs();
    }

    /** The diaphragm's scene (its latest rebuild, with the organs built again into it). */
    public DiaphragmViewScene diaphragm() {
        return diaphragm;
    }

    @Override
    public List<Integer> organBodies() {
        return List.of(1);
    }

    @Override
    public int organNodes() {
        return built.nodes();
    }

    @Override
    public String name() {
        return diaphragm.name();
    }

    @Override
    public String title() {
        return diaphragm.title() + "; " + bodies.get(1).name() + " (" + built.nodes() + " nodes, translucent)";
    }

    @Override
    public List<Body> bodies() {
        return bodies;
    }

    @Override
    public List<TunableParameter> parameters() {
        return diaphragm.parameters();
    }

    @Override
    public void apply(String key, double value) {
        diaphragm.apply(key, value);
    }

    @Override
    public Runnable prepare(String key, double value) {
        return diaphragm.prepare(key, value);
    }

    @Override
    public LiveState liveState() {
        return diaphragm.liveState();
    }

    /**
     * RK2, as {@code tensim diaphragm --lungs} runs: the organs' couplings are explicit force terms, not linearised by
     * the implicit integrators, so the large real-time steps of the thorax do not hold with them.
     */
    @Override
    public String defaultIntegrator() {
        return org.tensim.solver.integrators.Integrators.DEFAULT;
    }

    @Override
    public double defaultTimeStep() {
        return diaphragm.defaultTimeStep();
    }

    @Override
    public Resolution resolution() {
        return diaphragm.resolution();
    }

    @Override
    public int defaultProbeAxis() {
        return diaphragm.defaultProbeAxis();
    }

    @Override
    public double displacementScale() {
        return diaphragm.displacementScale();
    }

    /** As the diaphragm's: the organs' surfaces do not make the springs and nodes hidden or shown at first. */
    @Override
    public boolean wireframeAtStart() {
        return diaphragm.wireframeAtStart();
    }

    @Override
    public Vec3 up() {
        return diaphragm.up();
    }

    @Override
    public Vec3 viewFrom() {
        return diaphragm.viewFrom();
    }
}

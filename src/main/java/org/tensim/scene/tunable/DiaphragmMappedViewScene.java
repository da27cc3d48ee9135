package org.tensim.scene.tunable;

import java.util.List;
import java.util.Locale;
import org.tensim.model.Vec3;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.MappedDiaphragm;
import org.tensim.solver.Simulation;

/**
 * The diaphragm with its mechanics at one resolution and its body at another ({@link MappedDiaphragm}): the coarse
 * scene runs (its parameters, rebuilds and controls those of a {@link DiaphragmViewScene} of it), and the fine mesh
 * it carries is what is drawn, probed and measured. Two bodies: first the mechanics (stepped, not drawn: no surface,
 * one node shown), then the carried nodes, all fixed, set through the mapping after every step, with the fine
 * scene's surface, colours, cage lines and readouts ({@link DiaphragmLiveState} on them).
 */
public final class DiaphragmMappedViewScene implements ViewScene {
    private final DiaphragmViewScene mechanics;
    private final MappedDiaphragm mapped;
    private final DiaphragmViewFactory.Mechanics pick;
    private final Simulation carried;
    private final List<Body> bodies;

    DiaphragmMappedViewScene(DiaphragmViewScene mechanics, MappedDiaphragm mapped,
            DiaphragmViewFactory.Mechanics pick) {
        this.mechanics = mechanics;
        this.mapped = mapped;
        this.pick = pick;
        Body m = mechanics.bodies().get(0);
        Simulation coarse = m.simulation();
        this.carried = mapped.newCarried(coarse);
        // stepped after the mechanics (the runner steps the bodies in order): follow them, then the frame is taken
        carried.addListener(s -> mapped.follow(coarse, carried));
        DiaphragmScene fine = mapped.fine();
        Body mech = new Body("mechanics (" + pick.rings() + " rings)", coarse, new int[0], null, Vec3.ZERO,
                m.probeNode(), 1, new int[0]);
        Body drawn = new Body("diaphragm apex", carried, fine.allTriangles(),
                DiaphragmViewScene.colours(fine, carried.state().nodeCount), Vec3.ZERO, fine.apexNode(),
                fine.simulatedNodes(), DiaphragmViewScene.structure(fine));
        this.bodies = List.of(mech, drawn);
    }

    /** The mapping between the two scenes. */
    public MappedDiaphragm mapped() {
        return mapped;
    }

    /** The scene of the mechanics (its latest rebuild). */
    public DiaphragmScene mechanicsScene() {
        return mechanics.scene();
    }

    @Override
    public String name() {
        return mechanics.name();
    }

    @Override
    public String title() {
        return mechanics.title().replaceFirst("^Diaphragm: \\d+ nodes", "Diaphragm: " + mapped.drawnNodes()
                + " nodes drawn, carried by " + mapped.mechanicalNodes() + " (" + pick.rings() + " rings)");
    }

    @Override
    public List<Body> bodies() {
        return bodies;
    }

    @Override
    public List<TunableParameter> parameters() {
        return mechanics.parameters();
    }

    @Override
    public void apply(String key, double value) {
        mechanics.apply(key, value);
    }

    @Override
    public Runnable prepare(String key, double value) {
        return mechanics.prepare(key, value);
    }

    @Override
    public LiveState liveState() {
        return new DiaphragmLiveState(mapped.fine(), carried.state().x0, 1);
    }

    @Override
    public double defaultTimeStep() {
        return mechanics.defaultTimeStep();
    }

    @Override
    public Resolution resolution() {
        return new Resolution(mapped.drawnNodes(), mapped.mechanicalNodes(), pick.error(), String.format(Locale.ROOT,
                "mechanics at %d rings (%,d nodes), drawn at %,d: %.1f %% from %d rings (%s)", pick.rings(),
                mapped.mechanicalNodes(), mapped.drawnNodes(), 100 * pick.error(),
                mapped.fine().spec().mesh().rings(), pick.source()));
    }

    @Override
    public int defaultProbeAxis() {
        return mechanics.defaultProbeAxis();
    }

    @Override
    public double displacementScale() {
        return mechanics.displacementScale();
    }

    @Override
    public Vec3 up() {
        return mechanics.up();
    }

    @Override
    public Vec3 viewFrom() {
        return mechanics.viewFrom();
    }
}

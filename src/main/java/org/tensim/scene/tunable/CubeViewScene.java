package org.tensim.scene.tunable;

import java.util.List;
import org.tensim.model.Vec3;
import org.tensim.scene.CubeParameters;
import org.tensim.scene.CubeScene;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;

/**
 * The paper's cube comparison (Fig. 3) for the GUI: the mass-spring cube (left)
 * and the tensegrity cube (right, drawn {@value #GAP_M} m further along +x) built
 * by {@link CubeScene} with {@link CubeParameters#paper()}, stepped together under
 * the same sinusoidal force on their two upper element nodes. Every parameter
 * acts on both cubes, so they stay identical but for the rigid links.
 *
 * <p>The force laws compiled from the topology are replaced by
 * {@link TunableSinusoid}s of the same shape (amplitude, frequency, direction,
 * zero phase), so that amplitude and frequency can be tuned while running.
 */
public final class CubeViewScene implements ViewScene {
    /** Distance between the two cubes' origins along x, m. */
    public static final double GAP_M = 16;

    public static final String FORCE_AMPLITUDE = "forceAmplitudeN";
    public static final String FORCE_FREQUENCY = "forceFrequencyHz";
    public static final String STIFFNESS = "stiffnessNPerM";
    public static final String DAMPING = "dampingNsPerM";
    public static final String VISCOUS_DAMPING = "viscousDampingNsPerM";

    private static final CubeParameters P = CubeParameters.paper();

    /** The tunable parameters (the sweep and calibration read their names and ranges here). */
    public static final List<TunableParameter> PARAMETERS = List.of(
            TunableParameter.linear(FORCE_AMPLITUDE, "Force amplitude", "N", 0, 2000, P.forceAmplitudeN(),
                    "Peak of the sinusoidal force on each of the two loaded upper nodes of both cubes."),
            TunableParameter.log(FORCE_FREQUENCY, "Force frequency", "Hz", 0.02, 5, P.forceFrequencyHz(),
                    "Frequency of the sinusoidal force; the phase stays continuous when it changes."),
            TunableParameter.log(STIFFNESS, "Spring stiffness", "N/m", 10, 10000, P.stiffnessNPerM(),
                    "Stiffness k of every spring (edges, cables, ties) of both cubes."),
            TunableParameter.linear(DAMPING, "Spring damping", "N s/m", 0, 50, P.dampingNsPerM(),
                    "Axial damping c of every spring: resists the rate of stretch."),
            TunableParameter.linear(VISCOUS_DAMPING, "Viscous damping", "N s/m", 0, 20, 0,
                    "Global drag -c v on every free node (air-like damping)."));

    private final List<Body> bodies;
    private final TunableSinusoid[] forces;

    private CubeViewScene() {
        CubeScene mss = CubeScene.massSpring(P);
        CubeScene ts = CubeScene.tensegrity(P);
        Simulation a = new Simulation(SystemState.compile(mss.topology));
        Simulation b = new Simulation(SystemState.compile(ts.topology));
        forces = new TunableSinusoid[] {tunableForce(a), tunableForce(b)};
        bodies = List.of(
                new Body("MSS (mass-spring)", a, new int[0], null, Vec3.ZERO, mss.probe.id()),
                new Body("TS (tensegrity)", b, new int[0], null, new Vec3(GAP_M, 0, 0), ts.probe.id()));
    }

    /** A new pair of cubes at rest, parameters at their defaults. */
    public static CubeViewScene create() {
        return new CubeViewScene();
    }

    /** The factory used by the GUI: the cube has no tendon choice (both models are shown). */
    public static SceneFactory factory() {
        return new SceneFactory() {
            @Override
            public String name() {
                return "cube";
            }

            @Override
            public boolean hasTendonChoice() {
                return false;
            }

            @Override
            public ViewScene create(boolean tensegrityTendon, java.util.Map<String, Double> values) {
                return CubeViewScene.create();
            }
        };
    }

    private static TunableSinusoid tunableForce(Simulation s) {
        TunableSinusoid law = new TunableSinusoid(P.forceAmplitudeN(), P.forceFrequencyHz(), P.forceDirection());
        for (int i = 0; i < s.state().forceLaw.length; i++) {
            s.state().forceLaw[i] = law;
        }
        return law;
    }

    @Override
    public String name() {
        return "cube";
    }

    @Override
    public String title() {
        return "Cube (paper Fig. 3): mass-spring (left) and tensegrity (right), 10 x 10 x 10 m";
    }

    @Override
    public List<Body> bodies() {
        return bodies;
    }

    @Override
    public List<TunableParameter> parameters() {
        return PARAMETERS;
    }

    @Override
    public double defaultTimeStep() {
        return P.dtS();
    }

    @Override
    public void apply(String key, double value) {
        for (int b = 0; b < bodies.size(); b++) {
            Simulation sim = bodies.get(b).simulation();
            SystemState s = sim.state();
            switch (key) {
                case FORCE_AMPLITUDE -> forces[b].setAmplitude(value);
                case FORCE_FREQUENCY -> forces[b].setFrequency(value, sim.time());
                case STIFFNESS -> {
                    for (int i = 0; i < s.springCount(); i++) {
                        s.setSpringStiffness(i, value);
                    }
                }
                case DAMPING -> {
                    for (int i = 0; i < s.springCount(); i++) {
                        s.setSpringDamping(i, value);
                    }
                }
                case VISCOUS_DAMPING -> s.setViscousDamping(value);
                default -> throw new IllegalArgumentException("cube scene has no parameter '" + key + "'; known: "
                        + PARAMETERS.stream().map(TunableParameter::key).toList());
            }
        }
    }
}

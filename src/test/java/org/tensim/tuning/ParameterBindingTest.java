package org.tensim.tuning;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.tensim.scene.tunable.Body;
import org.tensim.scene.tunable.CubeViewScene;
import org.tensim.scene.tunable.SceneFactory;
import org.tensim.scene.tunable.TunableParameter;
import org.tensim.scene.tunable.ViewScene;
import org.tensim.solver.integrators.IntegratorChoice;
import org.tensim.solver.integrators.Integrators;

/**
 * Each control reaches the simulation: a value set through {@link Tuning} changes
 * what the scene's simulations compute, for every parameter of every scene; a
 * refused value changes nothing.
 */
public class ParameterBindingTest {
    /** Applies changes at once to one scene, as the runner does between steps. */
    static final class DirectTarget implements Tuning.Target {
        final ViewScene scene;
        double dt;

        DirectTarget(ViewScene scene) {
            this.scene = scene;
            this.dt = scene.defaultTimeStep();
        }

        @Override
        public void applyParameter(String key, double value) {
            if (key.equals(Tuning.TIME_STEP)) {
                dt = value;
            } else {
                scene.apply(key, value);
            }
        }

        @Override
        public void applyIntegrator(IntegratorChoice c) {
            for (Body b : scene.bodies()) {
                b.simulation().setIntegrator(c.create());
            }
        }

        @Override
        public void applyTendonModel(boolean tensegrity) {
            throw new UnsupportedOperationException("not needed here");
        }

        @Override
        public void applyMuscleLoad(org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad muscleLoad) {
            throw new UnsupportedOperationException("not needed here");
        }
    }

    static Stream<Arguments> sceneParameters() {
        return factories().stream().flatMap(f -> f.create(true).parameters().stream()
                .map(p -> Arguments.of(f.name(), p.key())));
    }

    static List<SceneFactory> factories() {
        return List.of(CubeViewScene.factory(), MembraneTestScene.factory(), coarseDiaphragm());
    }

    /** The diaphragm at a coarse resolution (6 rings per face), quick to build and step. */
    public static SceneFactory coarseDiaphragm() {
        return TunableScenes.factory("diaphragm", DiaphragmOptions.parse(java.util.List.of("--rings", "6")));
    }

    static SceneFactory factory(String name) {
        return factories().stream().filter(f -> f.name().equals(name)).findFirst().orElseThrow();
    }

    static Tuning tuning(ViewScene s, SceneFactory f) {
        return new Tuning(s.name(), s.parameters(), s.defaultTimeStep(), f.hasTendonChoice(),
                Integrators.choices());
    }

    /** Steps the scene and returns every body's positions, concatenated. */
    public static double[] run(ViewScene s, double dt, int steps) {
        for (int i = 0; i < steps; i++) {
            for (Body b : s.bodies()) {
                b.simulation().step(dt);
            }
        }
        return s.bodies().stream().flatMapToDouble(b -> java.util.Arrays.stream(b.simulation().state().x)).toArray();
    }

    /** A value well away from the current one, inside the range. */
    static double other(TunableParameter p, double current) {
        double f = p.toFraction(current);
        return p.fromFraction(f < 0.5 ? f + 0.4 : f - 0.4);
    }

    @ParameterizedTest(name = "{0}: {1}")
    @MethodSource("sceneParameters")
    void everyParameterChangesTheSimulation(String sceneName, String key) {
        SceneFactory f = factory(sceneName);
        if (f.create(true).parameters().stream().anyMatch(q -> q.key().equals(key) && q.restarts())) {
            restartingParameterReachesTheNewScene(f, key);
            return;
        }
        ViewScene reference = f.create(true);
        ViewScene same = f.create(true);
        ViewScene changed = f.create(true);
        Tuning sameTuning = tuning(same, f);
        sameTuning.bind(new DirectTarget(same));
        Tuning changedTuning = tuning(changed, f);
        changedTuning.bind(new DirectTarget(changed));
        double dt = reference.defaultTimeStep();
        int steps = 300;

        // Warm up so that velocities and forces are non-zero, then change the parameter mid-run.
        run(reference, dt, steps);
        run(same, dt, steps);
        run(changed, dt, steps);
        TunableParameter p = changedTuning.parameter(key);
        sameTuning.set(key, sameTuning.get(key)); // same value through the same path: nothing may change
        changedTuning.set(key, other(p, changedTuning.get(key)));
        assertEquals(other(p, p.defaultValue()), changedTuning.get(key));

        double[] a = run(reference, dt, steps);
        double[] b = run(same, dt, steps);
        double[] c = run(changed, dt, steps);
        assertArrayEquals(a, b, "re-applying the current value of " + key + " must not change the run");
        double diff = 0;
        for (int i = 0; i < a.length; i++) {
            diff = Math.max(diff, Math.abs(a[i] - c[i]));
        }
        assertTrue(diff > 1e-9, key + " changed from " + p.defaultValue() + " to " + changedTuning.get(key)
                + " but the positions moved by at most " + diff + " m");
    }

    /** A parameter that needs a new scene: the factory must build it with the value. */
    static void restartingParameterReachesTheNewScene(SceneFactory f, String key) {
        ViewScene reference = f.create(true);
        TunableParameter p = reference.parameters().stream().filter(q -> q.key().equals(key)).findFirst().orElseThrow();
        ViewScene same = f.create(true, java.util.Map.of(key, p.defaultValue()));
        ViewScene changed = f.create(true, java.util.Map.of(key, other(p, p.defaultValue())));
        double dt = reference.defaultTimeStep();
        double[] a = run(reference, dt, 300);
        assertArrayEquals(a, run(same, dt, 300), "the default value given explicitly must change nothing");
        double[] c = run(changed, dt, 300);
        double diff = 0;
        for (int i = 0; i < a.length; i++) {
            diff = Math.max(diff, Math.abs(a[i] - c[i]));
        }
        assertTrue(diff > 1e-9, key + " given to the factory changed nothing");
    }

    @Test
    void refusedValueChangesNothingAndNamesTheParameter() {
        SceneFactory f = CubeViewScene.factory();
        ViewScene s = f.create(true);
        Tuning t = tuning(s, f);
        DirectTarget target = new DirectTarget(s);
        t.bind(target);
        double before = s.bodies().get(0).simulation().state().springK[0];
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> t.set(CubeViewScene.STIFFNESS, -5));
        assertTrue(e.getMessage().contains(CubeViewScene.STIFFNESS), e.getMessage());
        assertTrue(e.getMessage().contains("-5"), e.getMessage());
        assertTrue(e.getMessage().contains("N/m"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> t.set(CubeViewScene.STIFFNESS, Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> t.set("noSuchThing", 1));
        assertEquals(before, s.bodies().get(0).simulation().state().springK[0]);
        assertEquals(t.parameter(CubeViewScene.STIFFNESS).defaultValue(), t.get(CubeViewScene.STIFFNESS));
    }

    @Test
    void stiffnessReachesEverySpringOfBothCubes() {
        SceneFactory f = CubeViewScene.factory();
        ViewScene s = f.create(true);
        Tuning t = tuning(s, f);
        t.bind(new DirectTarget(s));
        t.set(CubeViewScene.STIFFNESS, 1234);
        t.set(CubeViewScene.DAMPING, 7.5);
        t.set(CubeViewScene.VISCOUS_DAMPING, 3);
        for (Body b : s.bodies()) {
            for (int i = 0; i < b.simulation().state().springCount(); i++) {
                assertEquals(1234, b.simulation().state().springK[i]);
                assertEquals(7.5, b.simulation().state().springC[i]);
            }
            assertEquals(3, b.simulation().state().viscousDamping());
        }
    }

    @Test
    void timeStepAndIntegratorReachTheTarget() {
        SceneFactory f = CubeViewScene.factory();
        ViewScene s = f.create(true);
        Tuning t = tuning(s, f);
        DirectTarget target = new DirectTarget(s);
        t.bind(target);
        t.set(Tuning.TIME_STEP, 2e-4);
        assertEquals(2e-4, target.dt);
        var before = s.bodies().get(0).simulation().integrator();
        t.setIntegrator(Integrators.choices().get(0).name());
        assertNotSame(before, s.bodies().get(0).simulation().integrator(), "a fresh integrator instance per body");
        assertThrows(IllegalArgumentException.class, () -> t.setIntegrator("no-such-integrator"));
    }

    @Test
    void theCubeHasNoTendonChoiceAndBothModels() {
        SceneFactory f = CubeViewScene.factory();
        assertFalse(f.hasTendonChoice());
        ViewScene s = f.create(true);
        assertEquals(2, s.bodies().size());
        assertEquals(0, s.bodies().get(0).simulation().state().linkCount(), "left cube: mass-spring only");
        assertEquals(6, s.bodies().get(1).simulation().state().linkCount(), "right cube: six rigid links");
    }

    @Test
    void diaphragmControlsReachItsSceneAndTissueConstantsFollowTheScenesRules() {
        SceneFactory f = coarseDiaphragm();
        org.tensim.scene.tunable.DiaphragmViewScene s = (org.tensim.scene.tunable.DiaphragmViewScene) f.create(true);
        Tuning t = tuning(s, f);
        t.bind(new DirectTarget(s));
        t.set(org.tensim.scene.tunable.DiaphragmViewScene.RIB_AMPLITUDE, 2.5);
        t.set(org.tensim.scene.tunable.DiaphragmViewScene.MUSCLE_ACTION, 12000);
        assertEquals(2.5, s.scene().controls().ribAmplitude());
        assertEquals(12000, s.scene().controls().muscleAmplitudePa());
        var state = s.bodies().get(0).simulation().state();
        double[] k0 = state.springK.clone();
        double[] mu0 = state.triMu.clone();
        double shear0 = state.shears.count() == 0 ? 0 : state.shears.stiffness(0, 0, 0);
        double e0 = t.get(org.tensim.scene.tunable.DiaphragmViewScene.TISSUE_STIFFNESS);
        t.set(org.tensim.scene.tunable.DiaphragmViewScene.TISSUE_STIFFNESS, 4 * e0);
        int n = s.scene().diaphragmNodes();
        // The scene that tensim diaphragm would build with that modulus, the tendon's in its ratio.
        org.tensim.scene.diaphragm.DiaphragmParameters p4 = org.tensim.scene.diaphragm.DiaphragmParameters.defaults()
                .withTissueYoung(4 * e0);
        org.tensim.scene.diaphragm.DiaphragmScene direct;
        try {
            direct = org.tensim.scene.diaphragm.DiaphragmSetup.generated(6, null, p4,
                    new org.tensim.scene.diaphragm.BreathingCycle(4, 2),
                    new org.tensim.scene.diaphragm.DiaphragmControls(1, 0)).scene();
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
        double beta = 2 * p4.highDampingRatio() / direct.omegaMaxBound();
        int tissue = 0;
        for (int i = 0; i < k0.length; i++) {
            boolean isTissue = state.springA[i] < n && state.springB[i] < n;
            tissue += isTissue ? 1 : 0;
            // E x4: tissue springs x4, the others as built; every spring's damping beta k with the new w_max.
            assertEquals(isTissue ? 4 * k0[i] : k0[i], state.springK[i], 1e-9 * k0[i]);
            assertEquals(direct.topology().springs().get(i).stiffness(), state.springK[i], 0.0, "as built directly");
            assertEquals(beta * state.springK[i], state.springC[i], 1e-9 * state.springC[i]);
        }
        assertEquals(direct.topology().viscousDamping(), state.viscousDamping(), 0.0);
        assertEquals(direct.recommendedTimeStep(), s.defaultTimeStep(), 0.0, "the rebuilt scene's step");
        assertTrue(tissue < k0.length, "springs outside the tissue exist (supports, attachment)");
        // The tissue's membrane triangles and transverse shear elements (the material model has no tissue
        // springs but a few columns) take E x4 too.
        assertTrue(mu0.length > 0 && state.shears.count() > 0, "membrane triangles and shear elements exist");
        for (int i = 0; i < mu0.length; i++) {
            assertEquals(4 * mu0[i], state.triMu[i], 1e-9 * mu0[i], "triangle " + i);
        }
        assertEquals(4 * shear0, state.shears.stiffness(0, 0, 0), 1e-9 * shear0, "shear element 0");
        assertTrue(s.bodies().get(0).simulation().state().linkCount() > 0, "tensegrity tendon");
        assertEquals(0, f.create(false).bodies().get(0).simulation().state().linkCount(), "mass-spring tendon");
    }
}

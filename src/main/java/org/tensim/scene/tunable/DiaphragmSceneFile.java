package org.tensim.scene.tunable;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.DiaphragmParameters;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.scene.file.RunSettings;
import org.tensim.scene.file.Scene;
import org.tensim.scene.file.SceneBody;
import org.tensim.scene.file.SceneProbe;
import org.tensim.scene.file.SceneRebuild;
import org.tensim.scene.file.bodies.DiaphragmBodyType;
import org.tensim.solver.integrators.Integrators;
import org.tensim.solver.prefactored.PrefactoredBdf2;

/**
 * A scene file whose body is a {@code type: diaphragm} ({@code DiaphragmBodyType}) in the GUI: the view scene
 * {@code tensim gui --scene diaphragm} opens ({@link DiaphragmViewScene}), built from the spec the loader made of
 * the body's keys (the {@code --set} options applied, as {@code tensim run} reads them), run with the file's
 * integrator ({@link #integrator}) and step ({@code dt: auto}: the scene's recommended step). Its controls are the diaphragm's own (rib
 * motion, muscle action, tissue constants, breathing period, the tendon's boundary), starting at the spec's values
 * rather than the built-in scene's defaults; the file's {@code parameters:} set values when it is loaded
 * ({@code --set NAME=VALUE}) but are not controls. The file's regions, conditions and probes are applied to every
 * diaphragm the view builds (the first, and each rebuild a restarting control makes), and the chart follows its
 * first probe. The full model runs, as {@code tensim run} runs it: no mapped mechanics.
 */
final class DiaphragmSceneFile {
    private DiaphragmSceneFile() {
    }

    /**
     * The factory of the loaded file's diaphragm ({@code body}, whose scene {@code built} is): every diaphragm it
     * builds takes the file's regions, conditions and probes anew ({@link SceneRebuild}); the first is the loader's
     * own diaphragm when the window asks for the file's values (the diaphragm is not built twice).
     */
    static DiaphragmViewFactory factory(Scene loaded, SceneBody body, DiaphragmSetup.Built built) {
        DiaphragmViewFactory f = DiaphragmViewScene.factory(built.scene().spec(), null);
        SceneRebuild rebuild = SceneRebuild.of(loaded);
        f.openedFrom(loaded.run(), !rebuild.hasExtras() ? null
                : b -> rebuild.apply(DiaphragmBodyType.body(body.name(), body.node(), b)));
        f.firstIs(built, loaded.probes());
        return f;
    }

    /**
     * The bodies with the chart on the file's first probe (its first node: the node a node probe names, the first
     * of a region's), as the chart of any other scene file; unchanged without probes.
     */
    static List<Body> charting(List<Body> bodies, List<SceneProbe> probes) {
        if (probes.isEmpty() || probes.get(0).nodes().length == 0) {
            return bodies;
        }
        Body d = bodies.get(0);
        List<Body> out = new ArrayList<>(bodies);
        out.set(0, new Body(d.name().replace("apex", "probe " + probes.get(0).name()), d.simulation(), d.triangles(),
                d.vertexColours(), d.offset(), probes.get(0).nodes()[0], d.visibleNodes(), d.structureEdges()));
        return List.copyOf(out);
    }

    /**
     * The file's integrator as {@code tensim run} configures it: a plain {@code bdf2} among bone surfaces with
     * contact takes the thorax's converged iterations, which the GUI names {@link Integrators#CONTACT}.
     */
    static String integrator(RunSettings run, DiaphragmSpec spec) {
        boolean contact = spec.cage().boneSurfaces() && spec.cage().contact();
        return contact && run.integrator().equals(PrefactoredBdf2.NAME) ? Integrators.CONTACT : run.integrator();
    }

    /**
     * The controls with their defaults at the scene's values (its breathing, its tissue constants, its tendon's area
     * share), each range widened to hold its value when the spec's lies outside it (a 0.1 s period, say).
     */
    static List<TunableParameter> startingAt(List<TunableParameter> controls, DiaphragmScene scene,
            BoundaryConditions.MuscleLoad load) {
        DiaphragmSpec.Breathing b = scene.spec().breathing();
        DiaphragmParameters p = scene.parameters();
        Map<String, Double> at = Map.of(
                DiaphragmViewScene.RIB_AMPLITUDE, b.ribAmplitude(),
                DiaphragmViewScene.MUSCLE_ACTION, b.musclePa() != null ? b.musclePa()
                        : DiaphragmSetup.defaultMusclePa(load),
                DiaphragmViewScene.TISSUE_STIFFNESS, p.muscleYoungPa(),
                DiaphragmViewScene.TISSUE_DAMPING, p.highDampingRatio(),
                DiaphragmViewScene.SURROUNDING_DAMPING, p.viscousPerS(),
                DiaphragmViewScene.BREATHING_PERIOD, b.periodS(),
                DiaphragmViewScene.TENDON_SHARE, p.tendonAreaFraction());
        List<TunableParameter> out = new ArrayList<>();
        for (TunableParameter c : controls) {
            Double v = at.get(c.key());
            out.add(v == null || (c.logarithmic() && !(v > 0)) ? c : new TunableParameter(c.key(), c.label(),
                    c.unit(), Math.min(c.min(), v), Math.max(c.max(), v), v, c.logarithmic(), c.description(),
                    c.restarts()));
        }
        return List.copyOf(out);
    }
}

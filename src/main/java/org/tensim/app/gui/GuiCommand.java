package org.tensim.app.gui;

import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.SwingUtilities;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.tunable.SceneFactory;
import org.tensim.tuning.LastUsedParameters;
import org.tensim.tuning.SceneFileGui;
import org.tensim.scene.tunable.ViewScene;
import org.tensim.cli.ThreadsOption;
import org.tensim.solver.integrators.Integrators;
import org.tensim.tuning.ConfigDir;
import org.tensim.tuning.DiaphragmOptions;
import org.tensim.tuning.PresetFile;
import org.tensim.tuning.PresetScene;
import org.tensim.tuning.TunableScenes;
import org.tensim.tuning.Tuning;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code tensim gui}: the interactive window. */
@Command(name = "gui", mixinStandardHelpOptions = true,
        description = {"Opens the interactive simulation in a Java3D window.",
            "Tune parameters while it runs, watch a probe node's displacement, save and load presets. Last-used"
                + " parameters are restored from $XDG_CONFIG_HOME/tensim/ (or ~/.config/tensim/). Guide:"
                + " docs/gui.md."})
public final class GuiCommand implements Callable<Integer> {
    private static volatile boolean scripted;

    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @picocli.CommandLine.Mixin
    SceneFileGui sceneFile = new SceneFileGui();

    @Option(names = "--scene", paramLabel = "NAME",
            description = "Scene to show: ${COMPLETION-CANDIDATES} (default: ${DEFAULT-VALUE}).",
            completionCandidates = SceneNames.class)
    String scene = TunableScenes.names().get(0);

    @picocli.CommandLine.Mixin
    DiaphragmOptions options = new DiaphragmOptions();

    @picocli.CommandLine.Mixin
    org.tensim.tuning.PickOption pick = new org.tensim.tuning.PickOption();

    @Option(names = "--lungs", description = "With --thorax: build the thorax's lungs into the diaphragm's state, as"
            + " tensim diaphragm --lungs does (docs/lungs.md), and draw them translucent (View: \"Lungs, liver\""
            + " hides them). The full model runs: no mapped mechanics.")
    boolean lungs;

    @Option(names = "--liver", negatable = true, description = "With --lungs: also the liver as a volume pushed by"
            + " the diaphragm, as tensim diaphragm --lungs builds it: held at its bare area and on the abdomen below,"
            + " the rigid support kept (default: on with --lungs; --no-liver leaves it out; docs/lungs.md).")
    Boolean liver;

    @Option(names = "--preset", paramLabel = "FILE",
            description = "Load this JSON preset at start (after the last-used parameters).")
    Path preset;

    @Option(names = "--fresh", description = "Start from the defaults: do not restore the last-used parameters.")
    boolean fresh;

    @Option(names = "--config-dir", paramLabel = "DIR",
            description = "Folder for last-used parameters (default: $XDG_CONFIG_HOME/tensim or ~/.config/tensim).")
    Path configDir;

    @Option(names = "--paused", description = "Start paused (default: playing).")
    boolean paused;

    @Option(names = "--screenshot", paramLabel = "FILE",
            description = "Save a PNG of the window once --after simulated seconds have run, then exit.")
    Path screenshot;

    @Option(names = "--after", paramLabel = "S",
            description = "Simulated time before --screenshot, s (default: ${DEFAULT-VALUE}).")
    double after = 2;

    @Option(names = "--run-for", paramLabel = "S",
            description = {"Play for S seconds of wall time once the view shows (on until the first step if none was"
                    + " done"
                    + " by then), close the window and print a JSON"
                    + " line last: realtime_factor, fps, steps_per_s, nodes, integrator, dt_s, threads, error_estimate,"
                    + " edt_longest_delay_ms, load averages, window_title... (with --screenshot: the picture is taken"
                    + " at the end)."})
    Double runFor;

    @Option(names = "--unpaced", description = "Start with \"Real time\" unticked: simulate as fast as possible"
            + " instead of at most real time.")
    boolean unpaced;

    @Option(names = "--fps-cap", paramLabel = "N",
            description = "Draw at most N frames per second, 0 for no cap; the View menu changes it (default:"
                    + " ${DEFAULT-VALUE}, which leaves the renderer's spare time to the simulation).")
    int fpsCap = org.tensim.view.SceneView.DEFAULT_FRAME_CAP_FPS;

    @picocli.CommandLine.Mixin
    ThreadsOption threads = new ThreadsOption();

    /** Scene names for picocli's help. */
    static final class SceneNames implements Iterable<String> {
        @Override
        public java.util.Iterator<String> iterator() {
            return TunableScenes.names().iterator();
        }
    }

    /** True when the window is driven by a script (screenshot, tests): no modal dialogs. */
    static boolean scripted() {
        return scripted;
    }

    static void setScripted(boolean s) {
        scripted = s;
    }

    @Override
    public Integer call() throws Exception {
        long started = System.nanoTime();
        if (screenshot != null && !(after >= 0 && Double.isFinite(after))) {
            throw new IllegalArgumentException("--after must be a finite number >= 0 s, got " + after);
        }
        if (runFor != null && !(runFor > 0 && runFor <= 86_400)) {
            throw new IllegalArgumentException("--run-for must be a number of wall seconds > 0 and at most a day,"
                    + " got " + runFor);
        }
        int threadCount = threads.threads(spec);
        if (fpsCap < 0 || fpsCap > 1000) {
            throw new IllegalArgumentException("--fps-cap must be 0 (no cap) to 1000 frames per second, got " + fpsCap);
        }
        // Bad names and files fail here, before any window.
        if (pick.file() != null && !"diaphragm".equals(scene)) {
            throw new IllegalArgumentException("--pick " + pick.file() + " is a resolution of the diaphragm: leave it"
                    + " out with --scene " + scene);
        }
        java.util.List<String> sceneArgs = sceneFromPreset(java.util.List.of());
        sceneFile.refuseSetsWithoutFile();
        SceneFactory factory = sceneFile.given() ? sceneFile.factory(spec) : TunableScenes.factory(scene, options);
        StringBuilder unmapped = new StringBuilder();
        boolean organs = addOrgans(factory);
        org.tensim.experiment.diaphragm.ResolutionPick picked = sceneFile.given() || organs ? null
                : TunableScenes.mapMechanics(factory, pick, options, unmapped::append);
        requireDisplay();
        boolean script = screenshot != null || runFor != null;
        setScripted(script);
        Path dir = configDir != null ? configDir : ConfigDir.resolve();
        // A scripted run starts paused and plays once the view is up (takeScreenshotAndClose, TimedRun).
        // It never overwrites what the user tuned last.
        // A scene file runs with its own settings: nothing last-used is restored over them, nor saved.
        boolean keep = !sceneFile.given();
        GuiWindow w = open(factory, fresh || !keep ? null : dir, script || !keep ? null : dir, preset,
                !paused && !script, threadCount,
                keep && !organs && TunableScenes.opensInRealTime(scene) && !options.paperModel(),
                options.muscleLoad != null, options.thorax != null && !organs,
                sceneFile.given() ? Map.of() : options.controlValues(organs));
        w.tuning().setSceneOptions(sceneArgs);
        if (picked != null) {
            String note = "mechanics at " + picked.describe();
            SwingUtilities.invokeAndWait(() -> w.setTitleNote(note));
        } else if (unmapped.length() > 0) {
            SwingUtilities.invokeAndWait(() -> w.status().message(unmapped.toString(), false));
        }
        SwingUtilities.invokeAndWait(() -> w.setFrameCap(fpsCap));
        if (runFor != null) {
            java.util.Map<String, Object> summary = new java.util.LinkedHashMap<>(TimedRun.run(w, runFor, !unpaced,
                    screenshot, started));
            if (picked != null) {
                summary.put("resolution_pick", picked.toMap());
            }
            summary.put("window_title", w.windowTitle());
            w.awaitClosed();
            System.out.println(org.tensim.io.Json.line(summary));
            return summary.get("diverged") == null ? 0 : 1;
        }
        if (unpaced) {
            SwingUtilities.invokeAndWait(() -> w.controls().setPaced(false));
        }
        if (screenshot != null) {
            takeScreenshotAndClose(w, screenshot, after);
        }
        w.awaitClosed();
        return 0;
    }

    /**
     * With {@code --lungs}, reads the thorax's organs and has the factory build them into every scene; returns
     * whether it did.
     *
     * @throws picocli.CommandLine.ParameterException for --lungs without --thorax, on another scene or with --pick,
     *                                                and for --liver without --lungs
     */
    private boolean addOrgans(SceneFactory factory) throws java.io.IOException {
        if (liver != null && !lungs) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--liver and --no-liver go with"
                    + " --lungs");
        }
        boolean withLiver = liver == null || liver;
        if (!lungs) {
            return false;
        }
        if (!(factory instanceof org.tensim.scene.tunable.DiaphragmViewFactory f) || options.thorax == null
                || pick.file() != null) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--lungs needs the diaphragm with"
                    + " --thorax DIR (the organs' meshes) and runs the full model: leave out --pick, --scene cube and"
                    + " a scene file");
        }
        var o = org.tensim.scene.lungs.ThoraxOrgans.Options.defaults();
        f.setOrgans(new org.tensim.scene.tunable.DiaphragmOrgans(org.tensim.scene.lungs.OrganMeshes.load(
                options.thorax, withLiver), withLiver ? o.withLiver() : o.withoutLiver()));
        return true;
    }

    /**
     * Fails with one line when there is no display or it cannot be reached (AWT's
     * AWTError would otherwise surface as a long stack trace from the first window).
     */
    static void requireDisplay() {
        if (java.awt.GraphicsEnvironment.isHeadless()) {
            throw new IllegalStateException("the GUI needs a display: none is set (DISPLAY) or Java runs headless;"
                    + " ./tensim gui starts one with xvfb-run when DISPLAY is unset");
        }
        try {
            java.awt.GraphicsEnvironment.getLocalGraphicsEnvironment().getScreenDevices();
        } catch (java.awt.AWTError | java.awt.HeadlessException | UnsatisfiedLinkError e) {
            throw new IllegalStateException("cannot reach the display DISPLAY='" + System.getenv("DISPLAY")
                    + "' (" + e.getMessage() + "); start the X server, fix DISPLAY, or unset it so that ./tensim gui"
                    + " starts Xvfb");
        }
    }

    /**
     * Makes the first scene, restores the last-used parameters (from restoreDir,
     * unless null), applies a preset, and opens the window.
     *
     * @param saveDir where last-used parameters are saved on change and at exit (null: not saved)
     */
    static GuiWindow open(SceneFactory factory, Path restoreDir, Path saveDir, Path preset, boolean play)
            throws Exception {
        return open(factory, restoreDir, saveDir, preset, play, 0, false);
    }

    /**
     * As {@link #open(SceneFactory, Path, Path, Path, boolean)} with a thread count (0: automatic),
     * starting from the large-step solver when realTime (before last-used parameters and the preset).
     */
    static GuiWindow open(SceneFactory factory, Path restoreDir, Path saveDir, Path preset, boolean play, int threads,
            boolean realTime) throws Exception {
        return open(factory, restoreDir, saveDir, preset, play, threads, realTime, false, false, Map.of());
    }

    /**
     * As {@link #open(SceneFactory, Path, Path, Path, boolean, int, boolean)}; with {@code loadGiven} (the muscle
     * load named on the command line) the last-used parameters are restored only when they were tuned with that
     * load (a preset given with {@code --preset} still applies its own, rebuilding the scene); with {@code contact}
     * (a thorax of bone surfaces) starting from the thorax's real-time setting ({@link Integrators#CONTACT_REAL_TIME}
     * at {@link Integrators#REAL_TIME_STEP_S}, within 5 % of the step converged for contact, docs/thorax.md), whether
     * or not realTime is asked: the double dome's real-time step lags far there (the swept cage, {@code --cage
     * surfaces}, opens at the double dome's real-time step, which holds there with the contact projection). The
     * controls {@code given} on the command line (control key to the option and its value) are set over the
     * last-used values and the preset's: what a user types wins.
     */
    static GuiWindow open(SceneFactory factory, Path restoreDir, Path saveDir, Path preset, boolean play, int threads,
            boolean realTime, boolean loadGiven, boolean contact, Map<String, Map.Entry<String, Double>> given)
            throws Exception {
        ViewScene first = factory.create(true);
        Tuning tuning = factory.muscleLoad() == null
                ? new Tuning(first.name(), first.parameters(), first.defaultTimeStep(), factory.hasTendonChoice(),
                        Integrators.choices())
                : new Tuning(first.name(), first.parameters(), first.defaultTimeStep(), factory.hasTendonChoice(),
                        Integrators.choices(), factory.muscleLoad(), factory::parameters);
        if (contact) {
            tuning.setIntegrator(Integrators.CONTACT_REAL_TIME);
            tuning.set(Tuning.TIME_STEP, Integrators.REAL_TIME_STEP_S);
        } else if (realTime) {
            tuning.setIntegrator(Integrators.REAL_TIME);
            tuning.set(Tuning.TIME_STEP, Integrators.REAL_TIME_STEP_S);
        } else if (first.defaultIntegrator() != null) {
            tuning.setIntegrator(first.defaultIntegrator());
        }
        String note = restoreDir == null ? null
                : restore(tuning, ConfigDir.lastUsed(restoreDir, first.name()), loadGiven);
        if (preset != null) {
            try {
                tuning.apply(PresetFile.read(preset, tuning), preset.toString());
            } catch (PresetFile.PresetException e) {
                throw new IllegalArgumentException("--preset: " + e.getMessage(), e);
            }
        }
        for (Map.Entry<String, Map.Entry<String, Double>> g : given.entrySet()) {
            try {
                tuning.set(g.getKey(), g.getValue().getValue());
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(g.getValue().getKey() + " " + g.getValue().getValue() + ": "
                        + e.getMessage(), e);
            }
        }
        // The first scene was made with the defaults: make it again if what was restored needs a new one.
        boolean remake = factory.hasTendonChoice() && !tuning.tensegrityTendon();
        remake |= tuning.muscleLoad() != null && !tuning.muscleLoad().equals(factory.muscleLoad());
        for (org.tensim.scene.tunable.TunableParameter p : first.parameters()) {
            remake |= p.restarts() && tuning.get(p.key()) != p.defaultValue();
        }
        if (remake) {
            first = factory.create(tuning.tensegrityTendon(), tuning.muscleLoad(), tuning.snapshot().values());
        }
        ViewScene start = first;
        AtomicReference<GuiWindow> w = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> w.set(new GuiWindow(factory, start, tuning, saveDir, play, note, threads)));
        return w.get();
    }

    /**
     * The diaphragm's options in command-line form (null for the cube): those given, or the scene a
     * {@code --preset} holds with the options given beside it changing it ({@link PresetScene#merge}), which then
     * replaces {@link #options}; a muscle load given applies over the preset's.
     *
     * @param implied options implied by others (the rings of {@code --pick}), counted as given
     */
    private java.util.List<String> sceneFromPreset(java.util.List<String> implied) {
        if (!"diaphragm".equals(scene)) {
            return null;
        }
        java.util.List<String> given = new java.util.ArrayList<>(
                PresetScene.given(spec.commandLine().getParseResult()));
        given.addAll(implied);
        if (preset == null) {
            return given;
        }
        PresetScene.Read held;
        try {
            held = PresetFile.scene(preset);
        } catch (PresetFile.PresetException e) {
            throw new IllegalArgumentException("--preset: " + e.getMessage(), e);
        }
        if (held == null) {
            return given;
        }
        java.util.List<String> scene = PresetScene.merge(held.options(), given);
        java.util.List<String> args = new java.util.ArrayList<>(scene);
        BoundaryConditions.MuscleLoad load = options.muscleLoad != null ? options.muscleLoad : held.muscleLoad();
        if (load != null) {
            args.addAll(java.util.List.of("--muscle-load", BoundaryConditions.name(load)));
        }
        options = DiaphragmOptions.parse(args);
        return scene;
    }

    /** Restores last-used parameters ({@link LastUsedParameters#restore(Tuning, Path, boolean)}). */
    static String restore(Tuning tuning, Path file) {
        return LastUsedParameters.restore(tuning, file, false);
    }

    /** As {@link LastUsedParameters#restore(Tuning, Path, boolean)}. */
    static String restore(Tuning tuning, Path file, boolean keepLoad) {
        return LastUsedParameters.restore(tuning, file, keepLoad);
    }

    /**
     * Plays once the view renders, waits for the simulated time (at most 10 min of
     * wall time), saves the running window as PNG and closes it.
     */
    static void takeScreenshotAndClose(GuiWindow w, Path file, double afterS) throws Exception {
        long deadline = System.nanoTime() + 600_000_000_000L;
        // Java3D takes a moment to show its first frame: start the clock only then.
        while ((w.scene() == null || w.view().framesRendered() < 3) && System.nanoTime() < deadline) {
            Thread.sleep(20);
        }
        SwingUtilities.invokeAndWait(() -> {
            w.play(true);
            w.controls().showPlaying(true);
        });
        while ((w.runner().simTime() < afterS || w.view().shownTime() < afterS * 0.99)
                && w.runner().divergence() == null && System.nanoTime() < deadline) {
            Thread.sleep(10);
        }
        SwingUtilities.invokeAndWait(() -> w.chart().refresh());
        Thread.sleep(300); // the status bar's rates refresh every 250 ms
        AtomicReference<Exception> error = new AtomicReference<>();
        double[] shown = new double[1];
        SwingUtilities.invokeAndWait(() -> {
            try {
                shown[0] = w.view().shownTime();
                w.saveScreenshot(file);
            } catch (Exception e) {
                error.set(e);
            }
            w.close();
        });
        if (error.get() != null) {
            throw new java.io.IOException("cannot save screenshot " + file + ": " + error.get().getMessage(), error.get());
        }
        System.out.println("wrote " + file.toAbsolutePath() + " (scene at t = "
                + String.format(java.util.Locale.ROOT, "%.3f", shown[0]) + " s)");
    }
}

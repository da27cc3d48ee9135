package org.tensim.app.gui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.CountDownLatch;
import javax.swing.JFrame;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JPanel;
import javax.swing.JPopupMenu;
import javax.swing.JScrollPane;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import javax.swing.ToolTipManager;
import org.tensim.scene.tunable.FrameBuffer;
import org.tensim.scene.tunable.ProbeRecorder;
import org.tensim.scene.tunable.DiaphragmViewScene;
import org.tensim.scene.tunable.DiaphragmViewFactory;
import org.tensim.scene.tunable.SceneFactory;
import org.tensim.scene.tunable.ViewScene;
import org.tensim.solver.SimulationDivergedException;
import org.tensim.tuning.ConfigDir;
import org.tensim.tuning.PresetFile;
import org.tensim.tuning.SimulationRunner;
import org.tensim.tuning.Tuning;
import org.tensim.view.SceneView;

/**
 * The main window: the Java3D view, the control panel, the live probe chart and
 * the status bar, wired to a {@link SimulationRunner}. The window is made and
 * used on the Swing thread; runner events are handed over to it. Closing the
 * window saves the last-used parameters, stops the simulation and releases
 * Java3D.
 */
final class GuiWindow implements ControlPanel.Actions, SimulationRunner.Events {
    private final SceneFactory factory;
    private final Tuning tuning;
    private final Path configDir;
    private final JFrame frame;
    private final SceneView view;
    private final ControlPanel controls;
    private final ProbeChart chart;
    private final StatusBar status = new StatusBar();
    private final LivePanel live = new LivePanel();
    private JMenuItem saveLabels;
    private final BrushPanel brush;
    private final LabelTools labels;
    private final PresetActions presets;
    private FrameCapMenu frameCaps;
    private final SimulationRunner runner;
    private final Timer uiTimer;
    private final Timer saveTimer;
    private final CountDownLatch closed = new CountDownLatch(1);
    private volatile ViewScene scene;
    private volatile boolean shutDown;
    private boolean layersSet;
    private String sceneTitle;
    private String titleNote;

    /**
     * Builds and shows the window and starts the simulation with {@code first}.
     * Swing thread only.
     *
     * @param configDir where last-used parameters are saved, or null not to save them
     * @param play      whether to start playing at once
     * @param startMessage a note for the status bar (e.g. why last-used parameters were not restored), or null
     * @param threads   threads per step of a body, 0 for the automatic rule ({@link SimulationRunner})
     */
    GuiWindow(SceneFactory factory, ViewScene first, Tuning tuning, Path configDir, boolean play,
            String startMessage, int threads) {
        this.factory = factory;
        this.tuning = tuning;
        this.configDir = configDir;
        // The Java3D canvas is a heavyweight component: menus and tooltips must be too, or they hide behind it.
        JPopupMenu.setDefaultLightWeightPopupEnabled(false);
        ToolTipManager.sharedInstance().setLightWeightPopupEnabled(false);

        sceneTitle = first.title();
        frame = new JFrame(windowTitle());
        frame.setDefaultCloseOperation(JFrame.DO_NOTHING_ON_CLOSE);
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosing(WindowEvent e) {
                close();
            }
        });
        view = new SceneView();
        view.canvas().setPreferredSize(new Dimension(830, 520));
        view.canvas().setMinimumSize(new Dimension(200, 150));
        chart = new ProbeChart(first.defaultProbeAxis());
        controls = new ControlPanel(tuning, this, first.defaultProbeAxis(), msg -> status.message(msg, true));
        runner = new SimulationRunner(factory, tuning::snapshot, this, threads);
        labels = new LabelTools(frame, status, runner, factory, configDir, () -> scene);
        presets = new PresetActions(frame, status, tuning);
        tuning.bind(runner);
        if (factory instanceof DiaphragmViewFactory f && f.mechanics() != null) {
            DiaphragmViewFactory.Mechanics m = f.mechanics();
            controls.showFullModelSwitch(String.format(java.util.Locale.ROOT, "the mechanics at %d rings carry the"
                    + " drawn mesh, %.1f %% from it (%s)", m.rings(), 100 * m.error(), m.source()), full -> {
                        f.setFullModel(full);
                        runner.reset();
                    });
        }

        JPanel centre = new JPanel(new BorderLayout());
        centre.add(view.canvas(), BorderLayout.CENTER);
        centre.add(chart.panel(), BorderLayout.SOUTH);
        JScrollPane side = new JScrollPane(controls, JScrollPane.VERTICAL_SCROLLBAR_AS_NEEDED,
                JScrollPane.HORIZONTAL_SCROLLBAR_NEVER);
        side.setPreferredSize(new Dimension(375, 700));
        side.getVerticalScrollBar().setUnitIncrement(16);
        frame.setJMenuBar(menus());
        JPanel east = new JPanel(new BorderLayout());
        brush = new BrushPanel(view.canvas(), (o, d, l, r) -> labels.stroke(o, d, l, r));
        JPanel top = new JPanel(new BorderLayout());
        top.add(live, BorderLayout.NORTH);
        top.add(brush, BorderLayout.SOUTH);
        east.add(top, BorderLayout.NORTH);
        east.add(side, BorderLayout.CENTER);
        frame.getContentPane().add(centre, BorderLayout.CENTER);
        frame.getContentPane().add(east, BorderLayout.EAST);
        frame.getContentPane().add(status, BorderLayout.SOUTH);
        frame.pack();
        frame.setLocation(0, 0);
        frame.setVisible(true);

        uiTimer = new Timer(250, e -> {
            chart.refresh();
            live.refresh();
            status.update(runner, view.framesRendered());
            if (runner.divergence() != null) {
                controls.showPlaying(false);
            }
        });
        uiTimer.start();
        saveTimer = new Timer(1000, e -> saveLastUsed());
        saveTimer.setRepeats(false);
        tuning.addListener(saveTimer::restart);
        if (startMessage != null) {
            status.message(startMessage, true);
        }
        runner.start(first);
        if (play) {
            play(true);
            controls.showPlaying(true);
        }
    }

    private JMenuBar menus() {
        JMenuBar bar = new JMenuBar();
        JMenu file = new JMenu("File");
        file.add(item("Load preset...", this::loadPreset));
        file.add(item("Save preset...", this::savePreset));
        file.add(item("Save screenshot...", () -> WindowPicture.saveDialog(frame, status)));
        saveLabels = item("Save labels...", () -> labels.saveDialog());
        saveLabels.setToolTipText("Writes the diaphragm's label per mesh vertex (tendon as tuned, muscle, origins) for"
                + " --labels");
        saveLabels.setEnabled(false);
        file.add(saveLabels);
        file.addSeparator();
        file.add(item("Quit", this::close));
        bar.add(file);
        frameCaps = new FrameCapMenu(view, status);
        bar.add(frameCaps);
        return bar;
    }

    /** Draws at most fps frames per second (0: no cap), leaving the rest of the renderer's core to the simulation. */
    void setFrameCap(int fps) {
        frameCaps.select(fps);
    }

    private static JMenuItem item(String text, Runnable r) {
        JMenuItem i = new JMenuItem(text);
        i.addActionListener(e -> r.run());
        return i;
    }

    // ---- runner events (simulation thread) ----

    @Override
    public void installed(ViewScene s, FrameBuffer frames, ProbeRecorder probes) {
        SwingUtilities.invokeLater(() -> {
            if (shutDown) {
                return;
            }
            scene = s;
            view.show(frames, s.displacementScale(), s.up(), s.viewFrom(), s.organBodies());
            controls.showOrgansBox(!s.organBodies().isEmpty());
            if (!layersSet) { // the scene's choice at first; the user's afterwards
                layersSet = true;
                controls.setLayer("springs", s.wireframeAtStart());
                controls.setLayer("nodes", s.wireframeAtStart());
            }
            chart.attach(probes, s.bodies());
            live.show(frames.live(), frames.readouts());
            saveLabels.setEnabled(s instanceof DiaphragmViewScene);
            brush.setVisible(s instanceof DiaphragmViewScene && factory instanceof DiaphragmViewFactory);
            status.showResolution(s.resolution());
            sceneTitle = s.title();
            frame.setTitle(windowTitle());
        });
    }

    /**
     * A note the title keeps after the scene's own, over every scene change: what the scene was opened from, such
     * as the resolution pick. Swing thread only.
     */
    void setTitleNote(String note) {
        titleNote = note;
        frame.setTitle(windowTitle());
    }

    /** The window's title: the scene's, then the note (if any). */
    String windowTitle() {
        return "tensim: " + sceneTitle + (titleNote == null ? "" : " | " + titleNote);
    }

    @Override
    public void diverged(String body, SimulationDivergedException e) {
        SwingUtilities.invokeLater(() -> controls.showPlaying(false));
    }

    @Override
    public void warning(String message) {
        SwingUtilities.invokeLater(() -> status.message("Warning: " + message, true));
    }

    @Override
    public void failed(String what, RuntimeException e) {
        SwingUtilities.invokeLater(() -> status.message(what + ": " + e.getMessage(), true));
    }

    // ---- control panel actions (Swing thread) ----

    @Override
    public void play(boolean on) {
        if (on) {
            runner.play();
        } else {
            runner.pause();
        }
    }

    @Override
    public void step() {
        runner.stepOnce();
    }

    @Override
    public void reset() {
        runner.reset();
        status.message("Reset: at rest, t = 0, current parameters kept", false);
    }

    @Override
    public void resetView() {
        view.resetView();
    }

    @Override
    public void paced(boolean on) {
        runner.setPaced(on);
    }

    @Override
    public void layer(String layer, boolean on) {
        switch (layer) {
            case "surface" -> view.showSurface(on);
            case "springs" -> view.showSprings(on);
            case "links" -> view.showLinks(on);
            case "nodes" -> view.showNodes(on);
            case "vectors" -> view.showVectors(on);
            case "structure" -> view.showStructure(on);
            case "organs" -> view.showOrgans(on);
            default -> throw new IllegalArgumentException("unknown layer " + layer);
        }
    }

    @Override
    public void probeAxis(int axis) {
        chart.setAxis(axis);
    }

    @Override
    public void loadPreset() {
        presets.loadDialog();
    }

    /** Loads a preset; a malformed one is refused with its reason and nothing changes. */
    boolean loadPreset(Path file) {
        return presets.load(file);
    }

    @Override
    public void savePreset() {
        presets.saveDialog();
    }

    /** Saves the current parameters atomically. */
    boolean savePreset(Path file) {
        return presets.save(file);
    }

    /** Captures the whole window as it is on screen into a PNG file (written, then renamed). */
    void saveScreenshot(Path file) throws Exception {
        WindowPicture.save(frame, file);
    }

    private void saveLastUsed() {
        if (configDir == null) {
            return;
        }
        Path p = ConfigDir.lastUsed(configDir, tuning.scene());
        try {
            PresetFile.write(p, tuning.snapshot());
        } catch (IOException e) {
            status.message("Cannot save last-used parameters to " + p + ": " + e.getMessage(), true);
        }
    }

    /** Saves what the user tuned, stops the simulation, releases Java3D and closes. Swing thread. */
    void close() {
        if (shutDown) {
            return;
        }
        shutDown = true;
        saveTimer.stop();
        saveLastUsed();
        uiTimer.stop();
        runner.stop();
        if (!view.dispose(5000)) {
            System.err.println("tensim gui: Java3D did not finish its clean-up within 5 s; closing anyway");
        }
        frame.setVisible(false);
        frame.dispose();
        closed.countDown();
    }

    /** Waits until the window is closed. */
    void awaitClosed() throws InterruptedException {
        closed.await();
    }

    // ---- for tests and scripted runs ----

    JFrame frame() {
        return frame;
    }

    SceneView view() {
        return view;
    }

    ControlPanel controls() {
        return controls;
    }

    SimulationRunner runner() {
        return runner;
    }

    ProbeChart chart() {
        return chart;
    }

    StatusBar status() {
        return status;
    }

    LivePanel live() {
        return live;
    }

    Tuning tuning() {
        return tuning;
    }

    /** The scene on screen, or null before the first is shown. */
    ViewScene scene() {
        return scene;
    }

    LabelTools labels() {
        return labels;
    }

    SceneFactory factory() {
        return factory;
    }
}

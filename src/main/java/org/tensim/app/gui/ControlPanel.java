package org.tensim.app.gui;

import java.awt.Component;
import java.awt.GridLayout;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import javax.swing.BorderFactory;
import javax.swing.Box;
import javax.swing.BoxLayout;
import javax.swing.ButtonGroup;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JRadioButton;
import javax.swing.JToggleButton;
import org.tensim.scene.tunable.TunableParameter;
import org.tensim.solver.integrators.IntegratorChoice;
import org.tensim.tuning.Tuning;

/**
 * The control panel: transport (play, pause, single step, reset), the scene's
 * parameters, the solver (integrator, time step), the tendon model, the view
 * layers and the chart's component. Everything it changes goes through
 * {@link Tuning} or the {@link Actions}.
 */
final class ControlPanel extends JPanel implements javax.swing.Scrollable {
    private static final long serialVersionUID = 1L;

    /** What the buttons do (implemented by the window). */
    interface Actions {
        void play(boolean on);

        void step();

        void reset();

        void resetView();

        void paced(boolean on);

        void layer(String layer, boolean on);

        void probeAxis(int axis);

        void loadPreset();

        void savePreset();
    }

    private final Tuning tuning;
    private final Actions actions;
    private final java.util.Map<String, JCheckBox> layerBoxes = new java.util.HashMap<>();
    private final List<ParameterControl> controls = new ArrayList<>();
    private final JToggleButton play = new JToggleButton("Play");
    private final JComboBox<IntegratorChoice> integrator;
    private final JCheckBox realTime;
    private final JRadioButton massSpring = new JRadioButton("Mass-spring");
    private final JRadioButton tensegrity = new JRadioButton("Tensegrity");
    private final JCheckBox fullModel = new JCheckBox("Full model (unmapped)");
    private boolean updating;

    ControlPanel(Tuning tuning, Actions actions, int probeAxis, Consumer<String> errors) {
        this.tuning = tuning;
        this.actions = actions;
        setLayout(new BoxLayout(this, BoxLayout.Y_AXIS));
        setBorder(BorderFactory.createEmptyBorder(6, 8, 6, 8));

        play.setName("play");
        play.addActionListener(e -> {
            play.setText(play.isSelected() ? "Pause" : "Play");
            actions.play(play.isSelected());
        });
        JButton step = button("Step", "step", "One time step (while paused)", actions::step);
        JButton reset = button("Reset", "reset", "Back to rest at t = 0 with the current parameters", actions::reset);
        JPanel transport = new JPanel(new GridLayout(1, 3, 4, 0));
        transport.add(play);
        transport.add(step);
        transport.add(reset);
        add(section("Simulation", transport));
        realTime = check("Real time (untick: as fast as possible)", "realtime", true, on -> actions.paced(on));
        add(left(realTime));

        JPanel params = column();
        for (TunableParameter p : tuning.parameters()) {
            if (!p.key().equals(Tuning.TIME_STEP)) {
                ParameterControl c = new ParameterControl(p, tuning, errors);
                controls.add(c);
                params.add(c);
            }
        }
        add(section("Scene parameters", params));

        JPanel solver = column();
        integrator = new JComboBox<>(tuning.integrators().toArray(new IntegratorChoice[0]));
        integrator.setName("integrator");
        integrator.setToolTipText("The integrator of stage 1 of the paper's loop; takes effect at the next step.");
        // A fixed width: the panel must not grow wider than its column for a long name.
        integrator.setPreferredSize(new java.awt.Dimension(220, integrator.getPreferredSize().height));
        integrator.setMaximumSize(integrator.getPreferredSize());
        integrator.setSelectedItem(tuning.integrator());
        integrator.addActionListener(e -> {
            if (!updating) {
                tuning.setIntegrator(((IntegratorChoice) integrator.getSelectedItem()).name());
            }
        });
        solver.add(left(new JLabel("Integrator")));
        solver.add(left(integrator));
        ParameterControl dt = new ParameterControl(tuning.parameter(Tuning.TIME_STEP), tuning, errors);
        controls.add(dt);
        solver.add(dt);
        fullModel.setName("fullModel");
        fullModel.setToolTipText("Every node of the drawn mesh runs the mechanics, unmapped.");
        solver.add(left(fullModel));
        fullModel.setVisible(false);
        add(section("Solver", solver));

        JPanel tendon = column();
        ButtonGroup g = new ButtonGroup();
        g.add(massSpring);
        g.add(tensegrity);
        massSpring.setName("tendon.massSpring");
        tensegrity.setName("tendon.tensegrity");
        massSpring.addActionListener(e -> {
            if (!updating) {
                tuning.setTensegrityTendon(false);
            }
        });
        tensegrity.addActionListener(e -> {
            if (!updating) {
                tuning.setTensegrityTendon(true);
            }
        });
        if (tuning.hasTendonChoice()) {
            tendon.add(left(massSpring));
            tendon.add(left(tensegrity));
            tendon.add(left(new JLabel("<html><i>A change rebuilds the tendon: the run restarts.</i></html>")));
        } else if ("cube".equals(tuning.scene())) {
            tendon.add(left(new JLabel("<html>Both models are shown side by side:<br>"
                    + "mass-spring left, tensegrity right.</html>")));
        }
        // A scene file's zones give its models: no tendon section.
        if (tuning.hasTendonChoice() || "cube".equals(tuning.scene())) {
            add(section("Tendon model", tendon));
        }

        JPanel view = column();
        view.add(left(button("Reset view", "resetView", "Back to the initial camera", actions::resetView)));
        JPanel layers = new JPanel(new GridLayout(0, 2));
        layers.add(layerBox("Surface", "surface", true));
        layers.add(layerBox("Springs", "springs", true));
        layers.add(layerBox("Rigid links", "links", true));
        layers.add(layerBox("Nodes", "nodes", true));
        layers.add(layerBox("Ribs, sternum", "structure", true));
        layers.add(layerBox("Displacements", "vectors", false));
        // Shown by the window for a scene with organs (the lungs and the liver about the diaphragm).
        layers.add(layerBox("Lungs, liver", "organs", true));
        layerBoxes.get("organs").setToolTipText("The organs' surfaces, translucent: hidden, they still run.");
        layerBoxes.get("organs").setVisible(false);
        view.add(left(layers));
        JComboBox<String> axis = new JComboBox<>(new String[] {"x", "y", "z", "magnitude"});
        axis.setName("probeAxis");
        axis.setSelectedIndex(probeAxis);
        axis.addActionListener(e -> actions.probeAxis(axis.getSelectedIndex()));
        JPanel axisRow = new JPanel(new GridLayout(1, 2, 4, 0));
        axisRow.add(new JLabel("Chart component"));
        axisRow.add(axis);
        view.add(left(axisRow));
        add(section("View", view));

        JPanel presets = new JPanel(new GridLayout(1, 2, 4, 0));
        presets.add(button("Load preset...", "loadPreset", "Load parameters from a JSON preset", actions::loadPreset));
        presets.add(button("Save preset...", "savePreset", "Save the parameters as a JSON preset", actions::savePreset));
        add(section("Presets", presets));
        add(Box.createVerticalGlue());

        tuning.addListener(this::refresh);
        refresh();
    }

    // Scrollable: as wide as the scroll pane's view (never clipped by the scroll bar), scrolled vertically.
    @Override
    public java.awt.Dimension getPreferredScrollableViewportSize() {
        return getPreferredSize();
    }

    @Override
    public int getScrollableUnitIncrement(java.awt.Rectangle visible, int orientation, int direction) {
        return 16;
    }

    @Override
    public int getScrollableBlockIncrement(java.awt.Rectangle visible, int orientation, int direction) {
        return visible.height - 32;
    }

    @Override
    public boolean getScrollableTracksViewportWidth() {
        return true;
    }

    @Override
    public boolean getScrollableTracksViewportHeight() {
        return false;
    }

    /** Shows the tuning's current values in every control. */
    void refresh() {
        updating = true;
        try {
            for (ParameterControl c : controls) {
                c.refresh();
            }
            integrator.setSelectedItem(tuning.integrator());
            massSpring.setSelected(!tuning.tensegrityTendon());
            tensegrity.setSelected(tuning.tensegrityTendon());
        } finally {
            updating = false;
        }
    }

    /** Ticks or unticks a view layer's box and applies it ("springs", "nodes", ...). */
    void setLayer(String layer, boolean on) {
        JCheckBox box = layerBoxes.get(layer);
        box.setSelected(on);
        actions.layer(layer, on);
    }

    /** Shows or hides the organs' box (a scene with organs has it). */
    void showOrgansBox(boolean on) {
        layerBoxes.get("organs").setVisible(on);
    }

    /** Ticks or unticks "Real time" (pacing to wall time) and applies it. */
    void setPaced(boolean on) {
        realTime.setSelected(on);
        actions.paced(on);
    }

    /** Sets the play button's state without firing it. */
    void showPlaying(boolean on) {
        play.setSelected(on);
        play.setText(on ? "Pause" : "Play");
    }

    /** The control of a parameter, by key. */
    ParameterControl control(String key) {
        for (ParameterControl c : controls) {
            if (c.parameter().key().equals(key)) {
                return c;
            }
        }
        throw new IllegalArgumentException("no control for parameter '" + key + "'");
    }

    private static JButton button(String text, String name, String tip, Runnable r) {
        JButton b = new JButton(text);
        b.setName(name);
        b.setToolTipText(tip);
        b.addActionListener(e -> r.run());
        return b;
    }

    private JCheckBox layerBox(String text, String layer, boolean on) {
        JCheckBox c = check(text, "layer." + layer, on, v -> actions.layer(layer, v));
        layerBoxes.put(layer, c);
        return c;
    }

    private static JCheckBox check(String text, String name, boolean on, Consumer<Boolean> r) {
        JCheckBox c = new JCheckBox(text, on);
        c.setName(name);
        c.addActionListener(e -> r.accept(c.isSelected()));
        return c;
    }

    private static JPanel column() {
        JPanel p = new JPanel();
        p.setLayout(new BoxLayout(p, BoxLayout.Y_AXIS));
        return p;
    }

    private static JComponent left(JComponent c) {
        c.setAlignmentX(Component.LEFT_ALIGNMENT);
        return c;
    }

    /**
     * Shows the switch between the mapped mechanics and the full model (a diaphragm whose mechanics run coarser than
     * it is drawn): {@code onChange} gets whether the full model is chosen, and rebuilds the scene.
     *
     * @param what one sentence for the tooltip: which resolutions and the error
     */
    void showFullModelSwitch(String what, Consumer<Boolean> onChange) {
        fullModel.setToolTipText("<html>Ticked: every node of the drawn mesh runs the mechanics, as the paper's model"
                + " (slower).<br>Unticked: " + what + ".<br>A change rebuilds the scene: the run restarts.</html>");
        fullModel.addActionListener(e -> onChange.accept(fullModel.isSelected()));
        fullModel.setVisible(true);
    }

    private static JComponent section(String title, JComponent body) {
        body.setBorder(BorderFactory.createCompoundBorder(BorderFactory.createTitledBorder(title),
                BorderFactory.createEmptyBorder(2, 4, 2, 4)));
        body.setAlignmentX(Component.LEFT_ALIGNMENT);
        return body;
    }
}

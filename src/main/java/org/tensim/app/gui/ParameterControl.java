package org.tensim.app.gui;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Dimension;
import java.util.function.Consumer;
import javax.swing.BorderFactory;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSlider;
import javax.swing.JTextField;
import org.tensim.scene.tunable.TunableParameter;
import org.tensim.tuning.Tuning;

/**
 * One row of the control panel: the parameter's label and unit, a slider over its
 * range (logarithmic where the parameter says so) and a field for an exact value.
 * Every change goes through {@link Tuning#set}; a refused value turns the field
 * red, reports the reason, and leaves the parameter as it was.
 */
final class ParameterControl extends JPanel {
    private static final long serialVersionUID = 1L;
    private static final int TICKS = 1000;
    private static final Color BAD = new Color(255, 205, 205);

    private TunableParameter p; // the tuning's description of the parameter, replaced when the muscle load changes
    private final JLabel label = new JLabel();
    private final Tuning tuning;
    private final Consumer<String> errors;
    private final JSlider slider = new JSlider(0, TICKS);
    private final JTextField field = new JTextField(8);
    private final Color normal;
    private boolean updating;

    ParameterControl(TunableParameter param, Tuning tuning, Consumer<String> errors) {
        super(new BorderLayout(4, 0));
        this.p = param;
        this.tuning = tuning;
        this.errors = errors;
        setName("param." + param.key());
        slider.setName("slider." + param.key());
        field.setName("field." + param.key());
        normal = field.getBackground();
        describe();
        slider.setPreferredSize(new Dimension(150, slider.getPreferredSize().height));
        add(label, BorderLayout.NORTH);
        add(slider, BorderLayout.CENTER);
        add(field, BorderLayout.EAST);
        setBorder(BorderFactory.createEmptyBorder(2, 0, 4, 0));
        slider.addChangeListener(e -> {
            if (!updating) {
                commit(roundForSlider(p.fromFraction(slider.getValue() / (double) TICKS)));
            }
        });
        field.addActionListener(e -> commitText());
        field.addFocusListener(new java.awt.event.FocusAdapter() {
            @Override
            public void focusLost(java.awt.event.FocusEvent e) {
                commitText();
            }
        });
        refresh();
    }

    /** The label and the tooltips from the parameter's description. */
    private void describe() {
        label.setText(p.labelWithUnit() + (p.restarts() ? ", restarts" : ""));
        String tip = "<html>" + p.description() + "<br>Range " + TunableParameter.format(p.min()) + " to "
                + TunableParameter.format(p.max()) + " " + p.unit() + (p.logarithmic() ? " (log scale)" : "")
                + "; default " + TunableParameter.format(p.defaultValue()) + ". Preset key: " + p.key()
                + (p.restarts() ? "<br><b>A change restarts the simulation from rest</b> (it needs a new scene)." : "")
                + "</html>";
        label.setToolTipText(tip);
        slider.setToolTipText(tip);
        field.setToolTipText(tip);
    }

    /** The label shown above the slider (for tests). */
    String labelText() {
        return label.getText();
    }

    /** Shows the tuning's current value. */
    void refresh() {
        updating = true;
        try {
            TunableParameter now = tuning.parameter(p.key());
            if (now != p) {
                p = now;
                describe();
            }
            double v = tuning.get(p.key());
            slider.setValue((int) Math.round(p.toFraction(v) * TICKS));
            field.setText(TunableParameter.format(v));
            field.setBackground(normal);
        } finally {
            updating = false;
        }
    }

    /** Three significant digits: a slider cannot aim finer, and presets stay readable. */
    private double roundForSlider(double v) {
        if (v == 0) {
            return 0;
        }
        double r = new java.math.BigDecimal(v).round(new java.math.MathContext(3)).doubleValue();
        return Math.max(p.min(), Math.min(p.max(), r));
    }

    private void commitText() {
        String text = field.getText().trim();
        double v;
        try {
            v = Double.parseDouble(text);
        } catch (NumberFormatException e) {
            refuse(p.label() + " (" + p.key() + "): '" + text + "' is not a number; expected "
                    + TunableParameter.format(p.min()) + " to " + TunableParameter.format(p.max()) + " " + p.unit());
            return;
        }
        if (v != tuning.get(p.key())) {
            commit(v);
        } else {
            refresh();
        }
    }

    private void commit(double v) {
        try {
            tuning.set(p.key(), v);
        } catch (IllegalArgumentException e) {
            refuse(e.getMessage());
        }
    }

    private void refuse(String message) {
        field.setBackground(BAD);
        errors.accept(message);
    }

    TunableParameter parameter() {
        return p;
    }

    /** Types a value into the field and presses Enter, as a user would (tests, scripting). */
    void enter(String text) {
        field.setText(text);
        field.postActionEvent();
    }

    /** Whether the field currently shows a refused value. */
    boolean showsError() {
        return field.getBackground().equals(BAD);
    }
}

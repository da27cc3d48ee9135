package org.tensim.app.gui;

import java.awt.BorderLayout;
import java.awt.Color;
import java.util.Locale;
import javax.swing.BorderFactory;
import javax.swing.JLabel;
import javax.swing.JPanel;
import org.tensim.tuning.ErrorReadout;
import org.tensim.tuning.SimulationRunner;

/**
 * The status line: simulated time, steps per second, real-time factor, frames
 * per second, the time step and the integrator's error estimate (when it gives
 * one, {@link ErrorReadout}), and warnings (time step beyond the critical estimate, rigid links
 * not converging, divergence, refused values). Rates are measured between two
 * calls of {@link #update}.
 */
final class StatusBar extends JPanel {
    private static final long serialVersionUID = 1L;
    private final JLabel numbers = new JLabel(" ");
    private final JLabel warning = new JLabel(" ");
    private final JLabel resolution = new JLabel(" ");
    private long lastNanos;
    private long lastSteps;
    private double lastSim;
    private long lastFrames;
    private String message;
    private long messageUntil;

    StatusBar() {
        super(new BorderLayout(12, 0));
        setBorder(BorderFactory.createEmptyBorder(3, 8, 3, 8));
        numbers.setName("status.numbers");
        warning.setName("status.warning");
        warning.setForeground(new Color(190, 60, 0));
        add(numbers, BorderLayout.WEST);
        add(warning, BorderLayout.CENTER);
        resolution.setName("status.resolution");
        add(resolution, BorderLayout.EAST);
    }

    /**
     * Shows which resolution runs the mechanics against the one drawn, and its measured error (nothing for a scene
     * without the question).
     */
    void showResolution(org.tensim.scene.tunable.ViewScene.Resolution r) {
        resolution.setText(resolutionText(r));
        resolution.setToolTipText(r == null ? null : r.describe());
    }

    /** The status bar's resolution text: mapped with its error, or the full model; empty for none. */
    static String resolutionText(org.tensim.scene.tunable.ViewScene.Resolution r) {
        if (r == null) {
            return " ";
        }
        if (r.mechanicalNodes() == r.drawnNodes()) {
            return String.format(Locale.ROOT, "full model: %,d nodes", r.drawnNodes());
        }
        return String.format(Locale.ROOT, "mechanics %,d nodes, drawn %,d: %.1f %% error", r.mechanicalNodes(),
                r.drawnNodes(), 100 * r.error());
    }

    /** The resolution text shown (for tests). */
    String resolutionText() {
        return resolution.getText();
    }

    /** Shows a message in the warning area for a while (refused value, preset loaded...). */
    void message(String text, boolean isError) {
        message = text;
        messageUntil = System.nanoTime() + 8_000_000_000L;
        warning.setForeground(isError ? new Color(190, 60, 0) : new Color(20, 110, 40));
        warning.setText(text);
        warning.setToolTipText(text);
    }

    /** Recomputes the rates and the warning from the runner and the view's frame count. */
    void update(SimulationRunner r, long framesRendered) {
        long now = System.nanoTime();
        double wall = (now - lastNanos) * 1e-9;
        long steps = r.steps();
        double sim = r.simTime();
        if (lastNanos != 0 && wall > 0) {
            double sps = Math.max(0, steps - lastSteps) / wall;
            double rtf = Math.max(0, sim - lastSim) / wall;
            double fps = (framesRendered - lastFrames) / wall;
            String h = org.tensim.scene.tunable.TunableParameter.format(r.timeStep()) + " s" + errorText(r.errorEstimate());
            if (r.isPlaying()) {
                numbers.setText(String.format(Locale.ROOT, "t = %.3f s   |   %,.0f steps/s   |   real-time x%.2f   |   "
                        + "%.0f fps   |   h = %s", sim, sps, rtf, fps, h));
            } else {
                numbers.setText(String.format(Locale.ROOT, "t = %.3f s   |   paused (%,d steps)   |   %.0f fps   |   h = %s",
                        sim, steps, fps, h));
            }
            numbers.setToolTipText(r.threads() + (r.threads() == 1 ? " thread" : " threads") + " per step"
                    + (Double.isNaN(r.errorEstimate()) ? "" : "; error: the integrator's own relative estimate"
                            + " of its last step"));
        }
        lastNanos = now;
        lastSteps = steps;
        lastSim = sim;
        lastFrames = framesRendered;
        String w = warnings(r);
        if (w != null) {
            warning.setForeground(new Color(190, 60, 0));
            warning.setText(w);
            warning.setToolTipText(w);
        } else if (message != null && now < messageUntil) {
            warning.setText(message);
        } else {
            message = null;
            warning.setText(" ");
            warning.setToolTipText(null);
        }
    }

    /** The integrator's error estimate as shown after the time step: empty when it gives none. */
    static String errorText(double estimate) {
        if (Double.isNaN(estimate)) {
            return "";
        }
        return String.format(Locale.ROOT, "   |   error ~%.2g %%", 100 * estimate);
    }

    /** The standing warnings, or null. */
    static String warnings(SimulationRunner r) {
        StringBuilder b = new StringBuilder();
        if (r.divergence() != null) {
            b.append("Diverged, stopped: ").append(r.divergence()).append(" Press Reset. ");
        }
        double crit = r.criticalTimeStep();
        if (r.timeStep() > crit) {
            b.append(String.format(Locale.ROOT, "Time step %s s exceeds the critical estimate %s s for this integrator. ",
                    org.tensim.scene.tunable.TunableParameter.format(r.timeStep()), org.tensim.scene.tunable.TunableParameter.format(crit)));
        }
        if (r.unconvergedProjections() > 0) {
            b.append(r.unconvergedProjections()).append(" steps with rigid links above tolerance. ");
        }
        return b.length() == 0 ? null : b.toString().trim();
    }

    String numbersText() {
        return numbers.getText();
    }

    String warningText() {
        return warning.getText();
    }
}

package org.tensim.app.gui;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.GridLayout;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import javax.swing.BorderFactory;
import javax.swing.JLabel;
import javax.swing.JPanel;
import org.tensim.scene.tunable.LatestValues;
import org.tensim.scene.tunable.LiveState;

/**
 * The legend of the scene's colours and its live readouts ({@link LiveState}), beside the view: each colour with
 * what it means, each readout with its unit, refreshed from the simulation's newest frame by the window's timer.
 * Hidden for a scene without a live state (the cube). Swing thread only.
 */
final class LivePanel extends JPanel {
    private static final long serialVersionUID = 1L;
    private final JPanel legend = new JPanel(new GridLayout(0, 2, 6, 2));
    private final JPanel figures = new JPanel(new GridLayout(0, 2, 6, 2));
    private final List<JLabel> values = new ArrayList<>();
    private List<LiveState.Readout> readouts = List.of();
    private LatestValues source;

    LivePanel() {
        super(new BorderLayout(0, 4));
        setBorder(BorderFactory.createCompoundBorder(BorderFactory.createTitledBorder("Colours and readouts"),
                BorderFactory.createEmptyBorder(2, 4, 2, 4)));
        add(legend, BorderLayout.NORTH);
        add(figures, BorderLayout.CENTER);
        setVisible(false);
    }

    /** Shows the legend and readouts of a new scene's live state (null: hides the panel). */
    void show(LiveState live, LatestValues latest) {
        legend.removeAll();
        figures.removeAll();
        values.clear();
        source = latest;
        readouts = live == null ? List.of() : live.readouts();
        if (live != null) {
            for (LiveState.Legend l : live.legend()) {
                JLabel swatch = new JLabel(l.label());
                swatch.setIcon(new javax.swing.ImageIcon(square(l.rgb())));
                legend.add(swatch);
            }
            for (LiveState.Readout r : readouts) {
                figures.add(new JLabel(r.label() + (r.unit().isEmpty() ? "" : " (" + r.unit() + ")")));
                JLabel v = new JLabel("-", JLabel.RIGHT);
                v.setName("readout." + r.label());
                values.add(v);
                figures.add(v);
            }
        }
        setVisible(live != null);
        revalidate();
        repaint();
    }

    /** Shows the newest readouts. */
    void refresh() {
        if (source == null) {
            return;
        }
        double[] v = source.latest();
        for (int i = 0; i < values.size() && i < v.length; i++) {
            values.get(i).setText(format(v[i], readouts.get(i).unit()));
        }
    }

    /** The text shown for a readout: "-" when the scene cannot measure it, else rounded for its unit. */
    static String format(double v, String unit) {
        if (!Double.isFinite(v)) {
            return "-";
        }
        return "mm^2".equals(unit) ? String.format(Locale.ROOT, "%,.0f", v)
                : String.format(Locale.ROOT, "%.2f", v);
    }

    /** The readouts last shown, by their summary key (NaN where not measured). */
    java.util.Map<String, Double> shownValues() {
        java.util.Map<String, Double> m = new java.util.LinkedHashMap<>();
        double[] v = source == null ? new double[0] : source.latest();
        for (int i = 0; i < readouts.size() && i < v.length; i++) {
            m.put(readouts.get(i).key(), v[i]);
        }
        return m;
    }

    /** The text on screen of the readout with this label (for tests), or null. */
    String shown(String label) {
        for (int i = 0; i < readouts.size(); i++) {
            if (readouts.get(i).label().equals(label)) {
                return values.get(i).getText();
            }
        }
        return null;
    }

    private static java.awt.image.BufferedImage square(float[] rgb) {
        java.awt.image.BufferedImage img = new java.awt.image.BufferedImage(14, 14,
                java.awt.image.BufferedImage.TYPE_INT_RGB);
        java.awt.Graphics2D g = img.createGraphics();
        g.setColor(new Color(rgb[0], rgb[1], rgb[2]));
        g.fillRect(0, 0, 14, 14);
        g.setColor(Color.DARK_GRAY);
        g.drawRect(0, 0, 13, 13);
        g.dispose();
        return img;
    }
}

package org.tensim.app.gui;

import java.awt.FlowLayout;
import java.awt.GridLayout;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import javax.swing.BorderFactory;
import javax.swing.JCheckBox;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSpinner;
import javax.swing.SpinnerNumberModel;
import org.jogamp.java3d.Canvas3D;
import org.jogamp.java3d.Transform3D;
import org.jogamp.vecmath.Point3d;
import org.tensim.io.mesh.VertexLabel;

/**
 * The label brush's controls: "Paint labels" on, a click on the diaphragm (without dragging: a drag still turns the
 * view) paints every vertex within the radius of the vertex under the pointer with the chosen label, and the scene
 * restarts at rest with them ({@link GuiWindow#stroke}).
 */
final class BrushPanel extends JPanel {
    private static final long serialVersionUID = 1L;

    /** What a click asks for: a ray in the view's world frame (m), the label and the brush's radius. */
    interface Stroke {
        void paint(double[] origin, double[] direction, VertexLabel label, double radiusM);
    }

    private final JCheckBox on = new JCheckBox("Paint labels (click on the mesh)");
    private final JComboBox<VertexLabel> label = new JComboBox<>(VertexLabel.values());
    private final JSpinner radiusMm = new JSpinner(new SpinnerNumberModel(10.0, 1.0, 200.0, 1.0));

    BrushPanel(Canvas3D canvas, Stroke stroke) {
        super(new GridLayout(0, 1));
        setBorder(BorderFactory.createTitledBorder("Label brush"));
        on.setToolTipText("Click on the diaphragm to paint the label within the radius; the run restarts at rest with"
                + " the painted labels, which are kept in painted.labels beside the last-used parameters");
        label.setSelectedItem(VertexLabel.TENDON);
        label.setRenderer((list, value, index, selected, focus) -> new JLabel(value == null ? "" : value.fileName()));
        JPanel row = new JPanel(new FlowLayout(FlowLayout.LEFT, 4, 0));
        row.add(label);
        row.add(new JLabel("radius, mm"));
        row.add(radiusMm);
        add(on);
        add(row);
        canvas.addMouseListener(new MouseAdapter() {
            @Override
            public void mouseClicked(MouseEvent e) {
                if (on.isSelected() && e.getButton() == MouseEvent.BUTTON1) {
                    double[][] ray = ray(canvas, e.getX(), e.getY());
                    stroke.paint(ray[0], ray[1], (VertexLabel) label.getSelectedItem(),
                            1e-3 * ((Number) radiusMm.getValue()).doubleValue());
                }
            }
        });
    }

    /** Turns painting on or off (for scripts and tests). */
    void setPainting(boolean p) {
        on.setSelected(p);
    }

    /** The ray from the eye through pixel (x, y) of the canvas, in the view's world frame: {origin, direction}. */
    static double[][] ray(Canvas3D canvas, int x, int y) {
        Point3d eye = new Point3d();
        Point3d pixel = new Point3d();
        canvas.getCenterEyeInImagePlate(eye);
        canvas.getPixelLocationInImagePlate(x, y, pixel);
        Transform3D toWorld = new Transform3D();
        canvas.getImagePlateToVworld(toWorld);
        toWorld.transform(eye);
        toWorld.transform(pixel);
        return new double[][] {{eye.x, eye.y, eye.z}, {pixel.x - eye.x, pixel.y - eye.y, pixel.z - eye.z}};
    }
}

package org.tensim.app.gui;

import java.io.IOException;
import java.nio.file.Path;
import java.util.function.Supplier;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JOptionPane;
import javax.swing.filechooser.FileNameExtensionFilter;
import org.tensim.io.mesh.VertexLabel;
import org.tensim.io.mesh.VertexLabelsFile;
import org.tensim.scene.tunable.DiaphragmViewFactory;
import org.tensim.scene.tunable.DiaphragmViewScene;
import org.tensim.scene.tunable.LabelBrush;
import org.tensim.scene.tunable.SceneFactory;
import org.tensim.scene.tunable.ViewScene;
import org.tensim.tuning.SimulationRunner;

/** The window's work on the diaphragm's vertex labels: saving them ({@code File > Save labels...}) and the brush. */
final class LabelTools {
    private final JFrame frame;
    private final StatusBar status;
    private final SimulationRunner runner;
    private final SceneFactory factory;
    private final Path configDir;
    private final Supplier<ViewScene> current;

    LabelTools(JFrame frame, StatusBar status, SimulationRunner runner, SceneFactory factory, Path configDir,
            Supplier<ViewScene> current) {
        this.frame = frame;
        this.status = status;
        this.runner = runner;
        this.factory = factory;
        this.configDir = configDir;
        this.current = current;
    }

    void saveDialog() {
        JFileChooser c = new JFileChooser();
        c.setFileFilter(new FileNameExtensionFilter("tensim vertex labels (*.labels, *.txt)", "labels", "txt"));
        if (c.showSaveDialog(frame) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        Path p = c.getSelectedFile().toPath();
        boolean replace = false;
        if (java.nio.file.Files.exists(p)) {
            replace = JOptionPane.showConfirmDialog(frame, p + " exists. Replace it?", "Save labels",
                    JOptionPane.YES_NO_OPTION, JOptionPane.WARNING_MESSAGE) == JOptionPane.YES_OPTION;
            if (!replace) {
                status.message("Labels not saved: " + p + " exists", true);
                return;
            }
        }
        saveLabels(p, replace);
    }

    /**
     * Writes the labels of the diaphragm on screen ({@link DiaphragmViewScene#saveLabels}); an existing file is
     * replaced only when {@code replace} (the dialog asks first). Reports in the status bar.
     */
    boolean saveLabels(Path file, boolean replace) {
        if (!(current.get() instanceof DiaphragmViewScene d)) {
            status.message("Labels: only the diaphragm has vertex labels", true);
            return false;
        }
        try {
            int n = d.saveLabels(file, replace);
            status.message("Saved the labels of " + n + " vertices to " + file, false);
            return true;
        } catch (java.nio.file.FileAlreadyExistsException e) {
            status.message("Labels not saved: " + file + " exists (not replaced)", true);
            return false;
        } catch (IOException | RuntimeException e) {
            status.message("Cannot save labels to " + file + ": " + e.getMessage(), true);
            return false;
        }
    }

    /**
     * One stroke of the label brush: the vertex the ray (world frame, m) meets first takes {@code label}, with every
     * vertex within {@code radiusM} of it; the labels are written to {@code painted.labels} (in the configuration
     * folder, or a temporary file when there is none), the factory builds from them, and the run restarts at rest.
     *
     * @return the vertices painted, or -1 when nothing was hit or painted
     */
    int stroke(double[] origin, double[] direction, VertexLabel label, double radiusM) {
        if (!(current.get() instanceof DiaphragmViewScene d) || !(factory instanceof DiaphragmViewFactory f)) {
            status.message("Label brush: only the diaphragm has vertex labels", true);
            return -1;
        }
        org.tensim.model.Vec3 off = d.bodies().get(0).offset();
        double[] o = {origin[0] - off.x(), origin[1] - off.y(), origin[2] - off.z()};
        int v = LabelBrush.pick(d.scene().surfaces(), o, direction, Math.max(0.5 * radiusM, 0.002));
        if (v < 0) {
            status.message("Label brush: no vertex of the diaphragm under the pointer", true);
            return -1;
        }
        try {
            VertexLabel[] before = d.scene().currentVertexLabels();
            VertexLabel[] after = LabelBrush.paint(d.scene().surfaces(), before, v, radiusM, label);
            int changed = 0;
            for (int i = 0; i < after.length; i++) {
                changed += after[i] != before[i] ? 1 : 0;
            }
            Path file = configDir != null ? configDir.resolve("painted.labels")
                    : java.nio.file.Files.createTempFile("tensim-painted", ".labels");
            java.nio.file.Files.createDirectories(file.toAbsolutePath().getParent());
            VertexLabelsFile.write(file, after);
            f.paintLabels(after, file);
            runner.reset();
            status.message("Painted " + changed + " vertices " + label.fileName() + " around vertex " + v
                    + "; the run restarts with the labels of " + file, false);
            return changed;
        } catch (IOException | RuntimeException e) {
            status.message("Label brush: cannot paint or keep the labels: " + e.getMessage(), true);
            return -1;
        }
    }
}

package org.tensim.app.gui;

import java.io.IOException;
import java.nio.file.Path;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JOptionPane;
import javax.swing.filechooser.FileNameExtensionFilter;
import org.tensim.tuning.PresetFile;
import org.tensim.tuning.PresetScene;
import org.tensim.tuning.Settings;
import org.tensim.tuning.Tuning;

/** The window's presets: File &gt; Load preset... and Save preset... */
final class PresetActions {
    private final JFrame frame;
    private final StatusBar status;
    private final Tuning tuning;

    PresetActions(JFrame frame, StatusBar status, Tuning tuning) {
        this.frame = frame;
        this.status = status;
        this.tuning = tuning;
    }

    void loadDialog() {
        JFileChooser c = chooser();
        if (c.showOpenDialog(frame) == JFileChooser.APPROVE_OPTION) {
            load(c.getSelectedFile().toPath());
        }
    }

    /** Loads a preset; a malformed one is refused with its reason and nothing changes. */
    boolean load(Path file) {
        try {
            Settings s = PresetFile.read(file, tuning);
            if (s.sceneOptions() != null && tuning.sceneOptions() != null
                    && !PresetScene.same(s.sceneOptions(), tuning.sceneOptions())) {
                throw new IllegalArgumentException(file + ": field 'diaphragm' describes another scene "
                        + s.sceneOptions() + " than this window's " + tuning.sceneOptions()
                        + ": open it with tensim gui --preset " + file);
            }
            tuning.apply(s, file.toString());
            status.message("Loaded preset " + file, false);
            return true;
        } catch (PresetFile.PresetException | IllegalArgumentException e) {
            status.message("Preset refused: " + e.getMessage(), true);
            if (frame.isShowing() && !GuiCommand.scripted()) {
                JOptionPane.showMessageDialog(frame, e.getMessage(), "Preset refused", JOptionPane.ERROR_MESSAGE);
            }
            return false;
        }
    }

    void saveDialog() {
        JFileChooser c = chooser();
        if (c.showSaveDialog(frame) == JFileChooser.APPROVE_OPTION) {
            Path p = c.getSelectedFile().toPath();
            if (!p.getFileName().toString().endsWith(".json")) {
                p = p.resolveSibling(p.getFileName() + ".json");
            }
            save(p);
        }
    }

    /** Saves the current parameters atomically. */
    boolean save(Path file) {
        try {
            PresetFile.write(file, tuning.snapshot());
            status.message("Saved preset " + file, false);
            return true;
        } catch (IOException e) {
            status.message("Cannot save preset " + file + ": " + e.getMessage(), true);
            return false;
        }
    }

    private static JFileChooser chooser() {
        JFileChooser c = new JFileChooser();
        c.setFileFilter(new FileNameExtensionFilter("tensim presets (*.json)", "json"));
        return c;
    }
}

package org.tensim.app.gui;

import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.filechooser.FileNameExtensionFilter;

/** A picture of the whole window as it is on screen (File &gt; Save screenshot..., {@code --screenshot}). */
final class WindowPicture {
    private WindowPicture() {
    }

    /** Asks where, then saves; a failure goes to the status bar. */
    static void saveDialog(JFrame frame, StatusBar status) {
        JFileChooser c = new JFileChooser();
        c.setFileFilter(new FileNameExtensionFilter("PNG images", "png"));
        if (c.showSaveDialog(frame) == JFileChooser.APPROVE_OPTION) {
            try {
                save(frame, c.getSelectedFile().toPath());
            } catch (Exception e) {
                status.message("Cannot save screenshot: " + e.getMessage(), true);
            }
        }
    }

    /** Captures the window into a PNG file (written, then renamed). */
    static void save(JFrame frame, Path file) throws Exception {
        Point p = frame.getLocationOnScreen();
        BufferedImage img = new Robot().createScreenCapture(new Rectangle(p, frame.getSize()));
        org.tensim.io.OutputFiles.writeAtomically(file, out -> {
            if (!ImageIO.write(img, "png", out)) {
                throw new IOException("no PNG writer available");
            }
        });
    }
}

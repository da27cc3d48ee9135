package org.tensim.app.gui;

import java.util.HashMap;
import java.util.Map;
import javax.swing.ButtonGroup;
import javax.swing.JMenu;
import javax.swing.JRadioButtonMenuItem;
import org.tensim.view.SceneView;

/** The View menu's frame cap: at most 15, 30, 40 (the default) or 60 frames drawn per second, or no cap. */
final class FrameCapMenu extends JMenu {
    private static final long serialVersionUID = 1L;

    private final transient SceneView view;
    private final StatusBar status;
    private final Map<Integer, JRadioButtonMenuItem> items = new HashMap<>();

    FrameCapMenu(SceneView view, StatusBar status) {
        super("View");
        this.view = view;
        this.status = status;
        ButtonGroup caps = new ButtonGroup();
        for (int fps : new int[] {15, 30, SceneView.DEFAULT_FRAME_CAP_FPS, 60, 0}) {
            JRadioButtonMenuItem i = new JRadioButtonMenuItem(fps == 0 ? "No frame cap"
                    : "At most " + fps + " frames/s", fps == view.frameCap());
            i.setName("fps." + fps);
            i.addActionListener(e -> select(fps));
            items.put(fps, i);
            caps.add(i);
            add(i);
        }
    }

    /** Draws at most fps frames per second (0: no cap) and ticks its item, if it has one. */
    void select(int fps) {
        view.setFrameCap(fps);
        if (items.containsKey(fps)) {
            items.get(fps).setSelected(true);
        }
        status.message(fps == 0 ? "Frames drawn as fast as the display allows" : "Frames drawn at most " + fps
                + " per second", false);
    }
}

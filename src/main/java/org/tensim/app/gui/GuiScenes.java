package org.tensim.app.gui;

import java.nio.file.Path;
import java.util.List;
import org.tensim.view.CubeViewScene;
import org.tensim.view.SceneFactory;

/** The scenes the GUI can show, by name. */
public final class GuiScenes {
    private GuiScenes() {
    }

    /** Names accepted by {@code --scene}, the default first. */
    public static List<String> names() {
        return List.of("cube");
    }

    /**
     * The factory of a scene.
     *
     * @param mesh a mesh file for scenes that read one, or null for the built-in mesh
     * @throws IllegalArgumentException for an unknown name, or a mesh given to a scene without one
     */
    public static SceneFactory factory(String name, Path mesh) {
        switch (name) {
            case "cube":
                if (mesh != null) {
                    throw new IllegalArgumentException("--mesh " + mesh + ": the cube scene is built in and reads no mesh;"
                            + " --mesh applies to the diaphragm");
                }
                return CubeViewScene.factory();
            default:
                throw new IllegalArgumentException("--scene '" + name + "' is not a scene; expected one of " + names());
        }
    }
}

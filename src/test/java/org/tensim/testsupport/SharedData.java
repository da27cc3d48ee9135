package org.tensim.testsupport;

import java.nio.file.Path;
import org.tensim.io.ProjectFolder;

/** The shared data beside the project ({@code ../shared}) that tests read, skipping by name where it is absent. */
public final class SharedData {
    /** The thorax of bone surfaces, a folder with its {@code parts.json}. */
    public static final Path THORAX = ProjectFolder.resolve("..", "shared", "meshes", "thorax");
    /** The BodyParts3D diaphragm registered to {@link #THORAX}, mm. */
    public static final Path BODYPARTS3D_DIAPHRAGM = ProjectFolder.resolve("..", "shared", "meshes", "bodyparts3d",
            "diaphragm-FJ3131-dec28k-mm.obj");
    /** DIR-Lab's 4D-CT lung landmarks, cases 1-5 (its ATTRIBUTION.md gives units, axes and sources). */
    public static final Path LUNG_LANDMARKS = ProjectFolder.resolve("..", "shared", "data", "4dct-lung-landmarks");

    private SharedData() {
    }
}

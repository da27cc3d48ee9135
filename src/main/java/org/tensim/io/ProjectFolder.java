package org.tensim.io;

import java.nio.file.Path;

/**
 * Where the project's own files (meshes/, and ../shared beside a checkout) are
 * found: the folder named by the system property {@code tensim.home} (the
 * {@code ./tensim} launcher sets it to the checkout), else the working folder.
 * Paths a user types are resolved against the working folder as usual; only the
 * defaults come from here.
 */
public final class ProjectFolder {
    private ProjectFolder() {
    }

    /** The project folder. */
    public static Path home() {
        String h = System.getProperty("tensim.home");
        return (h == null || h.isBlank()) ? Path.of("") : Path.of(h);
    }

    /** A path inside the project folder, e.g. {@code resolve("meshes", "x.obj")}. */
    public static Path resolve(String first, String... more) {
        return home().resolve(Path.of(first, more)).normalize();
    }
}

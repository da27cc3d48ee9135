package org.tensim.scene.file;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/** Scene files written by tests into a temporary folder. */
final class SceneFiles {
    private SceneFiles() {
    }

    /** Writes {@code text} as dir/name and loads it. */
    static Scene load(Path dir, String name, String text, String... sets) {
        return SceneLoader.load(write(dir, name, text), List.of(sets));
    }

    static Path write(Path dir, String name, String text) {
        try {
            return Files.writeString(dir.resolve(name), text);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}

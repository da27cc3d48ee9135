package org.tensim.scene.diaphragm;

import java.io.IOException;
import java.nio.file.Path;

/** The bones of a thorax folder ({@code parts.json} and its surfaces) as the scene's {@link Bones}. */
final class ThoraxBones {
    private ThoraxBones() {
    }

    static Bones load(Path dir) throws IOException {
        throw new IOException("not yet");
    }
}

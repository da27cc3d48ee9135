package org.tensim.scene.tunable;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.tensim.scene.file.SceneException;

/** The GUI refuses a file whose bodies touch each other (it would run them apart), naming the condition. */
class FileViewSceneCoupledTest {
    @Test
    void aFileWithBodiesTouchingEachOtherIsRefusedAtTheCondition() {
        String m = assertThrows(SceneException.class,
                () -> FileViewScene.factory(Path.of("docs/examples/block-on-slab.yaml"))).getMessage();
        assertTrue(m.contains("block-on-slab.yaml:") && m.contains("conditions[2]") && m.contains("tensim run"), m);
    }
}

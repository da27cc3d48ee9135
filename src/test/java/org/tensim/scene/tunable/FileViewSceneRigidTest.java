package org.tensim.scene.tunable;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The GUI's scene-file view draws a rigid body as its surface, posed at the deformable bodies' time. */
class FileViewSceneRigidTest {
    @Test
    void theRigidPlateIsDrawnWhereItsMotionPutsIt() {
        ViewScene v = FileViewScene.factory(Path.of("docs/examples/plate.yaml")).create(false, Map.of());
        List<Body> bodies = v.bodies();
        Body plate = bodies.get(bodies.size() - 1);
        assertEquals("plate (rigid box)", plate.name());
        assertEquals(12 * 3, plate.triangles().length, "a box: two triangles a face");
        double[] rest = plate.simulation().state().x.clone();
        Body block = bodies.get(0);
        for (int i = 0; i < 20; i++) {
            block.simulation().step(v.defaultTimeStep());
        }
        // 1 s into the 2 s ramp: the plate is 0.5 mm down.
        assertEquals(1.0, block.simulation().time(), 1e-9);
        double[] x = plate.simulation().state().x;
        for (int i = 0; i < x.length; i++) {
            assertEquals(rest[i] - (i % 3 == 1 ? 0.0005 : 0), x[i], 1e-12, "coordinate " + i);
        }
    }
}

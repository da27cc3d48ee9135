package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.tensim.io.BoxesJson;

/** Shared by the diaphragm tests: the BodyParts3D rib boxes (tests skip when they are absent). */
final class SceneFixture {
    static final Path BOXES = Path.of("..", "shared", "meshes", "bodyparts3d", "rib-sternum-bounds-mm.json");

    private SceneFixture() {
    }

    static Map<String, double[]> boxes() throws IOException {
        assumeTrue(Files.isRegularFile(BOXES), "rib boxes not present at " + BOXES.toAbsolutePath());
        return BoxesJson.read(BOXES, 1e-3);
    }

    /** A coarse double dome (rings per face) with the default parameters. */
    static DiaphragmScene coarse(int rings, double ribAmplitude, double musclePa) throws IOException {
        return coarse(rings, ribAmplitude, musclePa, BoundaryConditions.defaults());
    }

    /** As {@link #coarse(int, double, double)} with the given attachment and muscle-load models. */
    static DiaphragmScene coarse(int rings, double ribAmplitude, double musclePa, BoundaryConditions bc)
            throws IOException {
        return DiaphragmScene.build(
                TwoSurfaces.split(DoubleDomeGenerator.shell(DoubleDomeGenerator.Shape.adult().withRings(rings))),
                boxes(), DiaphragmParameters.defaults(), BreathingCycle.quiet(),
                new DiaphragmControls(ribAmplitude, musclePa), null, bc);
    }
}

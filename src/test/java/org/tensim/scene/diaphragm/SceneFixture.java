package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.tensim.io.BoxesJson;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * Shared by the diaphragm tests: the project's parametric rib cage (always there) and, for the tests of the
 * BodyParts3D mesh only, BodyParts3D's rib boxes beside it.
 */
final class SceneFixture {
    static final Path BODYPARTS3D_BOXES = DiaphragmSetup.BODYPARTS3D_BOXES;

    /**
     * The defaults with the pressure load ({@code --muscle-load pressure}), for the tests whose figures were
     * measured with it (it was the default load until the fibres' tension replaced it).
     */
    static final BoundaryConditions PRESSURE = BoundaryConditions.defaults()
            .withMuscleLoad(BoundaryConditions.MuscleLoad.PRESSURE);

    private SceneFixture() {
    }

    /** The default cage: the parametric one, placed on the generated dome. */
    static Map<String, double[]> boxes() {
        return ParametricRibCage.adult();
    }

    /** BodyParts3D's boxes, for the tests of the BodyParts3D mesh (they skip, naming the file, without it). */
    static Map<String, double[]> bodyPartsBoxes() throws IOException {
        assumeTrue(Files.isRegularFile(BODYPARTS3D_BOXES), "needs BodyParts3D's rib and sternum boxes at "
                + BODYPARTS3D_BOXES.toAbsolutePath());
        return BoxesJson.read(BODYPARTS3D_BOXES, 1e-3);
    }

    /** A coarse double dome (rings per face) with the default parameters and muscle load. */
    static DiaphragmScene coarse(int rings, double ribAmplitude, double musclePa) throws IOException {
        return coarse(rings, ribAmplitude, musclePa, DiaphragmParameters.defaults());
    }

    /** The same with other parameters. */
    static DiaphragmScene coarse(int rings, double ribAmplitude, double musclePa, DiaphragmParameters p)
            throws IOException {
        return coarse(rings, ribAmplitude, musclePa, p, BoundaryConditions.defaults());
    }

    /** The same with the given attachment and muscle-load models. */
    static DiaphragmScene coarse(int rings, double ribAmplitude, double musclePa, BoundaryConditions bc)
            throws IOException {
        return coarse(rings, ribAmplitude, musclePa, DiaphragmParameters.defaults(), bc);
    }

    /** The same with other parameters and the given attachment and muscle-load models. */
    static DiaphragmScene coarse(int rings, double ribAmplitude, double musclePa, DiaphragmParameters p,
            BoundaryConditions bc) throws IOException {
        return DiaphragmScene.build(
                TwoSurfaces.split(DoubleDomeGenerator.shell(DoubleDomeGenerator.Shape.adult().withRings(rings))),
                boxes(), p, BreathingCycle.quiet(), new DiaphragmControls(ribAmplitude, musclePa), null, bc);
    }
}

package org.tensim.scene.file;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.tensim.io.ProjectFolder;
import org.tensim.model.Vec3;
import org.tensim.scene.CubeParameters;

/**
 * The paper's cube comparison as the scene file {@code docs/examples/cube.yaml}, with the values of a
 * {@link CubeParameters} set over the file's ({@code --set} overrides, each number written so that it reads back
 * to the same double). {@code tensim cube} builds its two cubes this way: the file is the experiment.
 */
public final class CubeSceneFile {
    /** The scene file, in the project folder. */
    public static final Path FILE = ProjectFolder.resolve("docs", "examples", "cube.yaml");
    /** The file's names of the two cubes, and of their probes (point P). */
    public static final String MASS_SPRING = "mss";
    public static final String TENSEGRITY = "ts";

    private CubeSceneFile() {
    }

    /**
     * The file's scene with {@code p}'s values: docs/examples/cube.yaml in the project folder, or, where there is
     * none (a machine with the jar alone, such as a Spark executor), the copy the build puts in the jar.
     */
    public static Scene load(CubeParameters p) {
        if (Files.isRegularFile(FILE)) {
            return withoutParameters(FILE, SceneTree.read(FILE), FILE.toAbsolutePath().getParent(), p);
        }
        String name = "cube.yaml (built in)";
        return withoutParameters(Path.of(name), SceneTree.read(name, builtIn()), Path.of("."), p);
    }

    /**
     * The scene without the file's {@code parameters:} block: the command's values are {@link CubeParameters}',
     * validated there, and the file's named parameters (the GUI's and sweeps' controls, whose ranges are those of
     * a slider) do not bound them; {@code tensim run cube.yaml} keeps them.
     */
    private static Scene withoutParameters(Path name, SceneNode root, Path folder, CubeParameters p) {
        root.remove("parameters");
        return SceneLoader.load(name, root, folder, overrides(p));
    }

    /** The build's copy of the file. */
    public static byte[] builtIn() {
        try (InputStream in = CubeSceneFile.class.getResourceAsStream("cube.yaml")) {
            if (in == null) {
                throw new IllegalStateException("neither " + FILE + " nor the build's copy of it (a resource) is"
                        + " there: rebuild, or run from the project folder");
            }
            return in.readAllBytes();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The {@code --set} options that give the file {@code p}'s values. */
    public static List<String> overrides(CubeParameters p) {
        List<String> s = new ArrayList<>();
        for (String body : List.of(MASS_SPRING, TENSEGRITY)) {
            s.add("bodies." + body + ".side=" + p.sideM() + " m");
            s.add("bodies." + body + ".node_mass=" + p.nodeMassKg() + " kg");
            s.add("bodies." + body + ".stiffness=" + p.stiffnessNPerM() + " N/m");
            s.add("bodies." + body + ".damping=" + p.dampingNsPerM() + " N*s/m");
        }
        s.add("laws.wave.frequency=" + p.forceFrequencyHz() + " Hz");
        s.add("conditions[1].magnitude=" + p.forceAmplitudeN() + " N");
        Vec3 d = p.forceDirection();
        s.add("conditions[1].direction[0]=" + d.x());
        s.add("conditions[1].direction[1]=" + d.y());
        s.add("conditions[1].direction[2]=" + d.z());
        s.add("run.dt=" + p.dtS() + " s");
        s.add("run.duration=" + p.durationS() + " s");
        return s;
    }

    /** Point P's node in a body of the scene: its probe's node. */
    public static int probe(Scene s, String body) {
        for (SceneProbe p : s.probes()) {
            if (p.name().equals(body)) {
                return p.nodes()[0];
            }
        }
        throw new IllegalStateException(FILE + " has no probe '" + body + "' (point P of that cube)");
    }
}

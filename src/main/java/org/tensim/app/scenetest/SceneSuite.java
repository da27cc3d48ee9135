package org.tensim.app.scenetest;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicReference;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicContainer;
import org.junit.jupiter.api.DynamicNode;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.extension.ExtensionContext;
import org.junit.jupiter.api.extension.ParameterContext;
import org.junit.jupiter.api.extension.ParameterResolver;
import org.opentest4j.AssertionFailedError;
import org.opentest4j.TestAbortedException;
import org.tensim.experiment.SceneExpectations;
import org.tensim.experiment.SceneRunner;
import org.tensim.io.RunFolder;
import org.tensim.scene.file.Scene;
import org.tensim.scene.file.SceneException;
import org.tensim.scene.file.SceneExpectation;
import org.tensim.scene.file.SceneLoader;

/**
 * A folder's scene files as JUnit 5 dynamic tests ({@code tensim test-scenes}, {@link SceneTestLauncher}): one
 * container per scene file ({@link SceneFileFinder}), holding one test per check of its {@code expect:} block.
 * The file is loaded and run (as {@code tensim run} does, into {@code OUT/runs/NAME}) when its container starts;
 * each test then passes when its check holds, and fails with the measured value and the range otherwise. A file
 * that cannot be loaded is one failed test, "load", with the loader's message, except one that names a file or
 * folder that does not exist (data not on this machine, as the shared meshes): its "load" is skipped (aborted),
 * naming the file, and counted apart from the failures; a run that fails or diverges adds
 * a failed test "run"; a scene without an expect block is one test, "load", that passes when the file loads, and so
 * is a diaphragm's ({@code standalone} body type: its run is its own experiment, minutes long, whose checks
 * {@code tensim run FILE} evaluates).
 * The folders come as configuration parameters of the launch ({@link #DIR}, {@link #OUT}, {@link #OVERWRITE}).
 */
@ExtendWith(SceneSuite.Settings.Resolver.class)
public class SceneSuite {
    /** The folder searched for scene files. */
    public static final String DIR = "tensim.test-scenes.dir";
    /** The folder the runs are written under ({@code runs/NAME}). */
    public static final String OUT = "tensim.test-scenes.out";
    /** "true": run folders holding other results are used all the same ({@code --overwrite}). */
    public static final String OVERWRITE = "tensim.test-scenes.overwrite";

    /** The launch's folders. */
    public record Settings(Path dir, Path out, boolean overwrite) {
        /** Gives the test factory the launch's settings. */
        public static final class Resolver implements ParameterResolver {
            @Override
            public boolean supportsParameter(ParameterContext p, ExtensionContext c) {
                return p.getParameter().getType() == Settings.class;
            }

            @Override
            public Object resolveParameter(ParameterContext p, ExtensionContext c) {
                Path dir = Path.of(c.getConfigurationParameter(DIR).orElseThrow(
                        () -> new IllegalStateException("the launch gives no " + DIR)));
                Path out = Path.of(c.getConfigurationParameter(OUT).orElse("out/test-scenes"));
                return new Settings(dir, out, c.getConfigurationParameter(OVERWRITE).orElse("false").equals("true"));
            }
        }
    }

    @TestFactory
    Stream<DynamicNode> scenes(Settings settings) throws IOException {
        List<DynamicNode> files = new ArrayList<>();
        for (SceneFileFinder.Found f : SceneFileFinder.find(settings.dir())) {
            Path runDir = settings.out().resolve("runs").resolve(f.runName());
            // A stream read when the container runs: the scene is loaded and run then, not at discovery.
            Stream<DynamicNode> tests = Stream.of(f).flatMap(x -> tests(x, runDir, settings.overwrite()).stream());
            files.add(DynamicContainer.dynamicContainer(f.relative(), f.file().toUri(), tests));
        }
        return files.stream();
    }

    private static List<DynamicNode> tests(SceneFileFinder.Found f, Path runDir, boolean overwrite) {
        Scene scene;
        try {
            scene = SceneLoader.load(f.file());
        } catch (SceneException e) {
            if (e.absentPath().isPresent()) {
                String why = "skipped: reads " + e.absentPath().get().normalize() + ", which is absent ("
                        + e.getMessage() + ")";
                return List.of(DynamicTest.dynamicTest("load", () -> {
                    throw new TestAbortedException(why);
                }));
            }
            return List.of(failing("load", describe(e)));
        } catch (RuntimeException e) {
            return List.of(failing("load", describe(e)));
        }
        if (scene.expect().isEmpty()) {
            return List.of(DynamicTest.dynamicTest("load (no expect block: nothing run)", () -> { }));
        }
        for (org.tensim.scene.file.SceneBody b : scene.bodies().values()) {
            if (org.tensim.scene.file.BodyTypes.get(b.type()).standalone()) {
                // A diaphragm's run is its own experiment (minutes for the default mesh), not SceneRunner's.
                return List.of(DynamicTest.dynamicTest("load (a " + b.type() + " scene: its expect block is checked"
                        + " by tensim run " + f.relative() + ", not run here)", () -> { }));
            }
        }
        List<DynamicNode> out = new ArrayList<>();
        AtomicReference<Map<String, Object>> written = new AtomicReference<>();
        try {
            RunFolder.run(runDir, "run", List.of(scene.run().csv()), overwrite,
                    folder -> written.set(SceneRunner.run(scene, scene.run(), folder)));
        } catch (Exception e) {
            return List.of(failing("run", "the run into " + runDir + " failed: " + describe(e)));
        }
        Map<String, Object> summary = written.get();
        if (summary.containsKey("diverged")) {
            out.add(failing("run", "the run diverged (" + summary.get("diverged") + "); its outputs are in "
                    + runDir));
        }
        @SuppressWarnings("unchecked")
        List<Map<String, Object>> outcomes = (List<Map<String, Object>>) summary.get("expectations");
        for (int i = 0; i < scene.expect().size(); i++) {
            SceneExpectation e = scene.expect().get(i);
            Map<String, Object> o = outcomes.get(i);
            String line = SceneExpectations.line(e, o) + " (run in " + runDir + ")";
            boolean pass = Boolean.TRUE.equals(o.get("pass"));
            out.add(DynamicTest.dynamicTest(e.label() + " " + e.range(), () -> {
                if (!pass) {
                    throw new AssertionFailedError(line);
                }
            }));
        }
        return out;
    }

    /** The program's own refusals by their message; anything else with its type, so that it can be reported. */
    private static String describe(Exception e) {
        String msg = e.getMessage() == null ? "" : e.getMessage();
        return e instanceof IllegalArgumentException || !(e instanceof RuntimeException) ? msg
                : "internal error (" + e.getClass().getName() + ": " + msg + ")";
    }

    private static DynamicTest failing(String name, String message) {
        return DynamicTest.dynamicTest(name, () -> {
            throw new AssertionFailedError(message);
        });
    }
}

package org.tensim.tuning;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.tensim.scene.tunable.FileViewScene;
import org.tensim.scene.tunable.SceneFactory;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * The scene-file part of {@code tensim gui}: {@code tensim gui FILE [--set NAME=VALUE ...]} opens a scene file
 * (docs/scenes.md) with its own integrator and step, its named parameters as the controls
 * ({@link FileViewScene}; a diaphragm file opens the diaphragm's view with its own controls). Nothing last-used is
 * restored over the file's values, nor saved.
 */
public final class SceneFileGui {
    /** The built-in scenes' options, which a scene file leaves out. */
    public static final List<String> BUILT_IN = List.of("--scene", "--mesh", "--pick", "--preset", "--thorax",
            "--muscle-load");

    @Parameters(index = "0", arity = "0..1", paramLabel = "FILE",
            description = "A scene file (docs/scenes.md) to open instead of a built-in scene; it runs with its own"
                    + " integrator and step, and its named parameters are the controls (a diaphragm file has the"
                    + " diaphragm's own; bodies touching each other run in one simulation, as in tensim run).")
    Path file;

    @Option(names = "--set", paramLabel = "KEY.PATH=VALUE",
            description = "With a scene file: replaces one of its values, or sets one of its named parameters, for"
                    + " example --set E=8kPa, before the window opens (repeatable).")
    List<String> sets = new ArrayList<>();

    /** Whether a scene file was given. */
    public boolean given() {
        return file != null;
    }

    /**
     * The factory of the scene file, loaded (and so checked) before any window; refuses the built-in scenes'
     * options beside it, and --set without it.
     */
    public SceneFactory factory(CommandSpec spec) {
        for (String o : BUILT_IN) {
            if (spec.commandLine().getParseResult().hasMatchedOption(o)) {
                throw new IllegalArgumentException(o + " chooses a built-in scene: leave it out with a scene file ("
                        + file + ")");
            }
        }
        return FileViewScene.factory(file, sets);
    }

    /** Refuses --set without a scene file. */
    public void refuseSetsWithoutFile() {
        if (file == null && !sets.isEmpty()) {
            throw new IllegalArgumentException("--set " + sets.get(0) + " sets a value of a scene file: give the"
                    + " file first (tensim gui FILE --set ...)");
        }
    }
}

package org.tensim.app;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.tensim.scene.file.Scene;
import org.tensim.scene.file.SceneCheck;
import org.tensim.scene.file.SceneLoader;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code tensim check FILE}: reads a scene file and reports what it builds, without running it. */
@Command(name = "check", mixinStandardHelpOptions = true,
        description = {"Validates a scene file (docs/scenes.md) without running it.",
            "It prints each body's node count and each region's resolved node count and bounding box. A refusal names"
                + " file:line:column and the key path, and exits with code 2."})
public final class CheckCommand implements Callable<Integer> {
    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Parameters(index = "0", paramLabel = "FILE", description = "The scene file (.yaml, .yml or .json).")
    Path file;

    @Option(names = "--set", paramLabel = "KEY.PATH=VALUE",
            description = "Replaces one value of the file, for example --set bodies.mss.stiffness=\"200 N/m\", or"
                    + " sets one of its named parameters, for example --set E=8kPa (a bare number is in the"
                    + " parameter's unit, and the value must lie in its range); repeatable.")
    List<String> sets = new ArrayList<>();

    @Override
    public Integer call() {
        Scene s = SceneLoader.load(file, sets);
        java.io.PrintWriter out = spec.commandLine().getOut();
        for (String line : SceneCheck.report(s)) {
            out.println(line);
        }
        out.println("ok");
        out.flush();
        return 0;
    }
}

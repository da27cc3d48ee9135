package org.tensim.app;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.tensim.app.scenetest.SceneFileFinder;
import org.tensim.app.scenetest.SceneTestLauncher;
import org.tensim.cli.OptionChecks;
import org.tensim.cli.OutFolderOption;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code tensim test-scenes DIR}: a folder's scene files as a regression suite (JUnit 5, JUnit XML reports). */
@Command(name = "test-scenes", mixinStandardHelpOptions = true,
        description = {"Runs every scene file under DIR (docs/scenes.md) and checks what its expect block states, as"
            + " JUnit 5 tests: one test per check, grouped by file.",
            "Scene files are the .yaml, .yml and .json files whose top level has bodies: or version: (sweep and"
                + " calibration specs, which name a scene:, are left out), searched recursively. Each is run as"
                + " tensim run runs it, into --out/runs/NAME. A file that does not load is a failed test named load,"
                + " with the loader's message; a scene without an expect block is a test that it loads.",
            "It prints each test's verdict, writes the JUnit XML report (TEST-junit-jupiter.xml) to --reports, and"
                + " ends with the line \"N passed, N failed\". The exit code is 0 when every test passed, 1 when one"
                + " failed, and 2 when DIR is not a folder or holds no scene file."})
public final class TestScenesCommand implements Callable<Integer> {
    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Parameters(index = "0", paramLabel = "DIR", description = "The folder of scene files (searched recursively).")
    Path dir;

    @picocli.CommandLine.Mixin
    OutFolderOption out = new OutFolderOption(Path.of("out", "test-scenes"));

    @Option(names = "--reports", paramLabel = "DIR",
            description = "Folder of the JUnit XML report (default: the reports folder inside --out).")
    Path reports;

    @Override
    public Integer call() throws Exception {
        if (!Files.isDirectory(dir)) {
            throw OptionChecks.usage(spec, "DIR " + dir + ": " + (Files.exists(dir) ? "is not a folder"
                    : "no such folder") + " (expected a folder of scene files)");
        }
        if (SceneFileFinder.find(dir).isEmpty()) {
            throw OptionChecks.usage(spec, "DIR " + dir + ": holds no scene file (.yaml, .yml or .json with"
                    + " bodies: or version: at its top level)");
        }
        Path outDir = out.folder(spec);
        Path reportDir = reports != null ? reports : outDir.resolve("reports");
        PrintWriter print = spec.commandLine().getOut();
        SceneTestLauncher.Result r = SceneTestLauncher.run(dir, outDir, reportDir, out.overwrite(), print);
        print.println("JUnit XML report in " + reportDir);
        print.println(r.line());
        print.flush();
        return r.failed() == 0 ? 0 : 1;
    }
}

package org.tensim.app;

import org.tensim.app.gui.GuiCommand;
import org.tensim.bench.BenchCommand;
import java.io.IOException;
import java.nio.file.FileSystemException;
import org.tensim.io.OutputFiles;
import org.tensim.io.RunFolder;
import org.tensim.io.RunSignals;
import org.tensim.io.RunStatus;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The {@code tensim} command line. Each subcommand is its own class; errors are
 * printed as one clear message (no stack trace) with a non-zero exit code.
 */
@Command(name = "tensim", mixinStandardHelpOptions = true, version = "tensim 0.1.0",
        description = {"Soft-organ deformation with mass-springs and tensegrity (Villard, Bourne and Bello, ISBMS"
            + " 2008)."},
        footer = {"", "The launcher also runs the test suite: ./tensim test (its last line is \"N passed, N failed,"
            + " N skipped\"; ./tensim test --help)."},
        subcommands = {CubeCommand.class, BenchCommand.class, AccuracyCommand.class, StabilityCommand.class,
            DiaphragmCommand.class, DiaphragmMeshCommand.class, GuiCommand.class, SweepCommand.class,
            CalibrateCommand.class, VolumeStudyCommand.class, CheckCommand.class, RunCommand.class,
            TestScenesCommand.class, LungLandmarksCommand.class, Validate4dctCommand.class})
public final class Main implements Runnable {
    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public void run() {
        spec.commandLine().usage(System.out);
    }

    /** Builds the configured command line (shared with tests). */
    public static CommandLine commandLine() {
        CommandLine cl = new CommandLine(new Main());
        // Every number option is a measured quantity, a factor or a count: NaN and infinities
        // (also from "1e400") are refused where they enter, with the option's name.
        cl.registerConverter(Double.class, org.tensim.cli.OptionChecks::finite);
        cl.registerConverter(double.class, org.tensim.cli.OptionChecks::finite);
        long[] foldersBefore = {0};
        cl.setExecutionStrategy(parsed -> {
            foldersBefore[0] = RunFolder.opened();
            return new CommandLine.RunLast().execute(parsed);
        });
        cl.setExecutionExceptionHandler((ex, cmd, parsed) -> {
            if (RunSignals.stopRequested()) {
                return RunStatus.INTERRUPTED.exitCode(); // the run's folder says so; no second message
            }
            cmd.getErr().println("tensim " + cmd.getCommandName() + ": " + describe(ex));
            // A value refused before any output folder was opened is a usage error, like picocli's own.
            boolean usage = ex instanceof IllegalArgumentException && RunFolder.opened() == foldersBefore[0];
            return usage ? RunStatus.USAGE_EXIT : RunStatus.FAILED.exitCode();
        });
        return org.tensim.cli.HelpLayout.install(cl);
    }

    /**
     * One line for an error: a file-system error says what failed on which path; an
     * error that is not one of the program's own refusals is called internal, with its
     * type, so that it can be reported (never a stack trace).
     */
    static String describe(Throwable ex) {
        String msg = ex.getMessage();
        if (ex instanceof FileSystemException f && (msg == null || !msg.startsWith("cannot "))) {
            return "cannot use " + f.getFile() + (f.getOtherFile() != null ? " or " + f.getOtherFile() : "") + ": "
                    + OutputFiles.reason(f);
        }
        if (ex instanceof IOException e && e.getCause() == null && msg != null && !msg.contains(" ")) {
            return "cannot use " + msg + ": " + OutputFiles.reason(e); // a bare path
        }
        // Checked exceptions and the argument/state refusals are the program's own messages.
        boolean own = !(ex instanceof RuntimeException || ex instanceof Error) || ex instanceof IllegalArgumentException
                || ex instanceof IllegalStateException || ex instanceof java.io.UncheckedIOException;
        if (msg == null || msg.isBlank()) {
            msg = ex.getClass().getSimpleName();
        }
        return own ? msg : "internal error (" + ex.getClass().getName() + ": " + msg
                + "); please report it with the command line that caused it";
    }

    public static void main(String[] args) {
        RunSignals.mainProcess();
        int code = commandLine().execute(args);
        RunSignals.exiting();
        System.exit(code);
    }
}

package org.tensim.app;

import org.tensim.app.gui.GuiCommand;
import org.tensim.bench.BenchCommand;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The {@code tensim} command line. Each subcommand is its own class; errors are
 * printed as one clear message (no stack trace) with a non-zero exit code.
 */
@Command(name = "tensim", mixinStandardHelpOptions = true, version = "tensim 0.1.0",
        description = {"Soft-organ deformation with mass-springs and tensegrity",
            "(Villard, Bourne, Bello, ISBMS 2008).", "",
            "The launcher also has: ./tensim test (the whole test suite)."},
        subcommands = {CubeCommand.class, BenchCommand.class, AccuracyCommand.class, StabilityCommand.class,
            DiaphragmCommand.class, DiaphragmMeshCommand.class, GuiCommand.class, SweepCommand.class,
            CalibrateCommand.class})
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
        cl.setExecutionExceptionHandler((ex, cmd, parsed) -> {
            cmd.getErr().println("tensim " + cmd.getCommandName() + ": " + describe(ex));
            return 1;
        });
        return cl;
    }

    static String describe(Throwable ex) {
        String msg = ex.getMessage();
        if (msg == null || msg.isBlank()) {
            msg = ex.getClass().getSimpleName();
        }
        return msg;
    }

    public static void main(String[] args) {
        System.exit(commandLine().execute(args));
    }
}

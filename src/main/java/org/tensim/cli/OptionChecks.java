package org.tensim.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import org.tensim.solver.parallel.Parallelism;
import picocli.CommandLine;
import picocli.CommandLine.Model.CommandSpec;

/**
 * Checks of the shared options, made where the option enters: a refused value is a usage error (exit code 2)
 * naming the option, the value and what was expected.
 */
public final class OptionChecks {
    /** Threads beyond this many per core only wait for one another (the workers spin). */
    public static final int THREADS_PER_CORE = 4;

    private OptionChecks() {
    }

    /**
     * Reads a number given on the command line: a finite double, else a conversion error naming the text (picocli
     * reports it with the option).
     */
    public static double finite(String text) {
        double v;
        try {
            v = Double.parseDouble(text.trim());
        } catch (NumberFormatException e) {
            throw new CommandLine.TypeConversionException("'" + text + "' is not a number");
        }
        if (!Double.isFinite(v)) {
            throw new CommandLine.TypeConversionException("'" + text + "' is not a finite number");
        }
        return v;
    }

    /** {@code --out}: a non-empty path that is not an existing file. */
    public static Path outFolder(CommandSpec spec, Path out) {
        if (out == null || out.toString().isBlank()) {
            throw usage(spec, "--out must name a folder, got an empty path (give e.g. --out out/run1)");
        }
        if (Files.exists(out) && !Files.isDirectory(out)) {
            throw usage(spec, "--out " + out + ": exists and is a file, not a folder");
        }
        return out;
    }

    /** A thread count: 1 to {@value #THREADS_PER_CORE} x the cores (0 too when {@code zeroIsAuto}). */
    public static int threads(CommandSpec spec, String option, int n, boolean zeroIsAuto) {
        int max = THREADS_PER_CORE * Parallelism.availableCores();
        if (n < (zeroIsAuto ? 0 : 1) || n > max) {
            throw usage(spec, option + " " + n + ": expected " + (zeroIsAuto ? "0 (automatic) or " : "")
                    + "1 to " + max + " (" + THREADS_PER_CORE + " x the " + Parallelism.availableCores()
                    + " cores here; more threads than that only wait for one another)");
        }
        return n;
    }

    /**
     * A time step that fits the run: finite, > 0 and at most the simulated time, so that
     * the run makes at least one step.
     */
    public static void stepFits(CommandSpec spec, String dtOption, double dt, String durationOption,
            double duration) {
        if (!(dt > 0) || !Double.isFinite(dt)) {
            throw usage(spec, dtOption + " " + dt + ": the time step must be a finite number > 0 s");
        }
        if (dt > duration || Math.round(duration / dt) < 1) {
            throw usage(spec, dtOption + " " + dt + " s is longer than the run (" + durationOption + " " + duration
                    + " s): it would make no step; give a time step <= " + duration + " s");
        }
    }

    /** A usage error of the command: picocli prints it with the command's usage hint, exit code 2. */
    public static CommandLine.ParameterException usage(CommandSpec spec, String message) {
        return new CommandLine.ParameterException(spec.commandLine(), message);
    }
}

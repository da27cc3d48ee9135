package org.tensim.cli;

import picocli.CommandLine;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;

/**
 * {@code --dt S}, the time step in seconds (a picocli mixin). A command either has a fixed default step, which
 * must stay > 0, or lets the scene choose its step when none is given (or 0 is), saying how in the help.
 */
public final class TimeStepOption {
    /**
     * A step in seconds, 0 for the one the scene chooses; {@code shown} is the help's wording of a default the
     * scene chooses (null for a number).
     */
    public record Step(double seconds, String shown) {
        @Override
        public String toString() {
            return shown != null ? shown : Double.toString(seconds);
        }
    }

    /** Reads a step: a finite number (its range is checked with the other options). */
    static final class Parser implements CommandLine.ITypeConverter<Step> {
        @Override
        public Step convert(String text) {
            return new Step(OptionChecks.finite(text), null);
        }
    }

    @Option(names = "--dt", paramLabel = "S", converter = Parser.class,
            description = "Time step, s (default: ${DEFAULT-VALUE}).")
    Step dt;

    private final boolean sceneChooses;

    private TimeStepOption(Step defaultStep, boolean sceneChooses) {
        this.dt = defaultStep;
        this.sceneChooses = sceneChooses;
    }

    /** The option with a fixed default step, s (> 0); the step given must be > 0 too. */
    public static TimeStepOption fixed(double defaultS) {
        return new TimeStepOption(new Step(defaultS, null), false);
    }

    /**
     * The option whose default (also {@code --dt 0}) is the step the scene chooses, worded {@code shown} in the
     * help.
     */
    public static TimeStepOption chosenByScene(String shown) {
        return new TimeStepOption(new Step(0, shown), true);
    }

    /** Whether {@code --dt} was given on the command line of {@code spec}. */
    public boolean given(CommandSpec spec) {
        return spec.commandLine().getParseResult() != null
                && spec.commandLine().getParseResult().hasMatchedOption("--dt");
    }

    /** Takes {@code seconds} (> 0) in place of the default when {@code --dt} was not given. */
    public void defaultTo(CommandSpec spec, double seconds) {
        if (!given(spec)) {
            dt = new Step(seconds, null);
        }
    }

    /**
     * The step, s: > 0, or 0 where the scene chooses its own step (the default of {@link #chosenByScene});
     * anything else is a usage error naming the value.
     */
    public double seconds(CommandSpec spec) {
        double s = dt.seconds();
        if (s < 0 || (s == 0 && !sceneChooses)) {
            throw OptionChecks.usage(spec, "--dt " + s + ": the time step must be a finite number > 0 s"
                    + (sceneChooses ? " (or 0 for the scene's own step)" : ""));
        }
        return s;
    }
}

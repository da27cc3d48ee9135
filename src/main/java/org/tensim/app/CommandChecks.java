package org.tensim.app;

import java.nio.file.Path;
import org.tensim.cli.OptionChecks;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.tuning.DiaphragmOptions;
import picocli.CommandLine;
import picocli.CommandLine.Model.CommandSpec;

/**
 * Checks of options shared by several commands, made where the option enters: a
 * refused value is a usage error (exit code 2) naming the option, the value and
 * what was expected.
 */
final class CommandChecks {
    private CommandChecks() {
    }

    /** A finite number > 0. */
    static double positive(CommandSpec spec, String option, double v, String unit) {
        if (!(v > 0) || !Double.isFinite(v)) {
            throw usage(spec, option + " " + v + ": expected a finite number > 0 " + unit);
        }
        return v;
    }

    static CommandLine.ParameterException usage(CommandSpec spec, String message) {
        return OptionChecks.usage(spec, message);
    }

    /** The diaphragm scene the options describe ({@link DiaphragmOptions#spec}); a bad option is a usage error. */
    static DiaphragmSpec scene(CommandSpec spec, DiaphragmOptions options, Path defaultMesh, int defaultRings) {
        try {
            return options.spec(defaultMesh, defaultRings);
        } catch (IllegalArgumentException e) {
            throw new CommandLine.ParameterException(spec.commandLine(), e.getMessage());
        }
    }
}

package org.tensim.cli;

import org.tensim.solver.Integrator;
import org.tensim.solver.integrators.Integrators;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;

/** {@code --integrator NAME}, a setup of the integrator catalogue (a picocli mixin). */
public final class IntegratorOption {
    @Option(names = "--integrator", paramLabel = "NAME", completionCandidates = Integrators.Names.class,
            description = "Integrator: ${COMPLETION-CANDIDATES}; rk2 is the paper's (default: ${DEFAULT-VALUE}).")
    String integrator = Integrators.DEFAULT;

    /** The name given (or the default), as given. */
    public String name() {
        return integrator;
    }

    /** Whether {@code --integrator} was given on the command line of {@code spec}. */
    public boolean given(CommandSpec spec) {
        return spec.commandLine().getParseResult() != null
                && spec.commandLine().getParseResult().hasMatchedOption("--integrator");
    }

    /** Takes {@code name} in place of the default when {@code --integrator} was not given (a scene's own default). */
    public void defaultTo(CommandSpec spec, String name) {
        if (!given(spec)) {
            integrator = name;
        }
    }

    /** A new integrator of the name; an unknown name is a usage error listing the known ones. */
    public Integrator create(CommandSpec spec) {
        try {
            return Integrators.create(integrator);
        } catch (IllegalArgumentException e) {
            throw OptionChecks.usage(spec, e.getMessage());
        }
    }
}

package org.tensim.cli;

import org.tensim.solver.parallel.Parallelism;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;

/** {@code --threads N}, the threads that share each step, 0 for automatic (a picocli mixin). */
public final class ThreadsOption {
    @Option(names = "--threads", paramLabel = "N",
            description = "Threads that share each step; 0 = automatic: all cores from "
                    + Parallelism.AUTO_PARALLEL_SPRINGS + " springs, else 1 (default: ${DEFAULT-VALUE}).")
    int threads = 0;

    /** The count asked for, 0 for automatic; refused (a usage error) beyond the machine's sensible range. */
    public int threads(CommandSpec spec) {
        return OptionChecks.threads(spec, "--threads", threads, true);
    }
}

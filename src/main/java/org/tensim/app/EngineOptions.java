package org.tensim.app;

import org.tensim.sweep.Engines;
import org.tensim.sweep.SweepEngine;
import picocli.CommandLine.Option;

/** The engine options shared by {@code sweep} and {@code calibrate} (a picocli mixin). */
public final class EngineOptions {
    @Option(names = "--engine", paramLabel = "local|spark",
            description = "The engine: local (all cores, one run per core; the default) or spark (Spark tasks,"
                    + " docs/scaling.md).")
    String engine = "local";

    @Option(names = "--master", paramLabel = "URL",
            description = "Spark only: the Spark master, e.g. local[2] or spark://host:7077 (default: local[*]).")
    String master;

    @Option(names = "--workers", paramLabel = "N",
            description = "Local engine: runs at once (default: 0, one per core).")
    int workers = 0;

    /** The engine asked for; bad options are reported as usage errors of {@code cmd}. */
    SweepEngine create(picocli.CommandLine cmd) {
        if (workers < 0) {
            throw new picocli.CommandLine.ParameterException(cmd, "--workers must be 0 (one per core) or more, got "
                    + workers);
        }
        try {
            return Engines.create(engine, master, workers);
        } catch (IllegalArgumentException e) {
            throw new picocli.CommandLine.ParameterException(cmd, e.getMessage());
        }
    }
}

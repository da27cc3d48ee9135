package org.tensim.sweep;

import org.tensim.solver.parallel.Parallelism;

/**
 * Makes the engine a command asks for. The Spark engine lives in its own source set and
 * installation (build/install/tensim-spark), so that Spark is neither downloaded for the
 * tests nor loaded by the other commands; it is found here by name, at run time.
 */
public final class Engines {
    /** Class of the Spark engine (src/spark/java), with a constructor taking the master URL. */
    public static final String SPARK_ENGINE = "org.tensim.spark.SparkEngine";

    private Engines() {
    }

    /**
     * @param name    {@code local} or {@code spark}
     * @param master  Spark master URL (spark only; null: {@code local[*]})
     * @param workers points at once on the local engine (0: one per core)
     */
    public static SweepEngine create(String name, String master, int workers) {
        switch (name) {
            case "local":
                if (master != null) {
                    throw new IllegalArgumentException("--master " + master + " applies to --engine spark only");
                }
                return new LocalEngine(workers > 0 ? workers : Parallelism.availableCores());
            case "spark":
                try {
                    Class<?> c = Class.forName(SPARK_ENGINE);
                    return (SweepEngine) c.getConstructor(String.class).newInstance(master == null ? "local[*]"
                            : master);
                } catch (ClassNotFoundException | NoClassDefFoundError e) {
                    throw new IllegalArgumentException("--engine spark: the Spark engine is not on the class path;"
                            + " run through ./tensim, which installs it (gradle installSpark), or see docs/scaling.md");
                } catch (ReflectiveOperationException e) {
                    Throwable cause = e.getCause() == null ? e : e.getCause();
                    throw new IllegalStateException("--engine spark: could not start Spark: " + cause, cause);
                }
            default:
                throw new IllegalArgumentException("--engine '" + name + "' is not an engine; expected local or spark");
        }
    }
}

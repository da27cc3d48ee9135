package org.tensim;

import java.util.SplittableRandom;

/**
 * Property-based testing with plain JUnit 5: a property is checked on many random
 * cases, each drawn from its own seed, so that a failure names the seed and the case
 * can be replayed alone ({@code RandomCases.replay}). The base seed is fixed, so that
 * every run checks the same cases (the suite stays deterministic); set the system
 * property {@code tensim.seed} to explore other cases.
 */
public final class RandomCases {
    /** Base seed of the cases (override with -Dtensim.seed=N). */
    public static final long SEED = Long.getLong("tensim.seed", 20261123L);

    private RandomCases() {
    }

    /** One random case: draws values from its own generator. */
    @FunctionalInterface
    public interface Case {
        void check(SplittableRandom random) throws Exception;
    }

    /** Checks {@code property} on {@code count} cases; a failure is rethrown naming the case's seed. */
    public static void check(String property, int count, Case c) throws Exception {
        SplittableRandom base = new SplittableRandom(SEED ^ property.hashCode());
        for (int i = 0; i < count; i++) {
            long seed = base.nextLong();
            replay(property, seed, c);
        }
    }

    /** Checks one case from its seed. */
    public static void replay(String property, long seed, Case c) throws Exception {
        try {
            c.check(new SplittableRandom(seed));
        } catch (Exception | AssertionError e) {
            throw new AssertionError(property + ": case with seed " + seed + " failed: " + e.getMessage(), e);
        }
    }

    /** One of the values, chosen at random. */
    @SafeVarargs
    public static <T> T oneOf(SplittableRandom r, T... values) {
        return values[r.nextInt(values.length)];
    }
}

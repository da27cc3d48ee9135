package org.tensim.bench;

import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.tensim.io.Json;
import org.tensim.solver.MidpointRK2;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code tensim bench}: figures of the force pass and of whole steps on the lattice. */
@Command(name = "bench", mixinStandardHelpOptions = true,
        description = {"Benchmark on the lattice cube of n x n x n nodes (axis and face-diagonal springs,",
            "bottom fixed, gravity). Prints one JSON line per case. Figures only: nothing is asserted."})
public final class BenchCommand implements Callable<Integer> {
    @Option(names = "--n", split = ",", paramLabel = "N[,N...]",
            description = "lattice sizes, nodes per side (default: ${DEFAULT-VALUE})")
    List<Integer> sizes = List.of(11, 21, 31);

    @Option(names = "--threads", split = ",", paramLabel = "T[,T...]",
            description = "thread counts (default: ${DEFAULT-VALUE}; the step is single-threaded for now)")
    List<Integer> threads = List.of(1);

    @Option(names = "--dt", paramLabel = "S", description = "time step, s (default: ${DEFAULT-VALUE})")
    double dt = 1e-3;

    @Option(names = "--steps", paramLabel = "K", description = "timed steps per repetition (default: ${DEFAULT-VALUE})")
    int steps = 100;

    @Option(names = "--repeats", paramLabel = "R", description = "repetitions; best and median reported (default: ${DEFAULT-VALUE})")
    int repeats = 5;

    @Option(names = "--links", description = "add a rigid link along a body diagonal of every cell (default: off)")
    boolean links;

    @Override
    public Integer call() {
        for (int t : threads) {
            if (t != 1) {
                throw new IllegalArgumentException("--threads " + t + ": only 1 thread is implemented so far");
            }
        }
        for (int n : sizes) {
            if (n < 2) {
                throw new IllegalArgumentException("--n " + n + ": a lattice needs at least 2 nodes per side");
            }
        }
        if (steps < 1 || repeats < 1) {
            throw new IllegalArgumentException("--steps and --repeats must be >= 1, got " + steps + " and " + repeats);
        }
        for (int n : sizes) {
            Map<String, Object> r = LatticeBenchmark.run(n, links, new MidpointRK2(), dt, steps, repeats);
            System.out.println(Json.line(r));
        }
        return 0;
    }
}

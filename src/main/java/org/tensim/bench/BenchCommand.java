package org.tensim.bench;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.tensim.cli.IntegratorOption;
import org.tensim.cli.OptionChecks;
import org.tensim.cli.TimeStepOption;
import org.tensim.io.Json;
import org.tensim.io.OutputFiles;
import org.tensim.io.RunFolder;
import org.tensim.io.RunStatus;
import org.tensim.solver.integrators.Integrators;
import org.tensim.solver.parallel.ParallelSpringPass;
import org.tensim.solver.parallel.Parallelism;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code tensim bench}: figures of the force pass and of whole steps, per scene, size and thread count. */
@Command(name = "bench", mixinStandardHelpOptions = true,
        description = {"Measures the force pass and whole steps per scene, size and thread count.",
            "The lattice scene is a cube of n x n x n nodes (axis and face-diagonal springs, bottom fixed, gravity)."
                + " Prints one JSON line per case (size x threads) and writes bench.jsonl, and scaling.png for two"
                + " sizes or more, to --out. Figures only: nothing is asserted. See docs/performance.md."})
public final class BenchCommand implements Callable<Integer> {
    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Option(names = "--scene", paramLabel = "NAME",
            description = "Scene: lattice or diaphragm (default: ${DEFAULT-VALUE}).")
    String scene = "lattice";

    @Option(names = {"--size", "--n"}, split = ",", paramLabel = "N[,N...]", hideParamSyntax = true,
            description = "Lattice sizes, nodes per side (default: ${DEFAULT-VALUE}).")
    List<Integer> sizes = List.of(11, 21, 31);

    @Option(names = "--threads", split = ",", paramLabel = "T[,T...]", hideParamSyntax = true,
            description = "Thread counts (default: all cores, here ${DEFAULT-VALUE}).")
    List<Integer> threads = List.of(Parallelism.availableCores());

    @picocli.CommandLine.Mixin
    IntegratorOption integrator = new IntegratorOption();

    @Option(names = "--links", description = "Add a rigid link along a body diagonal of every cell (default: off).")
    boolean links;

    @Option(names = "--order", paramLabel = "ORDER",
            description = "Internal node order: auto, authored or rcm (default: ${DEFAULT-VALUE}).")
    String order = "auto";

    @Option(names = "--solver", paramLabel = "NAME",
            description = "The solver: parallel (the multi-threaded step) or builtin (the single-threaded loops, for "
                + "before/after figures; --threads and --order are then ignored) (default: ${DEFAULT-VALUE}).")
    String solver = "parallel";

    @Option(names = "--shuffle", description = "Number the scene's nodes, springs and links randomly first "
            + "(an arbitrarily numbered mesh; default: off).")
    boolean shuffle;

    @picocli.CommandLine.Mixin
    TimeStepOption dt = TimeStepOption.chosenByScene("0.001 for the lattice, the step recommended for the integrator"
            + " on the diaphragm");

    @Option(names = "--steps", paramLabel = "K",
            description = "Timed steps per repetition; 0 lets the command choose: as many as make about 2e7 spring"
                    + " evaluations (10 to 5000), or 20 per round with --compare (default: ${DEFAULT-VALUE}).")
    int steps = 0;

    @Option(names = "--repeats", paramLabel = "R",
            description = "Repetitions; best and median reported (default: ${DEFAULT-VALUE}).")
    int repeats = 5;

    @picocli.CommandLine.Mixin
    org.tensim.cli.OutFolderOption out = new org.tensim.cli.OutFolderOption(Path.of("out", "bench"));

    @Option(names = "--compare", split = ",", paramLabel = "A,B", hideParamSyntax = true,
            description = {"With --scene diaphragm: two integrators of the catalogue (e.g. bdf2,bdf2-newton2), each on "
                + "its own copy of the scene, timed in --repeats alternating rounds of --steps steps (20 when --steps "
                + "is 0, its default) after as many warm-up steps, on the first --threads count; one JSON line per "
                + "round (step and solve ms of each, their ratio A/B, time and load), then the median ratios and how "
                + "far apart the two ended; a name may end in ':serial' or ':shared' (bdf2 with its solves and "
                + "products' fibres and shear elements on the calling thread, or always shared among the threads; by "
                + "default shared while measured faster) and in '@T' (its own thread count, e.g. bdf2@1,bdf2@2)."})
    List<String> compare;

    @Override
    public Integer call() throws Exception {
        if (!"lattice".equals(scene) && !"diaphragm".equals(scene)) {
            throw new IllegalArgumentException("--scene " + scene + ": expected lattice or diaphragm");
        }
        for (int t : threads) {
            OptionChecks.threads(spec, "--threads", t, false);
        }
        Path folder = out.folder(spec);
        for (int n : sizes) {
            if (n < 2) {
                throw new IllegalArgumentException("--size " + n + ": a lattice needs at least 2 nodes per side");
            }
        }
        if (steps < 0 || repeats < 1) {
            throw new IllegalArgumentException("--steps must be >= 0 and --repeats >= 1, got " + steps + " and "
                    + repeats);
        }
        double step = dt.seconds(spec); // 0: the scene's own
        ParallelSpringPass.Order ord = parseOrder(order);
        if (!"parallel".equals(solver) && !"builtin".equals(solver)) {
            throw new IllegalArgumentException("--solver " + solver + ": expected parallel or builtin");
        }
        boolean builtin = "builtin".equals(solver);
        List<Integer> threadCounts = builtin ? List.of(1) : threads;
        integrator.create(spec); // fails early on an unknown name
        if (compare != null) {
            if (compare.size() != 2 || !"diaphragm".equals(scene)) {
                throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--compare takes two "
                        + "integrator names, with --scene diaphragm; got " + compare + " on " + scene);
            }
            compare.forEach(InterleavedComparison::create);
            int k = steps > 0 ? steps : 20;
            InterleavedComparison.run(DiaphragmBenchScene::build, compare, threads.get(0), step, k,
                    repeats, k, m -> System.out.println(Json.line(m)));
            return 0;
        }
        return RunFolder.run(folder, "bench", List.of("bench.jsonl", "scaling.png"), out.overwrite(), run -> {
            List<Map<String, Object>> results = measure(builtin, threadCounts, ord, step, run.file("bench.jsonl"));
            if (sizes.size() >= 2 && !"diaphragm".equals(scene)) {
                ScalingChart.write(results, run.file("scaling.png"));
            }
            run.finish(RunStatus.OK, Map.of("cases", results.size()));
        });
    }

    private List<Map<String, Object>> measure(boolean builtin, List<Integer> threadCounts,
            ParallelSpringPass.Order ord, double step, Path jsonl) throws Exception {
        List<Map<String, Object>> results = new ArrayList<>();
        StringBuilder lines = new StringBuilder();
        boolean diaphragm = "diaphragm".equals(scene);
        for (int n : diaphragm ? List.of(0) : sizes) {
            for (int t : threadCounts) {
                LatticeBenchmark.Case c;
                if (diaphragm) {
                    // A new scene per case: a simulation is consumed by its run.
                    org.tensim.scene.diaphragm.DiaphragmScene d = DiaphragmBenchScene.build();
                    org.tensim.solver.Integrator in = Integrators.create(integrator.name());
                    c = new LatticeBenchmark.Case(scene, 0, d.topology(), d.newSimulation(), false, in, t, ord,
                            builtin, d.timeStep(in, step).seconds(), steps, repeats);
                } else {
                    c = new LatticeBenchmark.Case(scene, n, LatticeBenchmark.lattice(n, links), null, shuffle,
                            Integrators.create(integrator.name()), t, ord, builtin, step > 0 ? step : 1e-3, steps,
                            repeats);
                }
                Map<String, Object> r = LatticeBenchmark.run(c);
                results.add(r);
                String line = Json.line(r);
                System.out.println(line);
                if (jsonl != null) {
                    // Rewritten whole after every case: the file always ends on a complete line.
                    lines.append(line).append('\n');
                    byte[] bytes = lines.toString().getBytes(java.nio.charset.StandardCharsets.UTF_8);
                    OutputFiles.writeAtomically(jsonl, o -> o.write(bytes));
                }
            }
        }
        return results;
    }

    static ParallelSpringPass.Order parseOrder(String s) {
        for (ParallelSpringPass.Order o : ParallelSpringPass.Order.values()) {
            if (o.name().equalsIgnoreCase(s)) {
                return o;
            }
        }
        throw new IllegalArgumentException("--order " + s + ": expected auto, authored or rcm");
    }
}

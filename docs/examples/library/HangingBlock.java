import java.nio.file.Path;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.file.Scene;
import org.tensim.scene.file.SceneBody;
import org.tensim.scene.file.SceneLoader;
import org.tensim.scene.file.SceneProbe;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/**
 * tensim as a library (docs/tutorials/library.md): a scene built in code, then a scene file loaded and run.
 *
 * <pre>
 * java -cp "tensim-0.1.0.jar:DEPENDENCIES:." HangingBlock [SCENE.yaml [KEY.PATH=VALUE ...]]
 * </pre>
 *
 * Part 1 hangs a block (two nodes of 1 kg held together by a rigid link) from a fixed node by a spring, under
 * gravity, and prints where it comes to rest against the static stretch (m1 + m2) g / k. Part 2 loads a scene file
 * (default docs/examples/cantilever.yaml), with any overrides given as tensim run's --set takes them, runs it with
 * its own integrator, step and duration, and prints each probe's final mean displacement.
 */
public final class HangingBlock {
    public static void main(String[] args) {
        hangingBlock();
        Path file = Path.of(args.length > 0 ? args[0] : "docs/examples/cantilever.yaml");
        List<String> sets = args.length > 1 ? Arrays.asList(args).subList(1, args.length) : List.of();
        runScene(file, sets);
    }

    /** A spring of k = 50 N/m carrying two 1 kg nodes joined by a rigid link, damped, settled for 30 s. */
    static void hangingBlock() {
        double k = 50;          // N/m
        double m = 1.0;         // kg, each node of the block
        double g = 9.81;        // m/s^2
        Topology t = new Topology();
        Node top = t.addNode(0, 0, 0, m).fix();        // the ceiling: never moves
        Node upper = t.addNode(0, -0.5, 0, m);         // the block's upper node, 0.5 m below: the spring's rest length
        Node lower = t.addNode(0, -0.6, 0, m);         // the block's lower node, 0.1 m below the upper one
        t.addSpring(top, upper, k, 4);                 // N/m, axial damping N s/m; rest length: the distance now
        t.addRigidLink(upper, lower);                  // 0.1 m, kept after every step by the projection
        t.setGravity(new Vec3(0, -g, 0));

        Simulation sim = Simulation.of(t);             // the paper's RK2 on the compiled flat state
        double[] worst = {0};
        sim.addListener(s -> {                         // after each step: the link's length error, m
            SystemState st = s.state();
            double dy = st.position(lower.id(), 1) - st.position(upper.id(), 1);
            double dx = st.position(lower.id(), 0) - st.position(upper.id(), 0);
            double dz = st.position(lower.id(), 2) - st.position(upper.id(), 2);
            worst[0] = Math.max(worst[0], Math.abs(Math.sqrt(dx * dx + dy * dy + dz * dz) - 0.1));
        });
        sim.runUntil(30.0, 5e-4);                      // end time, step: s

        double stretch = -(sim.state().position(upper.id(), 1) - (-0.5));
        double expected = 2 * m * g / k;
        System.out.printf("hanging block: stretch %.6f m, (m1 + m2) g / k %.6f m (%+.3f %%), worst rigid link"
                + " length error %.3g m, %d steps%n", stretch, expected, 100 * (stretch / expected - 1), worst[0],
                sim.steps());
    }

    /** Loads a scene file, runs every body in lockstep as tensim run does, prints the probes' final displacements. */
    static void runScene(Path file, List<String> sets) {
        Scene scene = SceneLoader.load(file, sets);
        Map<String, Simulation> sims = new LinkedHashMap<>();
        int nodes = 0;
        for (SceneBody b : scene.bodies().values()) {
            sims.put(b.name(), new Simulation(SystemState.compile(b.topology()),
                    Integrators.create(scene.run().integrator())));
            nodes += b.topology().nodeCount();
        }
        for (long i = 0; i < scene.run().steps(); i++) {
            for (Simulation s : sims.values()) {
                s.step(scene.run().dtS());
            }
        }
        System.out.printf("scene %s: %d nodes, %d steps of %s s (%s), %s%n", file, nodes, scene.run().steps(),
                scene.run().dtS(), scene.run().integrator(), sets.isEmpty() ? "as written" : "with " + sets);
        double[] d = new double[3];
        for (SceneProbe p : scene.probes()) {
            double[] mean = new double[3];
            SystemState st = sims.get(p.body()).state();
            for (int i = 0; i < p.nodes().length; i++) {
                st.displacement(p.nodes()[i], d);
                // a region's mean, or a surface vertex: the weights of the nodes carrying it
                double w = p.weights() == null ? 1.0 / p.nodes().length : p.weights()[i];
                for (int a = 0; a < 3; a++) {
                    mean[a] += w * d[a];
                }
            }
            System.out.printf("probe %s: mean displacement %.6e %.6e %.6e m over %d nodes%n", p.name(), mean[0],
                    mean[1], mean[2], p.nodes().length);
        }
    }
}

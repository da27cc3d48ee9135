package org.tensim.analysis;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.BitSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.scene.file.QuantityKind;
import org.tensim.scene.file.Scene;
import org.tensim.scene.file.SceneBody;
import org.tensim.scene.file.SceneException;
import org.tensim.scene.file.SceneLoader;
import org.tensim.scene.file.SceneNode;
import org.tensim.scene.file.SceneProbe;
import org.tensim.scene.file.SceneTree;
import org.tensim.scene.file.SceneUnits;
import org.tensim.scene.file.Overrides;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/**
 * A scene file's volume body under refinement: the file is loaded and run as {@code tensim run} runs it (its own
 * integrator, step and duration, every body stepped in lockstep), once at its own {@code cell} and once at each
 * {@code cell / f} for the factors f given, by {@code --set bodies.NAME.cell=...}.
 *
 * <p>A scene's {@code force} is N a node, so a finer lattice, with more nodes in the loaded region, would carry a
 * larger load. Each force condition's total, its magnitude times its region's node count in the file as written,
 * is kept instead: at each level the magnitude is set to {@code total / nodes} ({@code --set
 * conditions[i].magnitude=...}), so every level carries the file's load. What is measured at the end of each run:
 * <ul>
 * <li>each force's work-conjugate displacement {@code sum_i f_i . u_i / |F|}, which for equal forces on the nodes
 * is the mean displacement of the loaded nodes along the force (m; positive along the force);</li>
 * <li>each region probe's mean displacement (m, x, y, z);</li>
 * <li>what oscillation is left (the first force's displacement's range over the run's last sixth), and where the
 * run settles: the same lattice's small-displacement statics under the same loads.</li>
 * </ul>
 */
public final class SceneRefinement {
    /**
     * One force condition of the file.
     *
     * @param index     its place in the conditions list
     * @param region    the region it loads
     * @param direction its unit direction
     * @param totalN    magnitude times the region's nodes on the body, in the file as written, N
     */
    public record Load(int index, String region, double[] direction, double totalN) {
    }

    /**
     * One resolution's run.
     *
     * @param factor      the file's cell divided by this level's
     * @param cellM       the cell size, m
     * @param nodes       the body's nodes
     * @param loadedNodes each force's region's nodes on the body, in the order of {@link #loads}
     * @param conjugateM  each force's work-conjugate displacement at the end of the run, m (along the force)
     * @param probesM     each region probe's final mean displacement (x, y, z), m
     * @param steps       steps made
     * @param spreadM     the first force's conjugate displacement's range (max - min) over the run's last sixth, m:
     *                    what oscillation is left at the end (0 without a force)
     * @param staticM     the first force's conjugate displacement in the small-displacement statics of the same
     *                    lattice ({@link LinearStatics}: the file's fixed and driven nodes held, its forces at
     *                    their full value), m: where the run settles, without its oscillation (NaN without a force)
     */
    public record Level(int factor, double cellM, int nodes, int[] loadedNodes, double[] conjugateM,
            Map<String, double[]> probesM, long steps, double spreadM, double staticM) {
    }

    /**
     * The study.
     *
     * @param body   the refined body
     * @param young  its material's E, Pa (the file's)
     * @param loads  the file's force conditions
     * @param answer the known answer of the first force, or null when the scene is neither shape below
     * @param levels one run per factor
     */
    public record Result(String body, double young, List<Load> loads, Answer answer, List<Level> levels) {
        /** (the first force's conjugate displacement - the known answer) / the known answer, at level i. */
        public double error(int i) {
            return levels.get(i).conjugateM()[0] / answer.displacementM() - 1;
        }

        /** As {@link #error}, for the same lattice's linear statics. */
        public double staticError(int i) {
            return levels.get(i).staticM() / answer.displacementM() - 1;
        }
    }

    /**
     * The known answer of a box-shaped body whose first force loads a flat face (normal to axis {@code face}) along
     * an axis: along the face's normal it is compressed or pulled, uniaxial stress {@code sigma = F / A}, and the
     * face moves {@code F S / (E A)} (S the extent along the normal, A the face's area); across it, it is a
     * cantilever of length L (the extent along the normal), depth h (along the load) and width w, whose tip moves
     * Euler-Bernoulli's {@code F L^3 / (3 E I)}, {@code I = w h^3 / 12}. The body's other faces are free and the
     * opposite face held: the file says how (a clamp holds the lateral strain there, which the answers do not).
     *
     * @param kind           "uniaxial" or "cantilever"
     * @param displacementM  the loaded face's displacement along the force, m
     * @param extentsM       the body's extents along x, y, z, m
     * @param face           the loaded face's normal axis (0, 1, 2)
     * @param lateral        for "uniaxial": probe name to the axis of the face it sits on (normal to the load,
     *                       at the body's high side), whose mean displacement over the extent is a lateral strain
     */
    public record Answer(String kind, double displacementM, double[] extentsM, int face, Map<String, Integer> lateral) {
    }

    private SceneRefinement() {
    }

    /**
     * Runs {@code file} (with the overrides {@code sets} applied first) at the file's cell divided by each factor.
     *
     * @param body    the volume body to refine (null: the file's only volume body)
     * @param factors cell divisors, each &gt;= 1 (1 is the file as written)
     * @throws SceneException when the file has no such body, or the body no {@code cell} (a tetrahedral mesh)
     */
    public static Result run(Path file, String body, List<Integer> factors, List<String> sets) {
        SceneNode root = SceneTree.read(file);
        Overrides.apply(root, sets);
        SceneUnits units = SceneUnits.read(root.get("units"));
        SceneNode bodies = root.get("bodies");
        String name = body != null ? body : onlyVolume(file, bodies);
        SceneNode b = bodies == null ? null : bodies.get(name);
        if (b == null || b.get("cell") == null || !b.isMap()) {
            throw new SceneException(file + ": no volume body '" + name + "' with a cell size to refine"
                    + " (a lattice's cell: is it a tetrahedral mesh?)");
        }
        double cell = units.si(b.get("cell"), QuantityKind.LENGTH);
        SceneNode material = b.get("material");
        double young = material == null || material.get("E") == null ? Double.NaN
                : units.si(material.get("E"), QuantityKind.PRESSURE);
        Scene asWritten = SceneLoader.load(file, sets);
        List<Load> loads = new ArrayList<>();
        SceneNode conditions = root.get("conditions");
        for (int i = 0; conditions != null && i < conditions.items().size(); i++) {
            SceneNode c = conditions.items().get(i);
            if (c.get("type") != null && c.get("type").text().equals("force")) {
                String region = c.get("region").text();
                double m = units.si(c.get("magnitude"), QuantityKind.FORCE);
                double[] d = new double[3];
                for (int a = 0; a < 3; a++) {
                    d[a] = units.si(c.get("direction").items().get(a), QuantityKind.NUMBER);
                }
                double norm = Math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                for (int a = 0; a < 3; a++) {
                    d[a] /= norm;
                }
                loads.add(new Load(i, region, d, m * nodesIn(asWritten, region, name).cardinality()));
            }
        }
        Answer answer = loads.isEmpty() || !(young > 0) ? null : answer(asWritten, name, loads.get(0), young);
        List<Level> levels = new ArrayList<>();
        for (int f : factors) {
            if (f < 1) {
                throw new IllegalArgumentException("refinement factors must be whole numbers >= 1, got " + f);
            }
            List<String> at = new ArrayList<>(sets);
            at.add("bodies." + name + ".cell=" + (cell / f) + " m");
            Scene counted = SceneLoader.load(file, at);
            int[] loaded = new int[loads.size()];
            for (int k = 0; k < loads.size(); k++) {
                Load l = loads.get(k);
                loaded[k] = nodesIn(counted, l.region(), name).cardinality();
                at.add("conditions[" + l.index() + "].magnitude=" + (l.totalN() / loaded[k]) + " N");
            }
            levels.add(runLevel(SceneLoader.load(file, at), name, f, cell / f, loads, loaded));
        }
        return new Result(name, young, loads, answer, levels);
    }

    /** The {@link Answer} of the scene as written, or null when its body and first load have neither shape. */
    static Answer answer(Scene s, String body, Load load, double young) {
        SceneBody b = s.bodies().get(body);
        double[] box = b.bounds();
        double[] ext = {box[3] - box[0], box[4] - box[1], box[5] - box[2]};
        double[] face = boxOf(b, nodesIn(s, load.region(), body));
        int normal = flatAxis(face, ext);
        int along = 0;
        for (int a = 1; a < 3; a++) {
            along = Math.abs(load.direction()[a]) > Math.abs(load.direction()[along]) ? a : along;
        }
        if (normal < 0 || Math.abs(load.direction()[along]) < 1 - 1e-9) {
            return null;
        }
        double f = load.totalN();
        if (normal == along) {
            double area = ext[(normal + 1) % 3] * ext[(normal + 2) % 3];
            Map<String, Integer> lateral = new LinkedHashMap<>();
            for (SceneProbe p : s.probes()) {
                if (p.body().equals(body) && p.quantity().equals("mean") && p.weights() == null) {
                    BitSet n = new BitSet();
                    for (int i : p.nodes()) {
                        n.set(i);
                    }
                    double[] pb = boxOf(b, n);
                    int a = flatAxis(pb, ext);
                    if (a >= 0 && a != normal && Math.abs(pb[a] - box[a + 3]) <= 1e-9 * ext[a]) {
                        lateral.put(p.name(), a);
                    }
                }
            }
            return new Answer("uniaxial", f * ext[normal] / (young * area), ext, normal, lateral);
        }
        double len = ext[normal];
        double h = ext[along];
        double w = ext[3 - normal - along];
        return new Answer("cantilever", f * len * len * len / (3 * young * w * h * h * h / 12), ext, normal,
                Map.of());
    }

    private static double[] boxOf(SceneBody b, BitSet nodes) {
        double[] r = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE,
            -Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (int i = nodes.nextSetBit(0); i >= 0; i = nodes.nextSetBit(i + 1)) {
            var p = b.topology().nodes().get(i).position();
            double[] x = {p.x(), p.y(), p.z()};
            for (int a = 0; a < 3; a++) {
                r[a] = Math.min(r[a], x[a]);
                r[a + 3] = Math.max(r[a + 3], x[a]);
            }
        }
        return r;
    }

    /** The one axis along which {@code box} has no extent (a face), or -1. */
    private static int flatAxis(double[] box, double[] ext) {
        int flat = -1;
        double scale = Math.max(ext[0], Math.max(ext[1], ext[2]));
        for (int a = 0; a < 3; a++) {
            if (box[a + 3] - box[a] <= 1e-9 * scale) {
                if (flat >= 0) {
                    return -1;
                }
                flat = a;
            }
        }
        return flat;
    }

    private static Level runLevel(Scene s, String name, int factor, double cellM, List<Load> loads, int[] loaded) {
        Map<String, Simulation> sims = new LinkedHashMap<>();
        for (SceneBody sb : s.bodies().values()) {
            sims.put(sb.name(), new Simulation(SystemState.compile(sb.topology()),
                    Integrators.create(s.run().integrator())));
        }
        long steps = s.run().steps();
        SystemState st = sims.get(name).state();
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (long i = 1; i <= steps; i++) {
            for (Simulation sim : sims.values()) {
                sim.step(s.run().dtS());
            }
            if (!loads.isEmpty() && i >= steps - steps / 6) {
                double u = conjugate(s, st, name, loads.get(0));
                lo = Math.min(lo, u);
                hi = Math.max(hi, u);
            }
        }
        double[] conjugate = new double[loads.size()];
        for (int k = 0; k < loads.size(); k++) {
            conjugate[k] = conjugate(s, st, name, loads.get(k));
        }
        double[] d = new double[3];
        Map<String, double[]> probes = new LinkedHashMap<>();
        for (SceneProbe p : s.probes()) {
            if (p.quantity().equals("mean") && p.weights() == null) {
                double[] mean = new double[3];
                SystemState ps = sims.get(p.body()).state();
                for (int n : p.nodes()) {
                    ps.displacement(n, d);
                    for (int a = 0; a < 3; a++) {
                        mean[a] += d[a] / p.nodes().length;
                    }
                }
                probes.put(p.name(), mean);
            }
        }
        return new Level(factor, cellM, s.bodies().get(name).topology().nodeCount(), loaded, conjugate, probes,
                steps, loads.isEmpty() ? 0 : hi - lo, statics(s, name, loads, loaded));
    }

    /** The first force's conjugate displacement in the linear statics of the body's lattice, m. */
    private static double statics(Scene s, String name, List<Load> loads, int[] loaded) {
        if (loads.isEmpty()) {
            return Double.NaN;
        }
        var t = s.bodies().get(name).topology();
        boolean[] fixed = new boolean[3 * t.nodeCount()];
        for (var n : t.nodes()) {
            boolean held = n.isFixed() || n.isDriven();
            fixed[3 * n.id()] = fixed[3 * n.id() + 1] = fixed[3 * n.id() + 2] = held;
        }
        double[] f = new double[fixed.length];
        for (int k = 0; k < loads.size(); k++) {
            BitSet nodes = nodesIn(s, loads.get(k).region(), name);
            double per = loads.get(k).totalN() / loaded[k];
            for (int n = nodes.nextSetBit(0); n >= 0; n = nodes.nextSetBit(n + 1)) {
                for (int a = 0; a < 3; a++) {
                    f[3 * n + a] += per * loads.get(k).direction()[a];
                }
            }
        }
        double[] u = LinearStatics.solve(t, fixed, f, 1e-10).displacementM();
        BitSet nodes = nodesIn(s, loads.get(0).region(), name);
        double[] dir = loads.get(0).direction();
        double sum = 0;
        for (int n = nodes.nextSetBit(0); n >= 0; n = nodes.nextSetBit(n + 1)) {
            sum += u[3 * n] * dir[0] + u[3 * n + 1] * dir[1] + u[3 * n + 2] * dir[2];
        }
        return sum / nodes.cardinality();
    }

    /** Equal forces F / N on N nodes: {@code sum f . u / F} is the mean of u along the force, m. */
    private static double conjugate(Scene s, SystemState st, String body, Load load) {
        BitSet nodes = nodesIn(s, load.region(), body);
        double[] dir = load.direction();
        double[] d = new double[3];
        double sum = 0;
        for (int n = nodes.nextSetBit(0); n >= 0; n = nodes.nextSetBit(n + 1)) {
            st.displacement(n, d);
            sum += d[0] * dir[0] + d[1] * dir[1] + d[2] * dir[2];
        }
        return sum / nodes.cardinality();
    }

    private static BitSet nodesIn(Scene s, String region, String body) {
        BitSet n = s.regions().get(region).in(body);
        if (n == null || n.isEmpty()) {
            throw new SceneException(s.file() + ": region '" + region + "' has no node on body '" + body
                    + "', which its force loads");
        }
        return n;
    }

    private static String onlyVolume(Path file, SceneNode bodies) {
        List<String> volumes = new ArrayList<>();
        if (bodies != null && bodies.isMap()) {
            for (Map.Entry<String, SceneNode> e : bodies.entries().entrySet()) {
                SceneNode t = e.getValue().isMap() ? e.getValue().get("type") : null;
                if (t != null && t.text().equals("volume")) {
                    volumes.add(e.getKey());
                }
            }
        }
        if (volumes.size() != 1) {
            throw new SceneException(file + ": expected one volume body to refine, found " + volumes.size()
                    + (volumes.isEmpty() ? "" : " (" + String.join(", ", volumes) + "): name one with --body"));
        }
        return volumes.get(0);
    }
}

package org.tensim.scene.file;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.tensim.model.Node;

/** What {@code tensim check} prints about a loaded scene, and small helpers its readers share. */
public final class SceneCheck {
    private SceneCheck() {
    }

    /**
     * The report's lines: each body's type and counts (nodes, springs, rigid links, fixed nodes, loads), each
     * coupling between deformable bodies, each region's resolved node count and bounding box per body, each probe's
     * columns, each named parameter (path, value, default, unit, range, apply mode), each expectation's range and
     * the run's settings.
     */
    public static List<String> report(Scene s) {
        List<String> out = new ArrayList<>();
        out.add(s.file() + ": scene version " + SceneLoader.VERSION + ", " + s.bodies().size() + " bod"
                + (s.bodies().size() == 1 ? "y" : "ies") + ", " + s.regions().size() + " region(s), "
                + s.laws().size() + " law(s), " + s.probes().size() + " probe(s)");
        for (SceneBody b : s.bodies().values()) {
            long fixed = b.topology().nodes().stream().filter(Node::isFixed).count();
            long driven = b.topology().nodes().stream().filter(Node::isDriven).count();
            out.add(String.format(Locale.ROOT, "body %s (%s): %d nodes, %d springs, %d rigid links; %d fixed, %d"
                    + " driven, %d loaded; nodes in %s", b.name(), b.type(), b.topology().nodeCount(),
                    b.topology().springs().size(), b.topology().rigidLinks().size(), fixed, driven,
                    b.topology().forces().size(), box(b.bounds())));
            for (String line : b.report()) {
                out.add("  " + line);
            }
            long held = b.topology().nodes().stream().filter(n -> !n.isFixed() && n.heldAxes() != 0).count();
            if (held > 0) {
                out.add("  " + held + " node(s) held on some axes only (fixed with axes:), free on the others");
            }
            if (!b.topology().contacts().isEmpty()) {
                out.add("  " + b.topology().contacts().size() + " contact pair(s) with "
                        + String.join(", ", b.topology().contactBodies().stream().map(c -> c.name()
                                + (c.hard() ? " (hard)" : "")).toList()));
            }
        }
        for (BodyCoupling c : s.couplings()) {
            out.add(String.format(Locale.ROOT, "%s of %d node(s) of %s with the surface of %s (%d triangles), %.6g"
                    + " N/m a node: run in one state", c.type(), c.followers().length, c.body(), c.with(),
                    s.bodies().get(c.with()).surface().mesh().triangleCount(), c.stiffnessNPerM()));
        }
        for (RigidBody r : s.rigids().values()) {
            out.add(String.format(Locale.ROOT, "rigid %s: %s%s, %s motion; surface in %s", r.name(), r.shape(),
                    r.cavity() ? " (cavity)" : "", r.motionType(), box(r.boundsM())));
            if (!r.report().isEmpty()) {
                out.add("  " + r.report());
            }
        }
        for (SceneRegions.Region r : s.regions().values()) {
            for (Map.Entry<String, BitSet> e : r.nodes().entrySet()) {
                SceneBody b = s.bodies().get(e.getKey());
                out.add(String.format(Locale.ROOT, "region %s on %s: %d nodes in %s", r.name(), e.getKey(),
                        e.getValue().cardinality(), box(bounds(b, e.getValue()))));
            }
        }
        for (SceneProbe p : s.probes()) {
            out.add("probe " + p.name() + " on " + p.body() + ": " + String.join(", ", p.columns()));
        }
        for (SceneParameter p : s.parameters()) {
            out.add(p.describe());
        }
        for (SceneExpectation e : s.expect()) {
            out.add("expect " + e.label() + " " + e.range());
        }
        RunSettings run = s.run();
        org.tensim.solver.stability.TimeStep auto = null;
        for (SceneBody b : run.autoStep() ? s.bodies().values() : List.<SceneBody>of()) {
            auto = BodyTypes.get(b.type()).autoStep(b, run.integrator());
        }
        if (auto != null) {
            out.add(String.format(Locale.ROOT, "run: %s, dt auto: %.6g s (%s), %s s (%d steps), CSV %s every %d"
                    + " step(s)", run.integrator(), auto.seconds(), auto.reason(), run.durationS(),
                    Math.round(run.durationS() / auto.seconds()), run.csv(), run.every()));
        } else {
            out.add(String.format(Locale.ROOT, "run: %s, dt %s s, %s s (%d steps), CSV %s every %d step(s)",
                    run.integrator(), run.dtS(), run.durationS(), run.steps(), run.csv(), run.every()));
        }
        return out;
    }

    /** The bounding box of some nodes' initial positions. */
    static double[] bounds(SceneBody b, BitSet nodes) {
        double[] bb = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE,
            -Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        nodes.stream().forEach(i -> {
            Node n = b.topology().node(i);
            double[] p = {n.position().x(), n.position().y(), n.position().z()};
            for (int a = 0; a < 3; a++) {
                bb[a] = Math.min(bb[a], p[a]);
                bb[a + 3] = Math.max(bb[a + 3], p[a]);
            }
        });
        return bb;
    }

    /** A bounding box as {@code [x0, y0, z0]-[x1, y1, z1] m}. */
    static String box(double[] b) {
        return String.format(Locale.ROOT, "[%.6g, %.6g, %.6g]-[%.6g, %.6g, %.6g] m", b[0], b[1], b[2], b[3], b[4],
                b[5]);
    }

    /** A body's name given by a scalar; refused with a "did you mean" if there is no such body. */
    static String bodyName(SceneNode n, Map<String, SceneBody> bodies) {
        if (!n.isScalar() || !bodies.containsKey(n.text())) {
            throw SceneException.at(n, n.describe() + " is not a body of this file"
                    + (n.isScalar() ? DidYouMean.suggest(n.text(), bodies.keySet()) : "") + " (bodies: "
                    + String.join(", ", bodies.keySet()) + ")");
        }
        return n.text();
    }
}

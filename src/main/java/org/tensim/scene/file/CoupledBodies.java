package org.tensim.scene.file;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.model.ContactPair;
import org.tensim.model.ForceLaw;
import org.tensim.model.LinearMapping;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.TriangleElement;
import org.tensim.model.Vec3;
import org.tensim.model.VolumeElement;
import org.tensim.solver.Simulation;
import org.tensim.solver.SurfaceSliding;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/**
 * Deformable bodies that touch or slide on each other ({@link BodyCoupling}) must share one state, because the
 * coupling's forces act on both at once. {@link #merge} turns a scene's coupled bodies, each group of bodies joined
 * by couplings, into one body whose topology holds theirs one after the other (node ids offset by the nodes before
 * it; elements, forces, contacts and motions carried over), its regions and probes moved to it with the same
 * offsets (their columns keep their names); {@link #addTerms} puts the couplings' {@link SurfaceSliding} terms on
 * its simulation. A scene without couplings is returned as it is: its bodies run as before, each on its own.
 *
 * <p>The merged body is named by its bodies joined with '+' (in file order), of type {@link #TYPE}. Its bodies'
 * gravities may differ (a gravity condition on some bodies): each then acts as the nodal forces m g of its nodes.
 * Their global viscous damping must agree (one value per state). Fibres and transverse shear are not carried over
 * (the volume, cube and shell bodies have none of theirs in a scene file): refused.
 */
public final class CoupledBodies {
    /** The type name of a merged body. */
    public static final String TYPE = "coupled";

    /** One coupling on the merged state: followers and the surface mapping in its node ids. */
    record Term(SurfaceSliding.Mode mode, int[] followers, LinearMapping surface, int[] triangles,
            double stiffnessNPerM, double gapM) {
    }

    private CoupledBodies() {
    }

    /**
     * Where a body of a scene sits in the scene {@link #merge} makes of it: the name of the body that holds it (its
     * own name when nothing couples it) and the id of its first node there.
     */
    public record Place(String into, int offset) {
    }

    /** Each body's {@link Place}, in file order. */
    public static Map<String, Place> places(Scene scene) {
        Map<String, Place> out = new LinkedHashMap<>();
        for (List<String> members : groups(scene)) {
            String name = String.join("+", members);
            int offset = 0;
            for (String m : members) {
                out.put(m, new Place(name, offset));
                offset += scene.bodies().get(m).topology().nodeCount();
            }
        }
        Map<String, Place> ordered = new LinkedHashMap<>();
        scene.bodies().keySet().forEach(b -> ordered.put(b, out.get(b)));
        return ordered;
    }

    /** The groups of bodies joined by couplings, each in file order, ordered by their first body. */
    private static List<List<String>> groups(Scene scene) {
        List<String> names = new ArrayList<>(scene.bodies().keySet());
        int[] group = new int[names.size()];
        for (int i = 0; i < group.length; i++) {
            group[i] = i;
        }
        for (BodyCoupling c : scene.couplings()) {
            int a = root(group, names.indexOf(c.body()));
            int b = root(group, names.indexOf(c.with()));
            group[Math.max(a, b)] = Math.min(a, b);
        }
        List<List<String>> out = new ArrayList<>();
        for (int i = 0; i < names.size(); i++) {
            if (root(group, i) == i) {
                List<String> members = new ArrayList<>();
                for (int j = 0; j < names.size(); j++) {
                    if (root(group, j) == i) {
                        members.add(names.get(j));
                    }
                }
                out.add(members);
            }
        }
        return out;
    }

    /** The scene with each group of coupled bodies merged into one (the scene itself when it has no coupling). */
    public static Scene merge(Scene scene) {
        if (scene.couplings().isEmpty()) {
            return scene;
        }
        Map<String, String> into = new LinkedHashMap<>(); // body -> its merged body's name
        Map<String, Integer> offset = new LinkedHashMap<>();
        Map<String, Place> places = places(scene);
        places.forEach((b, p) -> {
            into.put(b, p.into());
            offset.put(b, p.offset());
        });
        Map<String, SceneBody> bodies = new LinkedHashMap<>();
        for (List<String> members : groups(scene)) {
            if (members.size() == 1) {
                bodies.put(members.get(0), scene.bodies().get(members.get(0)));
            } else {
                String name = String.join("+", members);
                Topology t = new Topology();
                for (String m : members) {
                    copy(scene.bodies().get(m), t);
                }
                gravityAndDamping(scene, members, offset, t);
                List<Term> terms = new ArrayList<>();
                for (BodyCoupling c : scene.couplings()) {
                    if (into.get(c.body()).equals(name)) {
                        terms.add(term(c, scene.bodies().get(c.with()), offset, t.nodeCount()));
                    }
                }
                List<String> report = new ArrayList<>();
                report.add("bodies " + String.join(", ", members) + " in one state: " + t.nodeCount() + " nodes, "
                        + terms.size() + " coupling" + (terms.size() == 1 ? "" : "s"));
                SceneBody first = scene.bodies().get(members.get(0));
                bodies.put(name, new SceneBody(name, TYPE, t, null, first.node(), null, report, List.copyOf(terms)));
            }
        }
        List<SceneProbe> probes = new ArrayList<>();
        for (SceneProbe p : scene.probes()) {
            String body = into.get(p.body());
            probes.add(body == null || body.equals(p.body()) ? p : new SceneProbe(p.name(), body,
                    shift(p.nodes(), offset.get(p.body())), p.quantity(), p.weights(), p.with()));
        }
        Map<String, SceneRegions.Region> regions = new LinkedHashMap<>();
        for (SceneRegions.Region reg : scene.regions().values()) {
            Map<String, BitSet> nodes = new LinkedHashMap<>();
            for (Map.Entry<String, BitSet> e : reg.nodes().entrySet()) {
                int off = offset.get(e.getKey());
                BitSet shifted = nodes.computeIfAbsent(into.get(e.getKey()), k -> new BitSet());
                e.getValue().stream().forEach(i -> shifted.set(i + off));
            }
            regions.put(reg.name(), new SceneRegions.Region(reg.name(), reg.node(), nodes));
        }
        return new Scene(scene.file(), scene.overrides(), bodies, scene.laws(), regions, probes, scene.run(),
                scene.expect(), scene.parameters(), scene.rigids(), scene.couplings());
    }

    private static int root(int[] group, int i) {
        while (group[i] != i) {
            i = group[i];
        }
        return i;
    }

    private static int[] shift(int[] ids, int off) {
        int[] out = new int[ids.length];
        for (int i = 0; i < ids.length; i++) {
            out[i] = ids[i] + off;
        }
        return out;
    }

    /** Appends body b's topology to t, its node ids offset by t's node count. */
    private static void copy(SceneBody b, Topology t) {
        Topology from = b.topology();
        if (!from.fibres().isEmpty() || !from.shears().isEmpty()) {
            throw SceneException.at(b.node(), "body '" + b.name() + "' has active fibres or transverse shear, which"
                    + " a coupled body (in one state with another) does not carry over");
        }
        int off = t.nodeCount();
        for (Node n : from.nodes()) {
            Node m = t.addNode(n.position(), n.mass());
            if (n.isFixed()) {
                m.fix();
            } else if (n.isDriven()) {
                m.drive(n.motion());
            }
        }
        from.springs().forEach(s -> t.addSpring(s.a() + off, s.b() + off, s.stiffness(), s.restLength(),
                s.damping()));
        from.rigidLinks().forEach(l -> t.addRigidLink(l.a() + off, l.b() + off, l.length()));
        for (TriangleElement e : from.triangles()) {
            int[] p = {e.p(0) + off, e.p(1) + off, e.p(2) + off};
            int[] q = {e.q(0) + off, e.q(1) + off, e.q(2) + off};
            t.addTriangle(p, q, e.thicknessM(), e.youngPa(), e.poisson(), e.dampingS());
        }
        for (VolumeElement v : from.volumeElements()) {
            int[] ids = new int[v.size()];
            for (int c = 0; c < ids.length; c++) {
                ids[c] = v.node(c) + off;
            }
            t.addVolumeElement(ids, v.modulusPa(), v.dampingS());
        }
        int bodyOff = t.contactBodies().size();
        from.contactBodies().forEach(t::addContactBody);
        for (ContactPair c : from.contacts()) {
            t.addContact(c.node() + off, c.body() + bodyOff, c.stiffnessNPerM(), c.gapM());
        }
        from.forces().forEach(f -> t.applyForce(t.node(f.node() + off), f.law()));
    }

    /** One gravity when the bodies agree, else each body's as nodal forces; one damping, which they must share. */
    private static void gravityAndDamping(Scene scene, List<String> members, Map<String, Integer> offset,
            Topology t) {
        Topology first = scene.bodies().get(members.get(0)).topology();
        boolean same = members.stream().allMatch(m -> scene.bodies().get(m).topology().gravity()
                .equals(first.gravity()));
        for (String m : members) {
            Topology b = scene.bodies().get(m).topology();
            if (b.viscousDamping() != first.viscousDamping()) {
                throw SceneException.at(scene.bodies().get(m).node(), "body '" + m + "' has viscous damping "
                        + b.viscousDamping() + " N s/m and '" + members.get(0) + "' " + first.viscousDamping()
                        + ": bodies that touch or slide on each other share one state and one damping");
            }
            if (!same && b.gravity().norm() > 0) {
                Vec3 g = b.gravity();
                for (Node n : b.nodes()) {
                    t.applyForce(t.node(n.id() + offset.get(m)), ForceLaw.constant(g.times(n.mass())));
                }
            }
        }
        t.setGravity(same ? first.gravity() : Vec3.ZERO);
        t.setViscousDamping(first.viscousDamping());
    }

    /** A coupling's term data in the merged ids: the surface's mapping shifted, its triangles turned outward. */
    private static Term term(BodyCoupling c, SceneBody with, Map<String, Integer> offset, int nodes) {
        EmbeddedSurface s = with.surface();
        int[] tris = s.mesh().triangles().clone();
        if (s.mesh().signedVolume() < 0) { // given inside out: turn round so that the normals point outward
            for (int k = 0; k < tris.length; k += 3) {
                int swap = tris[k + 1];
                tris[k + 1] = tris[k + 2];
                tris[k + 2] = swap;
            }
        }
        SurfaceSliding.Mode mode = c.type().equals("contact") ? SurfaceSliding.Mode.CONTACT
                : SurfaceSliding.Mode.SLIDING;
        return new Term(mode, shift(c.followers(), offset.get(c.body())), shifted(s.mapping(),
                offset.get(with.name()), nodes), tris, c.stiffnessNPerM(), c.gapM());
    }

    /**
     * A body's surface mapping in the ids of the merged body that holds it ({@link #places}): each entry's node id
     * moved by {@code offset}, over {@code nodes} nodes.
     */
    public static LinearMapping shifted(LinearMapping m, int offset, int nodes) {
        LinearMapping.Builder b = new LinearMapping.Builder(nodes);
        for (int i = 0; i < m.pointCount(); i++) {
            int[] ids = new int[m.entries(i)];
            double[] w = new double[ids.length];
            for (int k = 0; k < ids.length; k++) {
                ids[k] = m.node(i, k) + offset;
                w[k] = m.weight(i, k);
            }
            b.add(ids, w);
        }
        return b.build();
    }

    /**
     * The simulations {@code tensim run} steps for a merged scene ({@link #merge}): one per body, in file order,
     * with a new {@code integrator} each (an {@code Integrators} name) and its couplings' terms ({@link #addTerms}).
     */
    public static Map<String, Simulation> simulations(Scene merged, String integrator) {
        Map<String, Simulation> sims = new LinkedHashMap<>();
        for (SceneBody b : merged.bodies().values()) {
            Simulation sim = new Simulation(SystemState.compile(b.topology()), Integrators.create(integrator));
            addTerms(b, sim);
            sims.put(b.name(), sim);
        }
        return sims;
    }

    /**
     * Adds the couplings of a merged body ({@link #merge}) to its simulation: one {@link SurfaceSliding} each, paired
     * at the simulation's positions, a sliding follower held at its rest distance d0, a contact follower kept beyond
     * min(gap, d0). Does nothing for another body.
     */
    public static void addTerms(SceneBody body, Simulation sim) {
        if (!TYPE.equals(body.type()) || !(body.built() instanceof List<?> terms)) {
            return;
        }
        double[] x = sim.state().x;
        for (Object o : terms) {
            Term c = (Term) o;
            int n = c.followers().length;
            double[] k = new double[n];
            java.util.Arrays.fill(k, c.stiffnessNPerM());
            sim.forces().addTerm(SurfaceSliding.heldAtRest(c.followers(), c.surface(), c.triangles(), k, c.mode(),
                    c.gapM(), x));
        }
    }
}

package org.tensim.scene.tunable;

import java.util.ArrayList;
import java.util.List;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.LinearMapping;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.lungs.OrganMeshes;
import org.tensim.scene.lungs.ThoraxOrgans;
import org.tensim.scene.volume.VolumeBody;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;

/**
 * The lungs and the liver in the diaphragm's window ({@code tensim gui --thorax DIR --lungs}): built into each
 * diaphragm scene's own state as {@code tensim diaphragm --lungs} builds them ({@link ThoraxOrgans}, their couplings
 * installed as force terms), and drawn as their embedded surfaces, each vertex carried by the eight lattice nodes of
 * its cell ({@link VolumeBody#surfaceMapping}).
 *
 * <p>What is drawn lives in a simulation of its own ({@link #newCarried}), as a mapped diaphragm's drawn mesh does
 * ({@link DiaphragmMappedViewScene}): every node fixed, no springs, its positions set through the mapping after every
 * step of the mechanics ({@link #follow}), so that the frame buffer copies them with the rest and the renderer never
 * reads the model.
 *
 * @param meshes  the organs' surfaces, read once
 * @param options how the organs are built
 */
public record DiaphragmOrgans(OrganMeshes meshes, ThoraxOrgans.Options options) {
    /** Colour of the lungs' surfaces (pink). */
    static final float[] LUNG_COLOUR = {0.95f, 0.62f, 0.66f};
    /** Colour of the liver's surface (dark red-brown). */
    static final float[] LIVER_COLOUR = {0.55f, 0.22f, 0.16f};

    /** The organs without the liver when {@code meshes} has none. */
    public DiaphragmOrgans {
        if (meshes.liver() == null && options.liver() != null) {
            options = options.withoutLiver();
        }
    }

    /** Builds the organs into {@code scene}'s topology, after all its nodes, without installing their couplings. */
    ThoraxOrgans build(DiaphragmScene scene) {
        return ThoraxOrgans.build(scene, meshes.lungs(), meshes.liver(), options);
    }

    /** Builds the organs into {@code scene} and installs their couplings: its next simulations carry them. */
    Built install(DiaphragmScene scene) {
        ThoraxOrgans o = build(scene);
        return new Built(o, List.copyOf(o.install(scene)), scene.topology().nodeCount() - o.firstNode());
    }

    /**
     * The organs of one scene.
     *
     * @param organs their build
     * @param terms  their couplings, as installed in the scene
     * @param nodes  the nodes they added to the scene's state (lattices, anchors, pleura frames)
     */
    record Built(ThoraxOrgans organs, List<org.tensim.solver.SurfaceSliding> terms, int nodes) {
        /** Every organ's surface, lungs then liver, one after the other. */
        List<VolumeBody> bodies() {
            List<VolumeBody> l = new ArrayList<>();
            organs.lungs().forEach(lung -> l.add(lung.body()));
            if (organs.liver() != null) {
                l.add(organs.liver());
            }
            return l;
        }

        /** The drawn vertices of every organ's surface on the state's nodes ({@code nodeCount} of them). */
        LinearMapping drawnMapping(int nodeCount) {
            LinearMapping.Builder b = new LinearMapping.Builder(nodeCount);
            for (VolumeBody v : bodies()) {
                LinearMapping m = v.surfaceMapping();
                for (int i = 0; i < m.pointCount(); i++) {
                    int e = m.entries(i);
                    int[] nodes = new int[e];
                    double[] w = new double[e];
                    for (int k = 0; k < e; k++) {
                        nodes[k] = m.node(i, k);
                        w[k] = m.weight(i, k);
                    }
                    b.add(nodes, w);
                }
            }
            return b.build();
        }

        /** The surfaces' triangles, on the drawn vertices of {@link #drawnMapping}. */
        int[] triangles() {
            int count = 0;
            for (VolumeBody v : bodies()) {
                count += v.surface().triangles().length;
            }
            int[] out = new int[count];
            int k = 0;
            int first = 0;
            for (VolumeBody v : bodies()) {
                TriangleMesh m = v.surface();
                for (int c : m.triangles()) {
                    out[k++] = first + c;
                }
                first += m.vertexCount();
            }
            return out;
        }

        /** A colour per drawn vertex: the lungs pink, the liver dark red. */
        float[] colours() {
            List<VolumeBody> all = bodies();
            int n = 0;
            for (VolumeBody v : all) {
                n += v.surface().vertexCount();
            }
            float[] c = new float[3 * n];
            int at = 0;
            for (int b = 0; b < all.size(); b++) {
                float[] rgb = b < organs.lungs().size() ? LUNG_COLOUR : LIVER_COLOUR;
                for (int v = 0; v < all.get(b).surface().vertexCount(); v++, at++) {
                    System.arraycopy(rgb, 0, c, 3 * at, 3);
                }
            }
            return c;
        }
    }

    /** The drawn surfaces' own simulation: fixed nodes at the mapped rest positions of {@code mechanics}. */
    static Simulation newCarried(LinearMapping drawn, Simulation mechanics) {
        double[] rest = new double[3 * drawn.pointCount()];
        drawn.apply(mechanics.state().x0, rest);
        Topology t = new Topology();
        for (int i = 0; i < drawn.pointCount(); i++) {
            t.addNode(new Vec3(rest[3 * i], rest[3 * i + 1], rest[3 * i + 2]), 1).fix();
        }
        Simulation s = new Simulation(SystemState.compile(t));
        follow(drawn, mechanics, s);
        return s;
    }

    /** Sets the drawn vertices from the mechanics' positions (allocation-free). */
    static void follow(LinearMapping drawn, Simulation mechanics, Simulation carried) {
        drawn.apply(mechanics.state().x, carried.state().x);
    }
}

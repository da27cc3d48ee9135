package org.tensim.scene.diaphragm;

import java.util.List;
import org.tensim.model.Topology;

/** A running simulation's constants replaced by a rebuilt scene's, its motion kept (the GUI's live retuning). */
public final class LiveConstants {
    private LiveConstants() {
    }

    /**
     * Gives the state of a running simulation the spring stiffnesses, spring damping, membrane
     * triangles' and shear elements' constants and viscous damping of topology {@code to}: that of a scene rebuilt from the running one with other
     * constants ({@link DiaphragmScene#rebuiltWith}), or a copy of it made the same way as the running topology
     * (e.g. with the rigid links as springs). Positions, velocities and time are kept.
     *
     * @throws IllegalArgumentException when the two topologies do not have the same springs
     */
    public static void copy(org.tensim.solver.SystemState state, Topology to) {
        List<org.tensim.model.Spring> springs = to.springs();
        if (springs.size() != state.springCount()) {
            throw new IllegalArgumentException("the rebuilt scene has " + springs.size() + " springs, the running"
                    + " simulation " + state.springCount() + ": only constants may change, not the topology");
        }
        for (int i = 0; i < springs.size(); i++) {
            org.tensim.model.Spring sp = springs.get(i);
            if (sp.a() != state.springA[i] || sp.b() != state.springB[i]) {
                throw new IllegalArgumentException("spring " + i + " joins " + sp.a() + "-" + sp.b()
                        + " in the rebuilt scene, " + state.springA[i] + "-" + state.springB[i] + " in the running one");
            }
            state.setSpringStiffness(i, sp.stiffness());
            state.setSpringDamping(i, sp.damping());
        }
        if (to.triangles().size() != state.triangleCount()) {
            throw new IllegalArgumentException("the rebuilt scene has " + to.triangles().size() + " membrane triangles,"
                    + " the running simulation " + state.triangleCount() + ": only constants may change");
        }
        for (int i = 0; i < to.triangles().size(); i++) {
            state.setTriangleConstants(i, to.triangles().get(i));
        }
        if (to.shears().size() != state.shears.count()) {
            throw new IllegalArgumentException("the rebuilt scene has " + to.shears().size() + " shear elements, the"
                    + " running simulation " + state.shears.count() + ": only constants may change");
        }
        for (int i = 0; i < to.shears().size(); i++) {
            state.setShearConstants(i, to.shears().get(i));
        }
        state.setViscousDamping(to.viscousDamping());
    }
}

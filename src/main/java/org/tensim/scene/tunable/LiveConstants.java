package org.tensim.scene.tunable;

import java.util.Arrays;
import org.tensim.solver.SystemState;

/**
 * Hands a running simulation the constants of the same scene built anew with other values (a scene file's live
 * parameters, docs/scenes.md): spring stiffness and damping, gravity, viscous damping, the applied forces' laws and
 * the driven nodes' motions. Positions, velocities and time are kept. Both states must be of the same build: the
 * same nodes, masses, rest positions, springs (ends and rest lengths), rigid links, fixed, driven and loaded nodes,
 * and membrane triangles of the same constants; anything else needs a rebuild and is refused, so that a key wrongly
 * taken for live can never change a running simulation halfway.
 */
public final class LiveConstants {
    private LiveConstants() {
    }

    /**
     * Gives {@code running} the constants of {@code fresh}. Simulation thread, between two steps.
     *
     * @param what the body, for the message
     * @throws IllegalStateException when {@code fresh} is not the same build as {@code running}
     */
    public static void adopt(SystemState running, SystemState fresh, String what) {
        String differs = sameBuild(running, fresh);
        if (differs != null) {
            throw new IllegalStateException(what + ": the new values change the " + differs + " of the running"
                    + " simulation, which only a rebuild can do");
        }
        for (int s = 0; s < running.springCount(); s++) {
            if (running.springK[s] != fresh.springK[s]) {
                running.setSpringStiffness(s, fresh.springK[s]);
            }
            if (running.springC[s] != fresh.springC[s]) {
                running.setSpringDamping(s, fresh.springC[s]);
            }
        }
        if (running.viscousDamping() != fresh.viscousDamping()) {
            running.setViscousDamping(fresh.viscousDamping());
        }
        System.arraycopy(fresh.forceLaw, 0, running.forceLaw, 0, fresh.forceLaw.length);
        System.arraycopy(fresh.drivenMotion, 0, running.drivenMotion, 0, fresh.drivenMotion.length);
        // Always: it also tells integrators that reuse forces that they may have changed (parameterVersion).
        running.setGravity(fresh.gravity());
    }

    /** Null when both states are of the same build, else what differs. */
    static String sameBuild(SystemState a, SystemState b) {
        if (a.nodeCount != b.nodeCount || !Arrays.equals(a.mass, b.mass) || !Arrays.equals(a.x0, b.x0)) {
            return "nodes or masses";
        }
        if (!Arrays.equals(a.springA, b.springA) || !Arrays.equals(a.springB, b.springB)
                || !Arrays.equals(a.springL, b.springL)) {
            return "springs";
        }
        if (!Arrays.equals(a.linkA, b.linkA) || !Arrays.equals(a.linkB, b.linkB) || !Arrays.equals(a.linkL, b.linkL)) {
            return "rigid links";
        }
        if (!Arrays.equals(a.fixedNode, b.fixedNode) || !Arrays.equals(a.drivenNode, b.drivenNode)
                || !Arrays.equals(a.forceNode, b.forceNode) || !Arrays.equals(a.heldDof, b.heldDof)) {
            return "fixed, driven or loaded nodes";
        }
        if (!Arrays.equals(a.triP, b.triP) || !Arrays.equals(a.triMu, b.triMu)
                || !Arrays.equals(a.triLambda, b.triLambda) || !Arrays.equals(a.triDamping, b.triDamping)
                || a.shears.count() != b.shears.count()) {
            return "membrane or shear elements";
        }
        return null;
    }
}

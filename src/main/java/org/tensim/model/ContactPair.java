package org.tensim.model;

/**
 * A node that may touch a contact body: a one-sided penalty spring along the body's
 * normal, {@code f = k max(0, g - d) n}, with d the node's signed distance to the
 * surface and g the gap kept (the shell's half-thickness, say).
 *
 * @param node           node id
 * @param body           index of the body in {@link Topology#contactBodies()}
 * @param stiffnessNPerM penalty stiffness k, N/m (&gt; 0)
 * @param gapM           signed distance from the surface at which contact begins, m (0: at the surface;
 *                       negative: below it, for a node that starts inside)
 */
public record ContactPair(int node, int body, double stiffnessNPerM, double gapM) {
    public ContactPair {
        Check.positive("contact stiffness", "N/m", stiffnessNPerM);
        Check.finite("contact gap", "m", gapM);
    }
}

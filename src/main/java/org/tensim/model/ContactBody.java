package org.tensim.model;

/**
 * A rigid body that deformable nodes may touch but not enter: its surface as a
 * signed distance in its rest frame, moved over time by a rigid motion. Contact is
 * frictionless and one-sided (a node is pushed out along the surface normal, never
 * pulled in, and slides freely along the surface).
 *
 * @param name     the body's name, for reports (e.g. {@code rib-r9})
 * @param surface  signed distance in the rest frame, m (negative inside)
 * @param motion   the body's pose over time ({@link RigidMotion#FIXED} for a body at rest)
 * @param boundsM  the surface's rest-frame bounding box {min x, min y, min z, max x, max y, max z}, m, for the
 *                 broad phase
 * @param hard     whether nodes that went deeper than their gap are also put back on it after each step (the
 *                 solver's contact projection, a bone); false for a penalty alone, whose penetration is the load
 *                 over the stiffness (a compliant support such as the liver)
 */
public record ContactBody(String name, SignedDistance surface, RigidMotion motion, double[] boundsM, boolean hard) {
    /** A body held by the penalty alone ({@code hard} false). */
    public ContactBody(String name, SignedDistance surface, RigidMotion motion, double[] boundsM) {
        this(name, surface, motion, boundsM, false);
    }

    public ContactBody {
        if (surface == null || motion == null) {
            throw new IllegalArgumentException("contact body '" + name + "' needs a surface and a motion");
        }
        if (boundsM == null || boundsM.length != 6) {
            throw new IllegalArgumentException("contact body '" + name + "' needs a bounding box of 6 numbers");
        }
    }
}

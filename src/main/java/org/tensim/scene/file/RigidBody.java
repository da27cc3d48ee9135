package org.tensim.scene.file;

import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.ContactBody;
import org.tensim.model.RigidMotion;
import org.tensim.model.SignedDistance;
import org.tensim.scene.rigid.RigidShapes;

/**
 * A {@code type: rigid} body of a scene ({@link RigidBodies}): a surface that moves by a rigid motion and has no
 * node of its own. Deformable bodies' conditions ({@code contact}, {@code attachment}, {@code sliding}) refer to
 * it; each deformable body's topology gets its own {@link ContactBody} of it, all sharing the same surface and
 * motion, so one rigid body serves every deformable body of the scene at once.
 *
 * @param name    its key under {@code bodies:}
 * @param shape   how it was given: mesh, box, sphere or plane
 * @param node    where it is written, for messages
 * @param surface the signed distance of its solid in its rest frame, m (negative in the solid: inside the surface,
 *                or outside it for a cavity)
 * @param motion  its pose over time
 * @param boundsM its surface's rest bounding box {min x, y, z, max x, y, z}, m (a plane's spans +/-1 km)
 * @param mesh    its surface mesh at rest, m, for drawing: the file's, or a box's or a sphere's; null for a plane,
 *                which has no extent (a view draws a square of it about the deformable bodies)
 * @param cavity  whether the solid is the outside of the closed surface (nodes are kept inside it)
 * @param motionType the motion's {@code type}: fixed, translation, rotation or helical
 * @param report  what {@code tensim check} prints of its surface (a mesh's distance grid: triangles, holes, grid
 *                size, build time); empty for the built-in shapes' exact distances
 */
public record RigidBody(String name, String shape, SceneNode node, SignedDistance surface, RigidMotion motion,
        double[] boundsM, TriangleMesh mesh, boolean cavity, String motionType, String report) {
    /** A contact body of this rigid body for one topology; {@code hard}: projected after each step. */
    public ContactBody contactBody(boolean hard) {
        return new ContactBody(name, surface, motion, boundsM.clone(), hard);
    }

    /**
     * The contact body of the complement of its solid (the other side of the same surface), named
     * {@code NAME~}: with {@link #contactBody} it holds a node on the surface from both sides.
     */
    public ContactBody complementBody(boolean hard) {
        return new ContactBody(name + "~", RigidShapes.complement(surface), motion, boundsM.clone(), hard);
    }

    /**
     * The signed distance of a point at rest (t = 0, m) to the solid, and its rest-frame point: {@code y = R(0)^T
     * (x - c(0))}. Not for the step (it allocates).
     */
    public double restDistance(double x, double y, double z) {
        double[] r = new double[9];
        double[] c = new double[3];
        motion.pose(0, r, 0, c, 0);
        double dx = x - c[0];
        double dy = y - c[1];
        double dz = z - c[2];
        double yx = r[0] * dx + r[3] * dy + r[6] * dz;
        double yy = r[1] * dx + r[4] * dy + r[7] * dz;
        double yz = r[2] * dx + r[5] * dy + r[8] * dz;
        return surface.distance(yx, yy, yz, new double[3], 0);
    }
}

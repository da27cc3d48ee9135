package org.tensim.scene.conditions;

import java.util.function.DoubleUnaryOperator;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;

/**
 * A field of active muscle fibres on membrane triangles ({@link org.tensim.model.ActiveFibre}: a membrane tension
 * {@code T = sigma_a(t) t} (N/m) along the fibre, t the thickness of muscle a triangle stands for), with the fibre
 * direction given per rest triangle by a {@link Direction} rule:
 * <ul>
 * <li>{@link #towards}: the meridian to a centre c about an axis a, {@code f = n x (a x r)} with n the triangle's
 * unit normal and r the unit direction from the axis through c to the triangle's centroid g (the part of g - c
 * across the axis): in the triangle's plane and across the circle about the axis, so radial on a face across the
 * axis and along the axis on a wall parallel to it. The diaphragm's fibres converge this way on the central tendon
 * (a the vertical; Gray's Anatomy, 41st ed., ch. 63; De Troyer and Boriek 2011, Compr. Physiol. 1:1273). Where
 * the triangle's plane holds the circle's direction ({@code |f| < }{@link #MIN_IN_PLANE}: a wall through the
 * axis), or g lies on the axis, the meridian is not defined and the triangle gets no fibre.</li>
 * <li>{@link #along}: a fixed direction d, projected on each triangle's plane ({@code ActiveFibre} uses the
 * in-plane part); a triangle whose plane is (almost) normal to d, in-plane part below {@link #MIN_IN_PLANE}
 * {@code |d|}, gets no fibre.</li>
 * </ul>
 * Only the fibre's line matters, not its sense (the tension acts both ways). The diaphragm's muscle
 * ({@code scene/diaphragm/MuscleFibres}) and a scene file's {@code fibres} condition are built by {@link #add}.
 */
public final class FibreField {
    /** Smallest accepted length of a triangle's fibre direction (unit inputs), 1: below it the triangle has none. */
    public static final double MIN_IN_PLANE = 0.05;

    private FibreField() {
    }

    /** A rule giving a rest triangle's fibre direction (any length, in its plane or not), or null for none. */
    @FunctionalInterface
    public interface Direction {
        /**
         * @param centroid the rest triangle's centroid, m
         * @param normal   its unit normal
         */
        Vec3 on(Vec3 centroid, Vec3 normal);
    }

    /** The meridian to {@code centre} (m) about {@code axis} (any length, not zero), as the class comment says. */
    public static Direction towards(Vec3 centre, Vec3 axis) {
        Vec3 a = axis.normalized();
        return (g, n) -> {
            Vec3 d = g.minus(centre);
            Vec3 r = d.minus(a.times(d.dot(a)));
            if (!(r.norm() > 0)) {
                return null;
            }
            Vec3 f = n.cross(a.cross(r.normalized()));
            return f.norm() < MIN_IN_PLANE ? null : f;
        };
    }

    /** The direction d (any length, not zero) on each triangle's plane, as the class comment says. */
    public static Direction along(Vec3 direction) {
        Vec3 d = direction.normalized();
        return (g, n) -> d.minus(n.times(d.dot(n))).norm() < MIN_IN_PLANE ? null : d;
    }

    /**
     * Adds the fibre of one triangle to t when its direction rule gives one.
     *
     * @param p          first node of each corner (3 ids)
     * @param q          second node of each corner (equal to p's for a plain triangle; corner k is their midpoint)
     * @param corners    the rest corners, m (the fibre's direction is taken on them; the fibre's rest shape is the
     *                   nodes', as {@link Topology#addFibre} takes it)
     * @param thicknessM the thickness of muscle the triangle stands for, m (&gt; 0)
     * @param stressPa   the active stress sigma_a(t), Pa; one object shared by a field's fibres, so that a force
     *                   pass evaluates it once
     * @return whether a fibre was added
     */
    public static boolean add(Topology t, int[] p, int[] q, Vec3[] corners, Direction dir, double thicknessM,
            DoubleUnaryOperator stressPa) {
        Vec3 g = corners[0].plus(corners[1]).plus(corners[2]).times(1.0 / 3);
        Vec3 n = corners[1].minus(corners[0]).cross(corners[2].minus(corners[0])).normalized();
        Vec3 f = dir.on(g, n);
        if (f == null) {
            return false;
        }
        t.addFibre(p, q, f, thicknessM, stressPa);
        return true;
    }
}

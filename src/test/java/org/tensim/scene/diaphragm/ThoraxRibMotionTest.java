package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Vec3;

/**
 * The thorax's rib kinematics on a rib of known geometry: a right rib (x &lt; 0; +Y posterior, +Z superior) from its
 * head beside the midline back and out, round and forwards, down to its anterior end 45 mm lateral, 100 mm anterior
 * and 80 mm below the head. Its rotation per tidal breath is Wilson et al.'s pump handle about the mediolateral
 * axis and bucket handle about the head-to-end chord (a true rib) or the antero-posterior axis (a false rib), each
 * times the tidal fraction.
 */
class ThoraxRibMotionTest {
    private static final Vec3 HEAD = new Vec3(-0.015, 0, 0);
    private static final Vec3 END = new Vec3(-0.060, -0.100, -0.080);
    /** The rib's most lateral point. */
    private static final Vec3 LATERAL = new Vec3(-0.100, -0.030, -0.030);

    /** A thin strip through the rib's points (each point and one 2 mm above it), mirrored to the left for side -1. */
    private static Bones.Bone rib(int index, int side) {
        Vec3[] p = {HEAD, new Vec3(-0.050, 0.020, -0.005), LATERAL, new Vec3(-0.080, -0.060, -0.045), END};
        double[] xyz = new double[6 * p.length];
        for (int i = 0; i < p.length; i++) {
            for (int k = 0; k < 2; k++) {
                xyz[6 * i + 3 * k] = side * p[i].x();
                xyz[6 * i + 3 * k + 1] = p[i].y();
                xyz[6 * i + 3 * k + 2] = p[i].z() + 0.002 * k;
            }
        }
        int[] tri = new int[6 * (p.length - 1)];
        for (int i = 0; i + 1 < p.length; i++) {
            int a = 2 * i;
            tri[6 * i] = a;
            tri[6 * i + 1] = a + 2;
            tri[6 * i + 2] = a + 1;
            tri[6 * i + 3] = a + 1;
            tri[6 * i + 4] = a + 2;
            tri[6 * i + 5] = a + 3;
        }
        return new Bones.Bone("rib", Bones.Kind.RIB, side > 0 ? Bones.Side.RIGHT : Bones.Side.LEFT, index,
                new TriangleMesh(xyz, tri));
    }

    private static final BreathingCycle CYCLE = BreathingCycle.quiet();

    /** The displacement at end-inspiration of a point of the rib, rotated with it (no translation along the axis). */
    private static Vec3 displacement(Bones.Bone rib, Vec3 point) {
        DiaphragmParameters d = DiaphragmParameters.defaults();
        DiaphragmParameters p = new DiaphragmParameters(d.densityKgPerM3(), d.muscleYoungPa(), d.tendonYoungPa(),
                d.highDampingRatio(), d.viscousPerS(), d.tendonAreaFraction(), d.tendonNormal(), d.tendonPoint(),
                d.attachThresholdM(), d.structureStiffness(), d.structureNodeMassKg(), d.attachStiffness(),
                d.ribQuietFraction(), 0, d.abdominalSupportPaPerM(), d.bendingFactor(), d.poissonRatio(),
                d.tissueModel());
        HelicalAxisMotion m = ThoraxCage.ribMotion(rib, 0, p, CYCLE, new DiaphragmControls(1, 0));
        double[] out = new double[3];
        m.position(CYCLE.inspirationS(), point, out, 0);
        return new Vec3(out[0], out[1], out[2]).minus(point);
    }

    @Test
    void theAnteriorEndOfATrueRibRisesAndGoesForwardsInItsSagittalPlane() {
        Vec3 u = displacement(rib(4, 1), END);
        // The pump handle alone moves the end: theta_p x (END - HEAD), theta_p = 10 deg x 0.17; the bucket handle
        // turns about the chord through the end. To first order: cranial theta_p 100 mm, ventral theta_p 80 mm (the
        // second order, half the square of the whole angle times 136 mm, is under 10 %).
        double pump = Math.toRadians(RibCage.wilsonDegrees(4)[0]) * ThoraxCage.TIDAL_FRACTION;
        assertEquals(pump * 0.100, u.z(), 0.1 * pump * 0.100, "cranial, m");
        assertEquals(-pump * 0.080, u.y(), 0.1 * pump * 0.080, "ventral (-y), m");
        assertEquals(0, u.x(), 0.1 * pump * 0.080, "not sideways, away from the sternum");
        assertTrue(u.z() > 0.002 && u.z() < 0.006, "2-6 mm cranially per tidal breath: " + u.z());
    }

    @Test
    void theLateralPartOfATrueRibRisesAndEverts() {
        Vec3 u = displacement(rib(4, 1), LATERAL);
        assertTrue(u.z() > 0, "rises: " + u);
        assertTrue(u.x() < 0, "moves outwards (right rib: -x): " + u);
    }

    @Test
    void aFalseRibsFreeEndMovesOutwards() {
        Vec3 u = displacement(rib(9, 1), END);
        assertTrue(u.x() < -0.5e-3, "the costal margin widens: " + u);
        assertTrue(u.z() > 0, "and rises: " + u);
    }

    @Test
    void theLeftRibMirrorsTheRight() {
        Vec3 right = displacement(rib(4, 1), LATERAL);
        Vec3 left = displacement(rib(4, -1), new Vec3(-LATERAL.x(), LATERAL.y(), LATERAL.z()));
        assertEquals(-right.x(), left.x(), 1e-12);
        assertEquals(right.y(), left.y(), 1e-12);
        assertEquals(right.z(), left.z(), 1e-12);
    }
}

package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Map;
import org.junit.jupiter.api.Test;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;

/** The project's own rib cage: its anatomy, its place on the dome, and the scene it gives. */
class ParametricRibCageTest {
    private static final ParametricRibCage.Dimensions D = ParametricRibCage.Dimensions.adult();
    private static final DoubleDomeGenerator.Shape DOME = DoubleDomeGenerator.Shape.adult();

    @Test
    void twelvePairsOfRibsOneVertebralLevelApartAndASternum() {
        Map<String, double[]> b = ParametricRibCage.adult();
        assertEquals(2 * 12 + 1, b.size());
        for (String side : new String[] {"r", "l"}) {
            for (int r = 1; r < 12; r++) {
                double spacing = (b.get("rib-" + side + r)[5] - b.get("rib-" + side + (r + 1))[5]) * 1e3;
                // a thoracic body (17-23 mm) plus a disc (4.5-7.2 mm)
                assertTrue(spacing >= 21.5 && spacing <= 30.2, "rib " + r + " to " + (r + 1) + ": " + spacing + " mm");
            }
        }
        double widest = 0;
        int widestRib = 0;
        for (int r = 1; r <= 12; r++) {
            double[] right = b.get("rib-r" + r);
            double[] left = b.get("rib-l" + r);
            assertEquals(-right[3], left[0], 1e-12, "symmetric, rib " + r);
            assertEquals(-right[0], left[3], 1e-12, "symmetric, rib " + r);
            assertTrue(right[2] < right[5] && right[1] < right[4], "rib " + r + " descends and has depth");
            if (left[3] > widest) {
                widest = left[3];
                widestRib = r;
            }
        }
        assertTrue(widestRib == 7 || widestRib == 8, "Gray: the ribs lengthen down to the seventh; widest " + widestRib);
        assertEquals(274, 2 * widest * 1e3, 2, "transverse extent, mm");
    }

    @Test
    void theSternumIsSeventeenCentimetresLongAndEndsOnTheDomesAnteriorRim() {
        Topology t = new Topology();
        RibCage cage = RibCage.build(t, new SpringList(), ParametricRibCage.adult(), DiaphragmParameters.defaults(),
                BreathingCycle.quiet(), new DiaphragmControls(1, 0));
        int[] s = cage.sternumNodes();
        Vec3 top = t.node(s[0]).position();
        Vec3 xiphoid = t.node(s[s.length - 1]).position();
        assertEquals(0.170, top.distance(xiphoid), 1e-9, "sternum length, m (Gray: about 17 cm)");
        double inclination = Math.toDegrees(Math.atan2(top.y() - xiphoid.y(), top.z() - xiphoid.z()));
        assertEquals(D.sternumInclinationDeg(), inclination, 1e-9, "top further back than the xiphoid");
        // the rim of the generated dome rises to the xiphoid at its front
        assertEquals(DOME.centreY() - DOME.semiAxisY(), xiphoid.y(), 1e-12);
        assertEquals(DOME.rimLateral() + DOME.rimAnteriorRise(), xiphoid.z(), 1e-12);
        // the true ribs' cartilage reaches the sternum; the false ribs' the rib above; the floating ribs' nothing
        long cartilage = cage.segments().stream().filter(g -> g.kind() == RibCage.Kind.CARTILAGE).count();
        assertEquals(2 * (7 * 2 + 3), cartilage);
    }

    @Test
    void theDomeSitsInsideTheCage() {
        Map<String, double[]> b = ParametricRibCage.adult();
        // the dome's footprint lies within the widest ribs and between the sternum and the rib angles
        double halfWidth = b.get("rib-l8")[3];
        assertTrue(DOME.semiAxisX() < halfWidth, DOME.semiAxisX() + " m inside " + halfWidth + " m");
        double front = b.get("sternum")[1];
        double back = b.get("rib-l7")[4];
        assertTrue(front < DOME.centreY() - DOME.semiAxisY() + 1e-12 && DOME.centreY() + DOME.semiAxisY() < back);
        // its lowest rim (the sides, 1015 mm) is above the lowest rib's end and below rib 7's head
        assertTrue(b.get("rib-l12")[2] < DOME.rimLateral() + 0.01 && DOME.rimLateral() < b.get("rib-l7")[5]);
    }

    @Test
    void theDefaultSceneAttachesItsRimToRibsSternumAndSpine() throws Exception {
        DiaphragmScene s = SceneFixture.coarse(12, 1, DiaphragmSetup.defaultMusclePa());
        assertTrue(s.attachedToRibs() > 50, "ribs: " + s.attachedToRibs());
        assertTrue(s.attachedToCartilage() > 20, "cartilage and sternum: " + s.attachedToCartilage());
        assertTrue(s.attachedToSpine() > 5, "spine (crura): " + s.attachedToSpine());
    }

    @Test
    void badDimensionsAreRefusedWithTheValue() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new ParametricRibCage.Dimensions(22, 30, D.endDropLevels(), D.halfWidthMm(), D.depthMm(),
                        D.angleOffsetMm(), 15, 170, 75, 54, 21, 202));
        assertTrue(e.getMessage().contains("sternum inclination 75.0"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
                () -> new ParametricRibCage.Profile(1, 12, 2, 3, 2));
        assertTrue(e.getMessage().contains("peak rib 12.0"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
                () -> new ParametricRibCage.Dimensions(22, 30, D.endDropLevels(),
                        new ParametricRibCage.Profile(10, 7.5, 137, 87, 2), D.depthMm(), D.angleOffsetMm(), 15, 170,
                        18.5, 54, 21, 202));
        assertTrue(e.getMessage().startsWith("rib 1:"), e.getMessage());
    }
}

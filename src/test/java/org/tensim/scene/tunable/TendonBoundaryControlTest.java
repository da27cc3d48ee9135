package org.tensim.scene.tunable;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.scene.diaphragm.TendonRule;

/**
 * The control that moves the tendon's boundary: the plane's height with the plane rule, the area share with the
 * geodesic rule, each a parameter that rebuilds the scene through its spec; the tendon grows and shrinks with it.
 */
class TendonBoundaryControlTest {
    private static final DiaphragmSpec COARSE = DiaphragmSpec.defaults().withMesh(DiaphragmSpec.Mesh.defaults()
            .withRings(10));

    private static double tendonShare(SceneFactory f, String key, double value) {
        DiaphragmViewScene s = (DiaphragmViewScene) f.create(true, Map.of(key, value));
        return s.scene().tendonAreaFraction();
    }

    private static TunableParameter parameter(List<TunableParameter> ps, String key) {
        return ps.stream().filter(p -> p.key().equals(key)).findFirst().orElse(null);
    }

    @Test
    void raisingThePlaneShrinksTheTendonAndZeroIsTheDefaultShare() {
        SceneFactory f = DiaphragmViewScene.factory(COARSE.withTendonRule(TendonRule.PLANE));
        TunableParameter plane = parameter(f.create(true).parameters(), DiaphragmViewScene.TENDON_PLANE);
        assertTrue(plane != null && plane.restarts() && plane.defaultValue() == 0 && "mm".equals(plane.unit()),
                String.valueOf(plane));
        assertEquals(null, parameter(f.create(true).parameters(), DiaphragmViewScene.TENDON_SHARE));
        double atDefault = ((DiaphragmViewScene) f.create(true)).scene().tendonAreaFraction();
        assertEquals(atDefault, tendonShare(f, DiaphragmViewScene.TENDON_PLANE, 0), 0);
        double previous = 1;
        for (double mm : new double[] {-12, -6, 0, 6, 12}) {
            double share = tendonShare(f, DiaphragmViewScene.TENDON_PLANE, mm);
            assertTrue(share < previous, "plane at " + mm + " mm: tendon share " + share + " after " + previous);
            previous = share;
        }
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> f.create(true, Map.of(DiaphragmViewScene.TENDON_PLANE, DiaphragmViewScene.TENDON_PLANE_RANGE_MM)));
        assertTrue(e.getMessage().contains("above the upper surface") && e.getMessage().contains("no tendon"),
                e.getMessage());
    }

    @Test
    void aLargerShareGivesALargerGeodesicTendonNearTheShareAskedForByDefault() {
        SceneFactory f = DiaphragmViewScene.factory(COARSE);
        assertEquals(TendonRule.GEODESIC, COARSE.tendonRule(), "the default rule");
        TunableParameter share = parameter(f.create(true).parameters(), DiaphragmViewScene.TENDON_SHARE);
        assertTrue(share != null && share.restarts() && share.defaultValue() == 0.12, String.valueOf(share));
        assertEquals(null, parameter(f.create(true).parameters(), DiaphragmViewScene.TENDON_PLANE));
        assertEquals(f.parameters(org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad.FIBRES).stream().map(TunableParameter::key).toList(),
                f.create(true).parameters().stream().map(TunableParameter::key).toList(),
                "the factory's parameters for a muscle load name the same controls as its scenes'");
        double previous = 0;
        for (double asked : new double[] {0.06, 0.12, 0.2, 0.3}) {
            double got = tendonShare(f, DiaphragmViewScene.TENDON_SHARE, asked);
            assertTrue(got > previous, "share " + asked + ": tendon " + got + " after " + previous);
            assertEquals(asked, got, 0.05, "the tendon covers about the share asked for");
            previous = got;
        }
    }

    @Test
    void aLabelFileSetsTheTendonSoNeitherControlIsOffered() {
        List<TunableParameter> ps = DiaphragmViewScene.parameters(
                org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad.FIBRES, TendonRule.GEODESIC, true);
        assertFalse(ps.stream().anyMatch(p -> p.key().startsWith("tendon")), ps.toString());
        assertTrue(DiaphragmViewScene.PARAMETERS.stream().anyMatch(p -> p.key().equals(
                DiaphragmViewScene.TENDON_SHARE)), "the sweeps' list: the default (geodesic) rule's");
        assertFalse(DiaphragmViewScene.PARAMETERS.stream().anyMatch(p -> p.key().equals(
                DiaphragmViewScene.TENDON_PLANE)), "the sweeps' list: not the plane's");
    }
}

package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.function.Supplier;
import org.junit.jupiter.api.Test;

/**
 * The scene definition's breathing and cage values: each copy changes its one value, and a bad value is refused
 * where it enters, with the value in the message.
 */
class DiaphragmSpecValuesTest {
    private static void refused(String value, Supplier<Object> make) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, make::get);
        assertTrue(e.getMessage().contains(value), e.getMessage());
    }

    @Test
    void breathingCopiesChangeOneValueAndRefuseBadOnes() {
        DiaphragmSpec.Breathing b = DiaphragmSpec.Breathing.defaults();
        assertEquals(new DiaphragmSpec.Breathing(5, 2, 1, null), b.withPeriod(5));
        assertEquals(new DiaphragmSpec.Breathing(4, 3, 1, null), b.withExpirationRatio(3));
        assertEquals(new DiaphragmSpec.Breathing(4, 2, 0.5, null), b.withRibAmplitude(0.5));
        assertEquals(new DiaphragmSpec.Breathing(4, 2, 1, 12_000.0), b.withMusclePa(12_000.0));
        assertEquals(5.0 / 3, b.withPeriod(5).cycle().inspirationS(), 1e-12);
        refused("-1", () -> b.withPeriod(-1));
        refused("0", () -> b.withExpirationRatio(0));
        refused("5", () -> b.withRibAmplitude(5));
        refused("-10", () -> b.withMusclePa(-10.0));
    }

    @Test
    void cageCopiesChangeOneValueAndRefuseBadOnes() {
        DiaphragmSpec.Cage c = DiaphragmSpec.Cage.defaults();
        assertEquals(1e8, c.withContactStiffness(1e8).contactStiffnessPaPerM());
        assertEquals(c.contact(), c.withContactStiffness(1e8).contact());
        refused("0", () -> c.withContactStiffness(0));
        assertEquals(2e4, c.withLiverSupport(2e4).liverSupportPaPerM());
        assertEquals(c.contactStiffnessPaPerM(), c.withLiverSupport(2e4).contactStiffnessPaPerM());
        assertEquals(0, c.withLiverSupport(0).liverSupportPaPerM()); // off
        refused("-1", () -> c.withLiverSupport(-1));
        refused("--thorax", () -> c.withBoxes(java.nio.file.Path.of("b.json")).withThorax(java.nio.file.Path.of("t")));
        assertTrue(!c.surfaces() && !c.boneSurfaces(), "the default cage is the band's segments");
        assertEquals(c.withContactStiffness(1e8).withSurfaces(true), c.withSurfaces(true).withContactStiffness(1e8));
        assertTrue(c.withSurfaces(true).boneSurfaces() && c.withThorax(java.nio.file.Path.of("t")).boneSurfaces());
    }
}

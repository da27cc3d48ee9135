package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class BreathingCycleTest {
    @Test
    void levelRisesDuringInspirationAndFallsDuringExpirationWithTheIeRatio() {
        BreathingCycle c = new BreathingCycle(4, 2);
        assertEquals(4.0 / 3, c.inspirationS(), 1e-12);
        assertEquals(0, c.level(0), 1e-12);
        assertEquals(1, c.level(c.inspirationS()), 1e-12);
        assertEquals(0, c.level(4), 1e-12);
        assertEquals(0.5, c.level(c.inspirationS() / 2), 1e-12);
        assertEquals(0.5, c.level(c.inspirationS() + (4 - c.inspirationS()) / 2), 1e-12);
        assertEquals(c.level(0.7), c.level(8.7), 1e-12, "periodic");
        double prev = -1;
        for (double t = 0; t <= c.inspirationS(); t += 0.01) {
            assertTrue(c.level(t) >= prev);
            prev = c.level(t);
        }
        prev = 1;
        for (double t = c.inspirationS(); t <= 4; t += 0.01) {
            assertTrue(c.level(t) <= prev + 1e-12);
            prev = c.level(t);
        }
        // continuous velocity at the switch: one-sided slopes both about zero
        double h = 1e-6;
        double ti = c.inspirationS();
        assertEquals(0, (c.level(ti) - c.level(ti - h)) / h, 1e-4);
        assertEquals(0, (c.level(ti + h) - c.level(ti)) / h, 1e-4);
    }

    @Test
    void badValuesAreRefusedWithTheirName() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new BreathingCycle(0, 2));
        assertTrue(e.getMessage().contains("breathing period"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> new BreathingCycle(4, -1));
        assertTrue(e.getMessage().contains("I:E"), e.getMessage());
    }
}

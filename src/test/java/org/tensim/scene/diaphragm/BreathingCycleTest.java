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
    void theEndExpiratoryPauseHoldsRestAfterAShorterExpirationWithContinuousVelocity() {
        BreathingCycle c = BreathingCycle.quiet();
        double ti = c.inspirationS();
        double tx = (1 - BreathingCycle.QUIET_PAUSE_SHARE) * (4 - ti); // 2 s of the 2.67 s expiration
        assertEquals(2.0, tx, 1e-12);
        assertEquals(1, c.level(ti), 1e-12);
        assertEquals(0.5, c.level(ti + tx / 2), 1e-12);
        for (double t = ti + tx; t <= 4; t += 0.01) {
            assertEquals(0, c.level(t), 0, "at rest in the pause, t = " + t);
        }
        double h = 1e-6;
        assertEquals(0, (c.level(ti + tx) - c.level(ti + tx - h)) / h, 1e-4, "velocity into the pause");
        // The inspiration is the pause-free law's.
        BreathingCycle plain = new BreathingCycle(4, 2);
        for (double t = 0; t <= ti; t += 0.05) {
            assertEquals(plain.level(t), c.level(t), 1e-15);
        }
        // The DIR-Lab cases' shares of end-inhale 10-40 % of the cycle after end-inhale (docs/lungs.md: ranges of the
        // five cases 0.65-0.99, 0.28-0.69, 0.07-0.41, 0.03-0.17): the quiet law lies within them, the pause-free one
        // not at 30 % and 40 %.
        double[][] range = {{0.65, 0.99}, {0.28, 0.69}, {0.07, 0.41}, {0.03, 0.17}};
        for (int k = 1; k <= 4; k++) {
            double share = c.level(ti + 0.1 * k * 4);
            assertTrue(share >= range[k - 1][0] && share <= range[k - 1][1], "t" + k + "0 share " + share);
        }
        assertTrue(plain.level(ti + 1.2) > 0.41 && plain.level(ti + 1.6) > 0.17, "the pause-free law is later");
    }

    @Test
    void badValuesAreRefusedWithTheirName() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new BreathingCycle(0, 2));
        assertTrue(e.getMessage().contains("breathing period"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> new BreathingCycle(4, -1));
        assertTrue(e.getMessage().contains("I:E"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> new BreathingCycle(4, 2, 1));
        assertTrue(e.getMessage().contains("end-expiratory pause") && e.getMessage().contains("got 1.0"),
                e.getMessage());
    }
}

package org.tensim.scene.tunable;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class TunableParameterTest {
    final TunableParameter k = TunableParameter.log("stiffnessNPerM", "Stiffness", "N/m", 10, 10000, 100, "k");
    final TunableParameter c = TunableParameter.linear("dampingNsPerM", "Damping", "N s/m", 0, 50, 2, "c");

    @Test
    void validationNamesParameterValueUnitAndRange() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> k.validate(5, "p.json"));
        String m = e.getMessage();
        assertTrue(m.startsWith("p.json: Stiffness (stiffnessNPerM)"), m);
        assertTrue(m.contains("between 10 and 10000 N/m") && m.endsWith("got 5.0"), m);
        assertThrows(IllegalArgumentException.class, () -> c.validate(Double.POSITIVE_INFINITY, null));
        assertEquals(50, c.validate(50, null));
    }

    @Test
    void sliderScalesRoundTrip() {
        assertEquals(1.0 / 3, k.toFraction(100), 1e-12, "log scale: 100 is a third of the way from 10 to 10000");
        assertEquals(100, k.fromFraction(1.0 / 3), 1e-9);
        assertEquals(0.04, c.toFraction(2), 1e-12);
        for (double f = 0; f <= 1; f += 0.125) {
            assertEquals(f, k.toFraction(k.fromFraction(f)), 1e-12);
            assertEquals(f, c.toFraction(c.fromFraction(f)), 1e-12);
        }
        assertEquals(10000, k.fromFraction(7), "clamped");
    }

    @Test
    void badDescriptorsAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> TunableParameter.log("a", "A", "", 0, 1, 0.5, ""));
        assertThrows(IllegalArgumentException.class, () -> TunableParameter.linear("a", "A", "", 1, 1, 1, ""));
        assertThrows(IllegalArgumentException.class, () -> TunableParameter.linear("a", "A", "", 0, 1, 2, ""));
        assertThrows(IllegalArgumentException.class, () -> TunableParameter.linear("a b", "A", "", 0, 1, 0, ""));
    }

    @Test
    void formatIsShortAndPlain() {
        assertEquals("10000", TunableParameter.format(10000));
        assertEquals("0.001", TunableParameter.format(1e-3));
        assertEquals("0.25", TunableParameter.format(0.25));
        assertEquals("123.5", TunableParameter.format(123.456));
    }
}

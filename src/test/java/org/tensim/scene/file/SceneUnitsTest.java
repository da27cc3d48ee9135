package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Values with units become SI; bare numbers take the units: block's unit; other dimensions are refused. */
class SceneUnitsTest {
    static SceneNode value(String text) {
        return SceneNode.scalar(SceneNode.Token.STRING, text, "t.yaml:1:1", "k");
    }

    static double si(SceneUnits u, String text, QuantityKind k) {
        return u.si(value(text), k);
    }

    @Test
    void unitsAreConvertedToSi() {
        SceneUnits u = new SceneUnits();
        assertEquals(3000, si(u, "3 kPa", QuantityKind.PRESSURE), 1e-9);
        assertEquals(0.0025, si(u, "2.5 mm", QuantityKind.LENGTH), 1e-15);
        assertEquals(1050, si(u, "1050 kg/m^3", QuantityKind.DENSITY), 1e-9);
        assertEquals(1050, si(u, "1050 kg/m³", QuantityKind.DENSITY), 1e-9);
        assertEquals(1050, si(u, "1.05 g/cm^3", QuantityKind.DENSITY), 1e-9);
        assertEquals(2, si(u, "2 N*s/m", QuantityKind.DAMPING), 1e-12);
        assertEquals(2, si(u, "2 N·s/m", QuantityKind.DAMPING), 1e-12);
        assertEquals(9.81, si(u, "9.81 m/s^2", QuantityKind.ACCELERATION), 1e-12);
        assertEquals(1e5, si(u, "100 N/mm", QuantityKind.STIFFNESS), 1e-6);
        assertEquals(0.001, si(u, "1e-3 s", QuantityKind.TIME), 0, "an exponent is the number's, not lost");
        assertEquals(0.001, si(u, "1 ms", QuantityKind.TIME), 1e-18);
        assertEquals(120, si(u, "2 min", QuantityKind.TIME), 1e-12);
        assertEquals(0.25, si(u, "0.25 Hz", QuantityKind.FREQUENCY), 0);
        assertEquals(0.25, si(u, "0.25 s^-1", QuantityKind.FREQUENCY), 1e-15);
        assertThrows(SceneException.class, () -> si(u, "0.25 1/s", QuantityKind.FREQUENCY), "indriya has no 1/s");
        assertEquals(-4.5, si(u, "-4.5", QuantityKind.NUMBER), 0);
        // SI values are passed through unchanged, to the bit.
        assertEquals(0.052335956242943835, si(u, "0.052335956242943835 N", QuantityKind.FORCE), 0);
    }

    @Test
    void bareNumbersTakeTheFilesUnitsOrSi() {
        SceneNode block = SceneNode.map("t.yaml:1:1", "units");
        block.put("length", value("mm"));
        block.put("pressure", value("kPa"));
        SceneUnits u = SceneUnits.read(block);
        assertEquals(0.0025, si(u, "2.5", QuantityKind.LENGTH), 1e-15);
        assertEquals(3000, si(u, "3", QuantityKind.PRESSURE), 1e-9);
        assertEquals(2.5, si(u, "2.5 m", QuantityKind.LENGTH), 0, "a unit given wins over the default");
        assertEquals(7, si(u, "7", QuantityKind.MASS), 0, "kinds not in the block are SI");
        assertEquals(7, si(new SceneUnits(), "7", QuantityKind.LENGTH), 0);
    }

    @Test
    void wrongDimensionsAndUnknownUnitsAreRefused() {
        SceneUnits u = new SceneUnits();
        SceneException e = assertThrows(SceneException.class, () -> si(u, "3 kPa/m", QuantityKind.PRESSURE));
        assertEquals("t.yaml:1:1: k: \"3 kPa/m\" is not a pressure (expected a value in Pa, e.g. \"2 kPa\")",
                e.getMessage());
        assertThrows(SceneException.class, () -> si(u, "3 kPa", QuantityKind.FORCE));
        assertThrows(SceneException.class, () -> si(u, "3 m", QuantityKind.NUMBER));
        assertTrue(assertThrows(SceneException.class, () -> si(u, "3 furlongs", QuantityKind.LENGTH)).getMessage()
                .contains("unknown unit \"furlongs\""));
        assertThrows(SceneException.class, () -> si(u, "N 3", QuantityKind.FORCE));
        SceneNode block = SceneNode.map("t.yaml:1:1", "units");
        block.put("force", value("kPa"));
        assertThrows(SceneException.class, () -> SceneUnits.read(block));
    }
}

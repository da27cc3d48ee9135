package org.tensim.scene.shell;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Material parameters are refused out of range with their name and unit; derived rigidities. */
class ShellMaterialTest {
    private static void refused(String name, String unit, Runnable make) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, make::run);
        assertTrue(e.getMessage().contains(name) && e.getMessage().contains(unit), e.getMessage());
    }

    @Test
    void outOfRangeValuesAreRefusedWithNameAndUnit() {
        refused("Young's modulus E", "Pa", () -> new ShellMaterial(0, 0.3, 0.002, 1000));
        refused("Young's modulus E", "Pa", () -> new ShellMaterial(-1, 0.3, 0.002, 1000));
        refused("Poisson's ratio nu", "(-1, 0.5)", () -> new ShellMaterial(1e4, 0.5, 0.002, 1000));
        refused("Poisson's ratio nu", "(-1, 0.5)", () -> new ShellMaterial(1e4, -1, 0.002, 1000));
        refused("Poisson's ratio nu", "(-1, 0.5)", () -> new ShellMaterial(1e4, Double.NaN, 0.002, 1000));
        refused("shell thickness t", "m", () -> new ShellMaterial(1e4, 0.3, 0, 1000));
        refused("density rho", "kg/m^3", () -> new ShellMaterial(1e4, 0.3, 0.002, -5));
    }

    @Test
    void bendingRigidityIsKirchhoffs() {
        ShellMaterial m = new ShellMaterial(40e3, 0.45, 0.0025, 1060);
        assertEquals(40e3 * Math.pow(0.0025, 3) / (12 * (1 - 0.45 * 0.45)), m.bendingRigidityNm(), 1e-12 * m.bendingRigidityNm());
        assertEquals(100, m.membraneNPerM(), 1e-12);
    }

    @Test
    void facesCarryAThirdOfTheMembraneAtPoissonOneThird() {
        SandwichShell s = SandwichShell.of(new ShellMaterial(1e4, 1.0 / 3, 0.002, 1000), 0.002);
        assertEquals(1.0 / 6, s.faceShare(), 1e-12, "2 c E t (s/2)^2 / (1 - 1/9) = E t^3 / (12 (1 - 1/9))");
        assertEquals(2.0 / 3, s.diagonalShare(), 1e-12);
        // Faces twice as far apart need a quarter of the stiffness for the same D.
        assertEquals(1.0 / 24, SandwichShell.of(new ShellMaterial(1e4, 1.0 / 3, 0.002, 1000), 0.004).faceShare(), 1e-12);
        assertThrows(IllegalArgumentException.class,
                () -> SandwichShell.of(new ShellMaterial(1e4, 1.0 / 3, 0.002, 1000), 0.001));
    }
}

package org.tensim.scene.shell;

import org.tensim.model.Check;

/**
 * An isotropic linear-elastic shell material, SI units, validated where it enters.
 *
 * @param youngPa        Young's modulus E, Pa (&gt; 0; resting diaphragm muscle about 30-45 kPa)
 * @param poisson        Poisson's ratio nu, in (-1, 0.5) (soft tissue 0.45-0.49: nearly incompressible)
 * @param thicknessM     shell thickness t, m (&gt; 0; diaphragm 1.9 +/- 0.4 mm by ultrasound)
 * @param densityKgPerM3 density rho, kg/m^3 (&gt; 0; soft tissue about 1060)
 */
public record ShellMaterial(double youngPa, double poisson, double thicknessM, double densityKgPerM3) {
    public ShellMaterial {
        Check.positive("Young's modulus E", "Pa", youngPa);
        if (!(poisson > -1 && poisson < 0.5)) {
            throw new IllegalArgumentException("Poisson's ratio nu must be in (-1, 0.5) (dimensionless), got "
                    + poisson);
        }
        Check.positive("shell thickness t", "m", thicknessM);
        Check.positive("density rho", "kg/m^3", densityKgPerM3);
    }

    /** Kirchhoff bending rigidity {@code D = E t^3 / (12 (1 - nu^2))}, N m. */
    public double bendingRigidityNm() {
        return youngPa * thicknessM * thicknessM * thicknessM / (12 * (1 - poisson * poisson));
    }

    /** Membrane (in-plane) Young's modulus times thickness, {@code E t}, N/m. */
    public double membraneNPerM() {
        return youngPa * thicknessM;
    }

    /** The same material with another Poisson's ratio. */
    public ShellMaterial withPoisson(double nu) {
        return new ShellMaterial(youngPa, nu, thicknessM, densityKgPerM3);
    }

    /** The same material with another thickness, m. */
    public ShellMaterial withThickness(double m) {
        return new ShellMaterial(youngPa, poisson, m, densityKgPerM3);
    }
}

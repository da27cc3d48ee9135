package org.tensim.scene.volume;

import org.tensim.model.Check;

/**
 * Everything a volume body is built from besides its surface: one plain definition with named defaults
 * ({@link #of}), validated where it enters.
 *
 * @param cellSizeM       side h of the lattice's cubic cells, m (&gt; 0)
 * @param youngPa         Young's modulus E, Pa (&gt; 0)
 * @param poisson         Poisson's ratio nu asked for (what the lattice gives: {@link LatticeMaterial#modelPoisson})
 * @param densityKgPerM3  rho, kg/m^3 (&gt; 0)
 * @param dampingTimeS    stiffness-proportional damping time beta, s (&gt;= 0): each spring of stiffness k gets the
 *                        axial damping {@code c = beta k} (N s/m), Kelvin-Voigt damping at the rate 1/beta
 * @param fit             which elastic constants the springs reproduce ({@link SpringFit})
 * @param fillSamples     sample points per axis of a cell the surface crosses, for its inside fraction
 *                        ({@code fillSamples^3} winding-number queries a cell; 1 to 16)
 */
public record VolumeParameters(double cellSizeM, double youngPa, double poisson, double densityKgPerM3,
        double dampingTimeS, SpringFit fit, int fillSamples) {
    /** Default sample points per axis of a crossed cell: 4 (64 a cell, an inside fraction to 1/64). */
    public static final int DEFAULT_FILL_SAMPLES = 4;

    public VolumeParameters {
        Check.positive("volume cell size", "m", cellSizeM);
        Check.positive("volume density", "kg/m^3", densityKgPerM3);
        Check.nonNegative("volume damping time", "s", dampingTimeS);
        if (fillSamples < 1 || fillSamples > 16) {
            throw new IllegalArgumentException("volume fill samples per cell axis must be 1 to 16, got "
                    + fillSamples);
        }
        new LatticeMaterial(youngPa, poisson, fit); // validates E, nu and the fit together
    }

    /** The isotropic fit, no damping, {@value #DEFAULT_FILL_SAMPLES} fill samples per axis. */
    public static VolumeParameters of(double cellSizeM, double youngPa, double poisson, double densityKgPerM3) {
        return new VolumeParameters(cellSizeM, youngPa, poisson, densityKgPerM3, 0, SpringFit.ISOTROPIC,
                DEFAULT_FILL_SAMPLES);
    }

    /** The same with another cell size, m. */
    public VolumeParameters withCellSize(double m) {
        return new VolumeParameters(m, youngPa, poisson, densityKgPerM3, dampingTimeS, fit, fillSamples);
    }

    /** The same with another spring fit. */
    public VolumeParameters withFit(SpringFit f) {
        return new VolumeParameters(cellSizeM, youngPa, poisson, densityKgPerM3, dampingTimeS, f, fillSamples);
    }

    /** The same with another damping time, s. */
    public VolumeParameters withDampingTime(double s) {
        return new VolumeParameters(cellSizeM, youngPa, poisson, densityKgPerM3, s, fit, fillSamples);
    }

    /** The same with another number of fill samples per cell axis (1 to 16). */
    public VolumeParameters withFillSamples(int n) {
        return new VolumeParameters(cellSizeM, youngPa, poisson, densityKgPerM3, dampingTimeS, fit, n);
    }

    /** The springs' material. */
    public LatticeMaterial material() {
        return new LatticeMaterial(youngPa, poisson, fit);
    }
}

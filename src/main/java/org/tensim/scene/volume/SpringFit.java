package org.tensim.scene.volume;

import java.util.Locale;

/**
 * Which elastic constants a lattice of central springs reproduces. Central springs between the nodes of a cubic
 * lattice obey Cauchy's relation {@code C12 = C44}: an isotropic spring lattice has Poisson's ratio 1/4 whatever its
 * stiffnesses (Golec et al. 2020, The Visual Computer 36: 809-825), so a requested nu other than 1/4 can only be
 * met in part by springs alone; the volumetric fit adds a volume term a cell. See {@link LatticeMaterial} for the
 * formulas and docs/volume.md for what each gives.
 */
public enum SpringFit {
    /**
     * Isotropic, with Young's modulus E: {@code C11 = 6E/5}, {@code C12 = C44 = 2E/5} (Lamé lambda = mu = 2E/5).
     * The model's Poisson ratio is 1/4 whatever nu is asked for; its shear modulus is 2E/5 and its bulk modulus 2E/3.
     */
    ISOTROPIC,
    /**
     * Cubic, matching a tensile test along each lattice axis (the test of Baudet et al. 2009): {@code C11 = lambda +
     * 2 mu} and {@code C12 = lambda} of the isotropic (E, nu), so that E, nu along the axes and the bulk modulus
     * {@code E / (3 (1 - 2 nu))} are exact; the shear modulus is then {@code C44 = lambda} instead of mu (too stiff
     * for nu above 1/4, too soft below) and Young's modulus off the axes differs from E. Needs nu in (0, 1/2).
     */
    AXIAL,
    /**
     * Isotropic with the requested E and nu: the isotropic spring lattice of shear modulus mu ({@code C11 = 3 mu},
     * {@code C12 = C44 = mu}) and, in each cell, a penalty on its volume change of modulus {@code lambda - mu}
     * ({@link org.tensim.model.VolumeElement}), which adds to C11 and C12 what Cauchy's relation denies the springs.
     * Exact under homogeneous strain. Needs nu in [1/4, 1/2); a lattice only (not the tetrahedral variant).
     */
    VOLUMETRIC;

    /** The name a scene file or command line uses: {@code isotropic}, {@code axial} or {@code volumetric}. */
    public String key() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** Parses a fit's {@link #key} (case-insensitive); anything else is refused, naming the choices. */
    public static SpringFit parse(String s) {
        if (s != null) {
            for (SpringFit f : values()) {
                if (f.key().equals(s.trim().toLowerCase(Locale.ROOT))) {
                    return f;
                }
            }
        }
        throw new IllegalArgumentException("spring fit must be 'isotropic', 'axial' or 'volumetric', got '" + s + "'");
    }
}

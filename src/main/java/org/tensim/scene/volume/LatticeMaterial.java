package org.tensim.scene.volume;

import org.tensim.model.Check;

/**
 * The springs of one cubic cell of side h from Young's modulus and Poisson's ratio: the identification of a volume
 * lattice. Each cell owns its 12 edges, 12 face diagonals and 4 body diagonals; a spring shared by several cells
 * (an edge by up to 4, a face diagonal by 2) gets the sum of their shares, as finite elements are assembled.
 *
 * <p>Following Lloyd, Székely and Harders (2007, IEEE TVCG 13(5): 1081-1094), the springs are chosen so that the
 * lattice's energy under any homogeneous strain equals that of a linear elastic reference. A spring of rest length
 * L along the unit vector n stores {@code k (L n.eps.n)^2 / 2} under a small strain eps, so a cell of volume h^3
 * has the elasticity tensor {@code C_ijkl = sum k L^2 n_i n_j n_k n_l / h^3}. With per-cell shares k_e (edges),
 * k_f (face diagonals) and k_b (body diagonals), the lattice is cubic with
 * <pre>
 *   C11 = (4 k_e + 4 k_f + 4 k_b / 3) / h,    C12 = C44 = (2 k_f + 4 k_b / 3) / h.
 * </pre>
 * {@code C12 = C44} is Cauchy's relation, which every lattice of central springs at rest obeys: it leaves one
 * free choice fewer than an isotropic material needs (see {@link SpringFit}). Given the target C11 and C12, the face
 * diagonals carry a share s of C12 and the body diagonals the rest:
 * <pre>
 *   k_f = s C12 h / 2,    k_b = 3 (1 - s) C12 h / 4,    k_e = (C11 - C12 - s C12) h / 4,
 * </pre>
 * with {@code s = min(1, (C11 - C12) / (2 C12))}: the face diagonals take as much of C12 as they can while the
 * edges keep at least half of what C11 - C12 allows them. For the isotropic fit s = 1: no body diagonals, edges
 * {@code k_e = E h / 10} and face diagonals {@code k_f = E h / 5} (the lattice of nearest and next-nearest
 * neighbours). Measured on the cantilever of docs/volume.md, moving C12 from the body to the face diagonals
 * lowers the tip deflection's error (at 8 cells across: 2.1 % with s = 0.05, 1.75 % with 0.5, 1.33 % with 1).
 * Edges and face diagonals make every cell rigid on its own (a box of rigid faces), so a clipped lattice's lone
 * cells have no mechanism. For bricks, Baudet et al. (2009, "Integrating tensile parameters in hexahedral
 * mass-spring system for simulation", WSCG) set a cell's springs from a tensile test along its axes; the
 * {@link SpringFit#AXIAL} fit matches that test. Homogeneous strain is reproduced exactly, whatever h.
 *
 * <p>The {@link SpringFit#VOLUMETRIC} fit adds to each cell a penalty on its volume change
 * ({@link org.tensim.model.VolumeElement}, modulus {@link #volumetricModulusPa}), which adds to Lamé's lambda what
 * central springs cannot: the springs are the isotropic lattice of shear modulus mu ({@code C11 = 3 mu},
 * {@code C12 = C44 = mu}) and the cell's term {@code K = lambda - mu}, so that the cell holds the isotropic material
 * of the requested E and nu exactly ({@code C11 = lambda + 2 mu}, {@code C12 = lambda}, {@code C44 = mu}).
 *
 * @param youngPa E, Pa (&gt; 0)
 * @param poisson nu requested (in (-1, 1/2) for the isotropic fit, which gives 1/4 anyway; in (0, 1/2) for the
 *                axial; in [1/4, 1/2) for the volumetric)
 * @param fit     which constants are reproduced
 */
public record LatticeMaterial(double youngPa, double poisson, SpringFit fit) {
    public LatticeMaterial {
        Check.positive("volume Young's modulus", "Pa", youngPa);
        Check.finite("volume Poisson ratio", "", poisson);
        if (fit == null) {
            throw new IllegalArgumentException("volume spring fit must be given: isotropic, axial or volumetric");
        }
        if (fit == SpringFit.VOLUMETRIC) {
            if (!(poisson >= 0.25 && poisson < 0.5)) {
                throw new IllegalArgumentException("volume Poisson ratio must be in [0.25, 0.5) for the volumetric"
                        + " spring fit, got " + poisson + " (it adds a volume term to springs whose own ratio is"
                        + " 1/4, and cannot take one away)");
            }
        } else {
            double lo = fit == SpringFit.AXIAL ? 0 : -1;
            if (!(poisson > lo && poisson < 0.5)) {
                throw new IllegalArgumentException("volume Poisson ratio must be in (" + (int) lo + ", 0.5) for the "
                        + fit.key() + " spring fit, got " + poisson + (fit == SpringFit.AXIAL
                        ? " (the axial fit's shear modulus is Lamé's lambda, zero at nu = 0)" : ""));
            }
        }
    }

    /** Lamé's lambda of the requested (E, nu), Pa. */
    public double lameLambdaPa() {
        return youngPa * poisson / ((1 + poisson) * (1 - 2 * poisson));
    }

    /** Shear modulus mu = E / (2 (1 + nu)) of the requested (E, nu), Pa. */
    public double lameMuPa() {
        return youngPa / (2 * (1 + poisson));
    }

    /** The cell's C11 (springs and volume term), Pa. */
    public double c11Pa() {
        return fit == SpringFit.ISOTROPIC ? 1.2 * youngPa : lameLambdaPa() + 2 * lameMuPa();
    }

    /** The cell's C12 (springs and volume term), Pa. */
    public double c12Pa() {
        return fit == SpringFit.ISOTROPIC ? 0.4 * youngPa : lameLambdaPa();
    }

    /** The cell's C44, Pa: equal to C12 for springs alone (Cauchy's relation), mu with the volume term. */
    public double c44Pa() {
        return fit == SpringFit.VOLUMETRIC ? lameMuPa() : c12Pa();
    }

    /** The springs' share of C11, Pa: all of it but for the volumetric fit's {@code 3 mu}. */
    public double springC11Pa() {
        return fit == SpringFit.VOLUMETRIC ? 3 * lameMuPa() : c11Pa();
    }

    /** The springs' share of C12 (= their C44), Pa: all of it but for the volumetric fit's {@code mu}. */
    public double springC12Pa() {
        return fit == SpringFit.VOLUMETRIC ? lameMuPa() : c12Pa();
    }

    /**
     * The modulus K of the volume term a full cell carries ({@link org.tensim.model.VolumeElement}), Pa:
     * {@code lambda - mu} for the volumetric fit (0 at nu = 1/4), 0 for the others (no term).
     */
    public double volumetricModulusPa() {
        return fit == SpringFit.VOLUMETRIC ? lameLambdaPa() - lameMuPa() : 0;
    }

    /** The lattice's shear modulus C44, Pa. */
    public double shearModulusPa() {
        return c44Pa();
    }

    /** The lattice's bulk modulus (C11 + 2 C12) / 3, Pa. */
    public double bulkModulusPa() {
        return (c11Pa() + 2 * c12Pa()) / 3;
    }

    /**
     * Poisson's ratio of the lattice under uniaxial stress along an axis, C12 / (C11 + C12): 1/4 for the isotropic
     * fit, the requested nu for the axial and volumetric ones.
     */
    public double modelPoisson() {
        return c12Pa() / (c11Pa() + c12Pa());
    }

    /**
     * Young's modulus of the lattice along the unit direction (nx, ny, nz), Pa: {@code 1 / E(n) = S11 - 2 (S11 - S12
     * - S44 / 2) (nx^2 ny^2 + ny^2 nz^2 + nz^2 nx^2)} for a cubic material, with its compliances S; E along the axes,
     * and along every direction for the isotropic and volumetric fits.
     */
    public double youngAlongPa(double nx, double ny, double nz) {
        double n = Math.sqrt(nx * nx + ny * ny + nz * nz);
        double a = nx / n;
        double b = ny / n;
        double c = nz / n;
        double c11 = c11Pa();
        double c12 = c12Pa();
        double det = (c11 - c12) * (c11 + 2 * c12);
        double s11 = (c11 + c12) / det;
        double s12 = -c12 / det;
        double s44 = 1 / c44Pa();
        return 1 / (s11 - 2 * (s11 - s12 - s44 / 2) * (a * a * b * b + b * b * c * c + c * c * a * a));
    }

    /** Share s of the springs' C12 carried by the face diagonals, {@code min(1, (C11 - C12) / (2 C12))} of theirs. */
    public double faceShare() {
        return Math.min(1, (springC11Pa() - springC12Pa()) / (2 * springC12Pa()));
    }

    /** One cell's share of each of its 12 edges, N/m, for cell side {@code cellM} (m). */
    public double edgeStiffness(double cellM) {
        return (springC11Pa() - springC12Pa() - faceShare() * springC12Pa()) * cellM / 4;
    }

    /** One cell's share of each of its 12 face diagonals, N/m. */
    public double faceDiagonalStiffness(double cellM) {
        return faceShare() * springC12Pa() * cellM / 2;
    }

    /** The stiffness of each of a cell's 4 body diagonals, N/m (0 for the isotropic fit: none are added). */
    public double bodyDiagonalStiffness(double cellM) {
        return 3 * (1 - faceShare()) * springC12Pa() * cellM / 4;
    }
}

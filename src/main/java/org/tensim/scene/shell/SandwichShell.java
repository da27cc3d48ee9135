package org.tensim.scene.shell;

/**
 * Identification of a two-surface shell: two triangle membranes (the faces) a distance s apart,
 * joined by through-thickness columns and by diagonals (the edges of the prisms between the
 * faces), and (with membrane triangles, {@link #ofElements}) a membrane on the mid-surface. It
 * chooses how much of the membrane stiffness the faces, the mid-surface and the diagonals carry
 * so that both the membrane and the bending rigidity are the material's.
 *
 * <p><b>With membrane triangles</b> ({@link org.tensim.model.TriangleElement}, the material model):
 * the faces have the material's nu, so {@code c = t^2 / (6 s^2)}; the mid-surface triangle (corners
 * at the midpoints of each upper node and its partner) carries {@code 1 - 2c - d} without bending
 * stiffness (bending leaves the mid-surface unstretched to first order); the diagonals carry
 * {@code d = }{@link #SHEAR_SHARE} (0: the transverse shear elements resist the faces' sliding; where a
 * mesh's pairs cannot carry one, the diaphragm's shell keeps diagonals, {@code ShellNetwork.FALLBACK_DIAGONAL_SHARE}). The paragraphs below describe the
 * edge-spring identification ({@link #of}, the springs model).
 *
 * <p><b>Bending.</b> Two faces each of membrane modulus {@code c E t} (a spring network, whose own
 * Poisson ratio is {@code nu_s = 1/3}) at {@code +/- s/2} from the mid-surface bend like a sandwich
 * panel: {@code D_s = 2 (c E t / (1 - nu_s^2)) (s/2)^2}. Matching Kirchhoff's
 * {@code D = E t^3 / (12 (1 - nu^2))} gives the face share
 * {@code c = (1 - nu_s^2) t^2 / (6 (1 - nu^2) s^2)} (4/27/(1 - nu^2) for s = t; 1/6 at nu = 1/3).
 * Faces that each carry half the membrane ({@code c = 1/2}, the paper's model) are three times
 * too stiff in bending at nu = 1/3.
 *
 * <p><b>Membrane.</b> The rest, {@code 1 - 2c}, is carried by the diagonals: each edge (i, j) of a
 * face has two, upper i to lower j and upper j to lower i; their stretch under an in-plane strain
 * is that of the edge times {@code (|e| / L)^2} (L the diagonal's length), and a rotation of the
 * normal (bending) does not stretch them to first order. So each gets
 * {@code k_d = (1 - 2c) / 2 k_e (L / |e|)^2}, with {@code k_e} the edge's membrane spring for the whole
 * thickness ({@link TriangleMembrane}). The pair also resists the faces sliding over each
 * other (transverse shear), with an effective shear modulus of order {@code E (t / h)^2}: its
 * share of the plate's deflection falls as {@code (h / a)^2} (h the element size, a the span).
 *
 * <p><b>Thickness.</b> The diagonals' tension has a component across the thickness that squeezes the
 * faces together. Columns of springs as soft as the tissue ({@code E A / L}) let the diagonals lose
 * most of their membrane stiffness where elements are as short as the shell is thick (patch test:
 * 15 % too soft at h = 1.25 t, 55 % at 0.64 t; stiffer columns cost the explicit step), so the
 * material model holds the columns rigid (Kirchhoff-Love's inextensible normal).
 */
public record SandwichShell(double faceShare, double midShare, double diagonalShare) {
    /**
     * Share of the membrane on the prisms' diagonals in {@link #ofElements} for the material model: 0.
     * The faces' sliding (transverse shear) is resisted by the shear elements
     * ({@link org.tensim.model.TransverseShear}, Mindlin-Reissner's {@code kappa G t}), so the diagonals
     * are not needed; their share of 3 % (an effective shear modulus {@code 0.03 E (t / h)^2}, 30 to 270
     * times too soft at the diaphragm's element sizes) moved the patch test by 0.8 % on right triangles,
     * against 0.00 % without them, and changes the plate by under 0.1 % with the shear elements
     * (docs/shell.md).
     */
    public static final double SHEAR_SHARE = 0;

    public SandwichShell {
        if (!(faceShare > 0 && faceShare <= 0.5) || !(midShare >= 0) || !(diagonalShare >= 0)
                || Math.abs(faceShare * 2 + midShare + diagonalShare - 1) > 1e-12) {
            throw new IllegalArgumentException("face share must be in (0, 0.5], the others >= 0 and the shares must"
                    + " add to 1, got " + faceShare + " (x2), " + midShare + " and " + diagonalShare);
        }
    }

    /**
     * The shares for a material whose faces are {@code separationM} apart.
     *
     * @throws IllegalArgumentException when the faces are so far apart (or nu so large) that the faces
     *         alone would need more than half the membrane
     */
    public static SandwichShell of(ShellMaterial m, double separationM) {
        double nuS = TriangleMembrane.NETWORK_POISSON;
        double t = m.thicknessM();
        double c = (1 - nuS * nuS) * t * t / (6 * (1 - m.poisson() * m.poisson()) * separationM * separationM);
        if (!(c > 0 && c <= 0.5)) {
            throw new IllegalArgumentException("faces " + separationM + " m apart cannot carry the bending of a "
                    + t + " m shell with nu = " + m.poisson() + ": face share " + c + ", expected <= 0.5");
        }
        return new SandwichShell(c, 0, 1 - 2 * c);
    }

    /**
     * The shares for membrane triangles ({@link org.tensim.model.TriangleElement}, exact for any nu):
     * faces {@code c = t^2 / (6 s^2)} each (two membranes of modulus {@code c E t / (1 - nu^2)} at
     * {@code +/- s/2} give {@code D = E t^3 / (12 (1 - nu^2))}), the diagonals {@code shearShare},
     * the mid-surface the rest.
     *
     * @param shearShare the diagonals' share, in [0, 1 - 2c)
     * @throws IllegalArgumentException when the faces are so far apart that they alone need more
     *         than half the membrane, or nothing would be left for the mid-surface
     */
    public static SandwichShell ofElements(ShellMaterial m, double separationM, double shearShare) {
        double t = m.thicknessM();
        double c = t * t / (6 * separationM * separationM);
        if (!(c > 0 && c <= 0.5) || !(shearShare >= 0 && shearShare < 1 - 2 * c)) {
            throw new IllegalArgumentException("faces " + separationM + " m apart cannot carry the bending of a "
                    + t + " m shell with a shear share " + shearShare + ": face share " + c
                    + ", expected <= 0.5 and 2 x face share + shear share < 1");
        }
        return new SandwichShell(c, 1 - 2 * c - shearShare, shearShare);
    }

    /** Stiffness of one face edge spring, N/m, from the edge's membrane spring for the whole thickness, N/m. */
    public double faceEdge(double edgeMembraneNPerM) {
        return faceShare * edgeMembraneNPerM;
    }

    /**
     * Stiffness of one of the two diagonals of a face edge, N/m.
     *
     * @param edgeMembraneNPerM the edge's membrane spring for the whole thickness ({@link TriangleMembrane}), N/m
     * @param edgeLengthM       the face edge's length (the diagonal's in-plane projection), m
     * @param diagonalM         the diagonal's length, m
     */
    public double diagonal(double edgeMembraneNPerM, double edgeLengthM, double diagonalM) {
        double r = diagonalM / edgeLengthM;
        return 0.5 * diagonalShare * edgeMembraneNPerM * r * r;
    }
}

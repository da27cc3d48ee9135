package org.tensim.scene.shell;

/**
 * How the two-surface shell's springs are derived from the tissue (docs/diaphragm.md, "The model").
 */
public enum TissueModel {
    /**
     * Each face carries half the membrane ({@code E (t/2) sum A / |e|^2}), folding springs between
     * the vertices opposite each edge (times the bending factor), and columns plus diagonals sharing
     * {@code E A / L} per upper node: the model the paper's figures were reproduced with. Its bending
     * rigidity is about three times Kirchhoff's, and the diagonals' share of shear and in-plane
     * stiffness changes with the element size over the thickness.
     */
    PAPER,
    /**
     * Identified element by element from E, nu and t ({@link org.tensim.scene.shell.SandwichShell#ofElements}):
     * the membrane as St Venant-Kirchhoff triangles ({@link org.tensim.model.TriangleElement}), exact
     * for a uniform strain on any mesh and any nu. Each face carries the share {@code c = t^2 / (6 s^2)}
     * that gives Kirchhoff's bending rigidity; the rest of the membrane is a
     * triangle on the mid-surface (the midpoints of each upper node and its partner), which bending
     * does not stretch. The faces' sliding over each other (transverse shear) is resisted by a
     * transverse shear element per upper triangle ({@link org.tensim.model.TransverseShear},
     * Mindlin-Reissner's {@code kappa G t}, kappa = 5/6). Every column across the thickness is a rigid
     * link (Kirchhoff-Love); no folding springs, no diagonals. The default.
     */
    MATERIAL,
    /**
     * The same identification with edge springs only (Van Gelder 1998, {@link
     * org.tensim.scene.shell.TriangleMembrane}): faces sized for Kirchhoff's bending rigidity (for the
     * network's own nu = 1/3), the rest of the membrane on the prisms' diagonals, rigid columns. Exact
     * on equilateral triangles at nu = 1/3 only (patch test 8-10 % off on distorted meshes); kept for
     * comparison.
     */
    SPRINGS;

    /** Whether every column across the thickness is a rigid link (else only the tendon's). */
    public boolean rigidColumns() {
        return this != PAPER;
    }

    /** The model of that name (case-insensitive), with the known names in the error. */
    public static TissueModel parse(String name) {
        for (TissueModel m : values()) {
            if (m.name().equalsIgnoreCase(name)) {
                return m;
            }
        }
        throw new IllegalArgumentException("unknown tissue model '" + name + "': expected one of "
                + java.util.Arrays.stream(values()).map(m -> m.name().toLowerCase()).toList());
    }
}

package org.tensim.scene.diaphragm;

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
     * Springs identified element by element from E, nu and t ({@link org.tensim.scene.shell.SandwichShell}):
     * faces sized for Kirchhoff's bending rigidity, the rest of the membrane on the prisms'
     * diagonals; no folding springs. Every node's column across the thickness is a rigid link
     * (Kirchhoff-Love: the normal keeps its length), so that the diagonals' pull across the
     * thickness cannot thin the shell and take their membrane stiffness away where elements are
     * as short as the shell is thick; the tendon differs from the muscle by its modulus.
     */
    MATERIAL;

    /** Whether every column across the thickness is a rigid link (else only the tendon's). */
    public boolean rigidColumns() {
        return this == MATERIAL;
    }

    /** The model of that name (case-insensitive), with the known names in the error. */
    public static TissueModel parse(String name) {
        for (TissueModel m : values()) {
            if (m.name().equalsIgnoreCase(name)) {
                return m;
            }
        }
        throw new IllegalArgumentException("unknown tissue model '" + name + "': expected paper or material");
    }
}

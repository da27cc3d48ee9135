package org.tensim.io.mesh;

/**
 * The length unit of the coordinates in a mesh file. Meshes are converted to
 * metres (the solver's unit) when they are loaded.
 */
public enum MeshUnits {
    /** Millimetres (BodyParts3D, most anatomical meshes): 1 file unit = 0.001 m. */
    MM(1e-3),
    /** Metres: 1 file unit = 1 m. */
    M(1.0);

    private final double metresPerUnit;

    MeshUnits(double metresPerUnit) {
        this.metresPerUnit = metresPerUnit;
    }

    /** Metres per file unit. */
    public double metresPerUnit() {
        return metresPerUnit;
    }

    /** Parses {@code mm} or {@code m} (case-insensitive); anything else is refused with a message. */
    public static MeshUnits parse(String s) {
        if (s != null) {
            switch (s.trim().toLowerCase(java.util.Locale.ROOT)) {
                case "mm":
                    return MM;
                case "m":
                    return M;
                default:
                    break;
            }
        }
        throw new IllegalArgumentException("mesh units must be 'mm' or 'm', got '" + s + "'");
    }
}

package org.tensim.scene.diaphragm;

/** How the central tendon is found on a mesh without a label file. */
public enum TendonRule {
    /** The paper's: the cap on the positive side of a plane, placed to give the tendon its area share. */
    PLANE,
    /**
     * The upper-surface region nearest, along the surface, to the two dome tops and their midpoint, grown to the
     * tendon's area share ({@link GeodesicTendon}): central, as the real trefoil is, whichever dome is higher.
     */
    GEODESIC
}

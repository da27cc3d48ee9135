package org.tensim.experiment.lungs;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.LinearMapping;

/**
 * A lung's surface against its pleura: a sphere's vertices as the lung's surface on nodes 0..n-1 and the same sphere as
 * the pleura on nodes n..2n-1. At rest no departure; the lung's vertices moved out radially by 1 mm read a penetration
 * of 1 mm (to the faceted sphere's flatness), the pleura moved out by 2 mm instead a separation of 2 mm; the larger
 * of each is kept with its time and place.
 */
class LungSurfaceGapTest {
    private static final double R = 0.05;

    @Test
    void departuresAreTheLungSurfacesSignedDistancesToThePleura() {
        TriangleMesh s = org.tensim.scene.rigid.RigidMeshes.sphere(new double[] {0, 0, 0}, R);
        int n = s.vertexCount();
        LinearMapping.Builder lung = new LinearMapping.Builder(2 * n);
        LinearMapping.Builder pleura = new LinearMapping.Builder(2 * n);
        for (int v = 0; v < n; v++) {
            lung.add(new int[] {v}, new double[] {1});
            pleura.add(new int[] {n + v}, new double[] {1});
        }
        LungSurfaceGap gap = new LungSurfaceGap(lung.build(), pleura.build(), s.triangles());
        double[] x = new double[6 * n];
        double[] c = s.coordinates();
        System.arraycopy(c, 0, x, 0, 3 * n);
        System.arraycopy(c, 0, x, 3 * n, 3 * n);
        gap.read(x, 0);
        assertEquals(0, gap.maxPenetrationM(), 1e-15, "at rest");
        assertEquals(0, gap.maxSeparationM(), 1e-15, "at rest");
        scale(x, 0, n, (R + 0.001) / R); // the lung out by 1 mm
        gap.read(x, 0.5);
        assertEquals(0.001, gap.maxPenetrationM(), 1e-6, "the vertices out by 1 mm from a vertex-inscribed sphere");
        assertEquals(0, gap.maxSeparationM(), 1e-15);
        assertEquals(0.5, gap.penetrationTimeS(), 0);
        double[] at = gap.penetrationAtM();
        assertEquals(R + 0.001, Math.sqrt(at[0] * at[0] + at[1] * at[1] + at[2] * at[2]), 1e-12);
        System.arraycopy(c, 0, x, 0, 3 * n);
        scale(x, n, n, (R + 0.002) / R); // the pleura out by 2 mm: the lung inside it
        gap.read(x, 1.0);
        // Inside a sphere scaled by 1.04 a vertex of the smaller is 2 mm from the larger's vertex and a little less
        // from its faces' planes (flatness (R + 2 mm) (1 - cos) of the facets).
        assertTrue(gap.maxSeparationM() > 0.0017 && gap.maxSeparationM() <= 0.002 + 1e-12,
                "separation " + gap.maxSeparationM());
        assertEquals(1.0, gap.separationTimeS(), 0);
        assertEquals(0.001, gap.maxPenetrationM(), 1e-6, "the larger penetration kept");
    }

    private static void scale(double[] x, int first, int count, double f) {
        for (int k = 3 * first; k < 3 * (first + count); k++) {
            x[k] *= f;
        }
    }
}

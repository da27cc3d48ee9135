package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.analysis.FlatMeshes;
import org.tensim.analysis.LinearStatics;
import org.tensim.analysis.ShellStatics;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.ObjWriter;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Spring;
import org.tensim.model.Topology;
import org.tensim.model.TransverseShear;
import org.tensim.model.TriangleElement;

/**
 * A shell zone of its own Young's modulus ({@code model: mass-spring, material: {E}}): a strip pulled at one end
 * whose far half is twice as stiff stretches as two springs in series predict, its zone's strain half the rest's; a
 * zone over the whole strip at 2 E halves the stretch (linear statics is linear in E); a zone of the body's own E
 * changes no spring, triangle or shear element, to the bit.
 */
class ShellZoneMaterialTest {
    private static final double LENGTH = 0.1;
    private static final double WIDTH = 0.02;
    private static final int CELLS = 20;
    private static final double SIGMA = 100; // Pa on the end section

    @TempDir
    Path dir;

    private Topology strip(String model, String zones) throws IOException {
        return strip(model, zones, CELLS);
    }

    private Topology strip(String model, String zones, int cells) throws IOException {
        TriangleMesh flat = FlatMeshes.rectangle(FlatMeshes.Pattern.RIGHT, cells, LENGTH, WIDTH, 11);
        ObjWriter.write(dir.resolve("strip.obj"), flat, MeshUnits.M, List.of("a flat strip"), 12);
        String yaml = "version: 1\n"
                + "bodies:\n"
                + "  strip: {type: shell, surface: {file: strip.obj, units: m}, thickness: 2.5 mm,\n"
                + "          material: {E: 40 kPa, nu: 0.3, damping_time: 1 ms}, tissue_model: " + model + "}\n"
                + "regions:\n"
                + "  far: {box: {min: [0.5, 0, 0], max: [1, 1, 1], frame: relative}}\n"
                + "  all: {box: {min: [0, 0, 0], max: [1, 1, 1], frame: relative}}\n"
                + zones
                + "run: {dt: 1 ms, duration: 1 ms}\n";
        return SceneFiles.load(dir, "strip.yaml", yaml).bodies().get("strip").topology();
    }

    /** Small-displacement statics: x = 0 held along x (one node also in y, z), SIGMA on the end x = LENGTH. */
    private static double[] stretch(Topology t) {
        int n = t.nodeCount();
        double[] f = new double[3 * n];
        boolean[] fixed = new boolean[3 * n];
        double tol = 1e-9;
        int endNodes = 0;
        for (int v = 0; v < n; v++) {
            endNodes += Math.abs(t.node(v).position().x() - LENGTH) < tol ? 1 : 0;
        }
        double width = 0;
        for (int v = 0; v < n; v++) {
            width = Math.max(width, t.node(v).position().y());
        }
        int pin = -1;
        for (int v = 0; v < n; v++) {
            double x = t.node(v).position().x();
            if (Math.abs(x - LENGTH) < tol) {
                // Equal shares of the end force: the end's nodes are equally spaced, the two end ones carry half,
                // a simplification the ratio below does not see (the same load on every strip).
                f[3 * v] = SIGMA * 0.0025 * width / endNodes;
            }
            if (Math.abs(x) < tol) {
                fixed[3 * v] = true;
                if (pin < 0) {
                    pin = v;
                }
            }
        }
        // As the patch test (ShellStatics.patch): one end node held in y on both faces and in z on the upper one.
        fixed[3 * pin + 1] = true;
        fixed[3 * (pin + n / 2) + 1] = true;
        fixed[3 * pin + 2] = true;
        return LinearStatics.solve(t, fixed, f, ShellStatics.TOLERANCE).displacementM();
    }

    private static double endDisplacement(Topology t, double[] u) {
        double sum = 0;
        int count = 0;
        for (int v = 0; v < t.nodeCount(); v++) {
            if (Math.abs(t.node(v).position().x() - LENGTH) < 1e-9) {
                sum += u[3 * v];
                count++;
            }
        }
        return sum / count;
    }

    /** The mean of u_x(x1) - u_x(x0) over the nodes at x0 and x1, divided by x1 - x0. */
    private static double strain(Topology t, double[] u, double x0, double x1) {
        return (meanAt(t, u, x1) - meanAt(t, u, x0)) / (x1 - x0);
    }

    private static double meanAt(Topology t, double[] u, double x) {
        double sum = 0;
        int count = 0;
        for (int v = 0; v < t.nodeCount(); v++) {
            if (Math.abs(t.node(v).position().x() - x) < 1e-9) {
                sum += u[3 * v];
                count++;
            }
        }
        assertTrue(count > 0, "nodes at x = " + x);
        return sum / count;
    }

    @Test
    void aStripWhoseFarHalfIsTwiceAsStiffStretchesAsSpringsInSeries() throws IOException {
        // In series: the near half at E, the far half at 2 E: u = sigma/E (L/2) + sigma/(2E) (L/2) = 0.75 u0.
        // The elements on the zone's border (an edge on x = L/2) take the mean of their edges' E, stiffer than E
        // over one column of elements: an error of order h, halved when the mesh is.
        double[] error = new double[2];
        Topology zoned = null;
        double[] uz = null;
        for (int r = 0; r < 2; r++) {
            int cells = CELLS << r;
            Topology plain = strip("material", "", cells);
            zoned = strip("material", "zones:\n  scar: {region: far, model: mass-spring, material: {E: 80 kPa}}\n",
                    cells);
            double u0 = endDisplacement(plain, stretch(plain));
            uz = stretch(zoned);
            double ratio = endDisplacement(zoned, uz) / u0;
            error[r] = ratio / 0.75 - 1;
            System.out.printf("strip of %d cells, far half 2 E: stretch %.5f of the plain strip's (series 0.75),"
                    + " %+.3f %%%n", cells, ratio, 100 * error[r]);
        }
        assertEquals(0, error[0], 0.02, "series springs at 20 cells: 0.75 within 2 %");
        assertEquals(0, error[1], 0.01, "series springs at 40 cells: 0.75 within 1 %");
        assertEquals(2, error[0] / error[1], 0.3, "the border's error is first order in h");
        double h = LENGTH / (2 * CELLS);
        double near = strain(zoned, uz, 2 * h, LENGTH / 2 - 2 * h);
        double far = strain(zoned, uz, LENGTH / 2 + 2 * h, LENGTH - 2 * h);
        System.out.printf("strain near %.6g, far %.6g, ratio %.5f (2)%n", near, far, near / far);
        assertEquals(2, near / far, 0.02 * 2, "the zone's strain is half the rest's, within 2 %");
    }

    @Test
    void aZoneOverTheWholeStripAtTwiceItsModulusHalvesItsStretch() throws IOException {
        Topology plain = strip("material", "");
        Topology doubled = strip("material", "zones:\n  all: {region: all, model: mass-spring, material: {E: 80 kPa}}\n");
        double u0 = endDisplacement(plain, stretch(plain));
        double u2 = endDisplacement(doubled, stretch(doubled));
        assertEquals(0.5, u2 / u0, 1e-6, "linear in E");
        for (int i = 0; i < plain.springs().size(); i++) {
            Spring a = plain.springs().get(i);
            Spring b = doubled.springs().get(i);
            assertEquals(2 * a.stiffness(), b.stiffness(), 1e-12 * a.stiffness(), "spring " + i);
            assertEquals(2 * a.damping(), b.damping(), 1e-12 * a.damping(), "spring " + i + " damping beta k");
        }
    }

    @Test
    void aZoneOfTheBodysOwnModulusChangesNothingToTheBit() throws IOException {
        for (String model : List.of("material", "springs", "paper")) {
            Topology plain = strip(model, "");
            Topology same = strip(model, "zones:\n  same: {region: far, model: mass-spring, material: {E: 40 kPa}}\n");
            assertEquals(plain.springs(), same.springs(), model + ": springs (records: ends, k, L, c)");
            assertEquals(plain.triangles().size(), same.triangles().size(), model);
            for (int i = 0; i < plain.triangles().size(); i++) {
                TriangleElement a = plain.triangles().get(i);
                TriangleElement b = same.triangles().get(i);
                assertEquals(a.youngPa(), b.youngPa(), 0, model + ": triangle " + i);
                assertEquals(a.muVolume(), b.muVolume(), 0, model + ": triangle " + i);
                assertEquals(a.lambdaVolume(), b.lambdaVolume(), 0, model + ": triangle " + i);
                assertEquals(a.dampingS(), b.dampingS(), 0, model + ": triangle " + i);
            }
            assertEquals(plain.shears().size(), same.shears().size(), model);
            for (int i = 0; i < plain.shears().size(); i++) {
                TransverseShear a = plain.shears().get(i);
                TransverseShear b = same.shears().get(i);
                for (int k = 0; k < 9; k++) {
                    assertEquals(a.stiffness(k / 3, k % 3), b.stiffness(k / 3, k % 3), 0, model + ": shear " + i);
                }
            }
            assertTrue(model.equals("paper") || !plain.triangles().isEmpty() || !plain.springs().isEmpty(), model);
        }
    }
}

package org.tensim.solver.parallel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tensim.testsupport.FiniteDifferences.maxAbs;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tensim.model.Topology;
import org.tensim.solver.ForceModel;
import org.tensim.solver.NodeLoops;
import org.tensim.solver.PartitionedTriangleTangent;
import org.tensim.solver.SystemState;
import org.tensim.solver.TriangleTangent;
import org.tensim.testsupport.FiniteDifferences;

/**
 * {@link PartitionedTriangleTangent}, the fused and slab-parallel form of the triangles' clamped
 * tangent that bdf2's Newton-Krylov solve applies: it is the general {@link TriangleTangent}'s
 * matrix to round-off (with fixed nodes, midpoint corners, damping and compressed elements whose
 * stress is clamped), it is the derivative of the triangle forces where no element is compressed,
 * and its products and linearisation give the same bits on 1, 2 or 3 threads.
 */
class PartitionedTriangleTangentTest {
    private static final int NX = 100; // nodes along x (across the slabs)
    private static final int NY = 12; // with NX: 2,178 elements, enough for the slabs to be dispatched

    /**
     * A bumpy sheet of NX x NY nodes, two triangles per cell; every third triangle takes the midpoints
     * of cell edges as corners (nodes p and q of a corner differ), and every other one is damped.
     */
    private static SystemState sheet(Random rnd) {
        Topology t = new Topology();
        for (int i = 0; i < NX; i++) {
            for (int j = 0; j < NY; j++) {
                t.addNode(0.01 * i, 0.01 * j, 0.002 * rnd.nextDouble(), 0.01);
            }
        }
        int e = 0;
        for (int i = 0; i + 1 < NX; i++) {
            for (int j = 0; j + 1 < NY; j++) {
                int a = i * NY + j;
                int b = a + NY;
                int c = a + 1;
                int d = b + 1;
                for (int[] p : new int[][] {{a, b, d}, {a, d, c}}) {
                    int[] q = e % 3 == 0 ? new int[] {p[1], p[2], p[0]} : p.clone();
                    if (e % 3 == 0 && q[0] == q[1]) {
                        q = p.clone();
                    }
                    t.addTriangle(p, q, 2e-3, 30e3 * (0.5 + rnd.nextDouble()), 0.3, e % 2 == 0 ? 0.01 : 0);
                    e++;
                }
            }
        }
        return SystemState.compile(t);
    }

    /** Compact offsets: about one node in five left out (fixed or eliminated), the others numbered. */
    private static int[] offsets(SystemState s, Random rnd) {
        int[] offset = new int[s.nodeCount];
        int k = 0;
        for (int i = 0; i < s.nodeCount; i++) {
            offset[i] = rnd.nextInt(5) == 0 ? -1 : 3 * k++;
        }
        return offset;
    }

    private static int compactLength(int[] offset) {
        int n = 0;
        for (int o : offset) {
            n = Math.max(n, o + 3);
        }
        return n;
    }

    private static double[] deformed(SystemState s, Random rnd, double stretch, double noise) {
        double[] x = new double[s.x0.length];
        for (int k = 0; k < x.length; k++) {
            x[k] = stretch * s.x0[k] + noise * rnd.nextGaussian();
        }
        return x;
    }

    @Test
    void productIsTheGeneralTangentsToRoundOff() {
        Random rnd = new Random(5);
        SystemState s = sheet(rnd);
        int[] offset = offsets(s, rnd);
        int n3 = compactLength(offset);
        // Noise of 2 mm on a 1 cm grid: some elements are compressed and their stress is clamped.
        double[] x = deformed(s, rnd, 1.0, 2e-3);
        double[] p = new double[n3];
        for (int k = 0; k < n3; k++) {
            p[k] = rnd.nextGaussian();
        }
        TriangleTangent general = new TriangleTangent(s);
        general.linearise(x, true);
        double[] expected = new double[n3];
        general.multiplyAdd(p, expected, offset, 0.3, 0.7);
        PartitionedTriangleTangent fused = new PartitionedTriangleTangent(s, offset);
        fused.linearise(x, NodeLoops.SERIAL);
        double[] actual = new double[n3];
        fused.multiplyAdd(p, actual, 0.3, 0.7, NodeLoops.SERIAL);
        double scale = maxAbs(expected);
        assertTrue(scale > 0, "the deformed sheet is stiff");
        for (int k = 0; k < n3; k++) {
            assertEquals(expected[k], actual[k], 1e-13 * scale, "component " + k);
        }
        assertTrue(fused.seamElements() > 0 && fused.seamElements() < fused.elements() / 4,
                "a thin seam between the slabs: " + fused.seamElements() + " of " + fused.elements());
    }

    @Test
    void productIsTheDerivativeOfTheForcesWhereNothingIsCompressed() {
        Random rnd = new Random(6);
        SystemState s = sheet(rnd);
        int[] offset = new int[s.nodeCount];
        for (int i = 0; i < s.nodeCount; i++) {
            offset[i] = 3 * i; // all free: the full layout
        }
        double[] x = deformed(s, rnd, 1.05, 1e-5); // stretched 5 %: every element in tension
        PartitionedTriangleTangent k = new PartitionedTriangleTangent(s, offset);
        k.linearise(x, NodeLoops.SERIAL);
        double[] dir = new double[x.length];
        for (int i = 0; i < dir.length; i++) {
            dir[i] = rnd.nextGaussian();
        }
        double[] kd = new double[x.length];
        k.multiplyAdd(dir, kd, 1, 0, NodeLoops.SERIAL);
        ForceModel fm = new ForceModel(s);
        double[] df = FiniteDifferences.directional(fm::triangles, x, dir, 1e-7);
        double scale = maxAbs(kd);
        for (int i = 0; i < x.length; i++) {
            assertEquals(-df[i], kd[i], 1e-6 * scale, "component " + i);
        }
    }

    @Test
    void sameBitsOnAnyNumberOfThreads() {
        Random rnd = new Random(7);
        SystemState s = sheet(rnd);
        int[] offset = offsets(s, rnd);
        int n3 = compactLength(offset);
        double[] x = deformed(s, rnd, 1.02, 1e-3);
        double[] p = new double[n3];
        for (int k = 0; k < n3; k++) {
            p[k] = rnd.nextGaussian();
        }
        assertTrue(2 * (NX - 1) * (NY - 1) >= PartitionedTriangleTangent.MIN_PARALLEL_ELEMENTS,
                "enough elements for the slabs to go to the threads");
        double[] reference = null;
        for (int threads = 1; threads <= 3; threads++) {
            try (WorkerPool pool = new WorkerPool(threads, "tangent-test")) {
                NodeLoops loops = new PooledNodeLoops(pool, 1);
                PartitionedTriangleTangent k = new PartitionedTriangleTangent(s, offset);
                k.linearise(x, loops);
                double[] out = new double[n3];
                java.util.Arrays.fill(out, 0.5); // the product adds to what is there
                k.multiplyAdd(p, out, 0.4, 0.2, loops);
                if (reference == null) {
                    reference = out;
                } else {
                    assertArrayEquals(reference, out, threads + " threads");
                }
            }
        }
    }
}

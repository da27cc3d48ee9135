package org.tensim.calibration;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.ObjWriter;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.sweep.Measure;
import org.tensim.sweep.Point;
import org.tensim.sweep.PointResult;
import org.tensim.sweep.RunSetup;
import org.tensim.sweep.SceneRun;

/**
 * A target surface made by the project itself, for testing a calibration on a known answer:
 * the diaphragm is run at known parameter values and its surface (both faces) at one time is
 * written as an OBJ file in millimetres, every vertex moved by Gaussian noise of a given
 * standard deviation per coordinate (the segmentation error of a 4D-CT surface).
 */
public final class SyntheticTarget {
    private SyntheticTarget() {
    }

    /**
     * Runs {@code setup} at {@code truth} and writes the surface at {@code timeS}.
     *
     * @param noiseMm standard deviation of the noise added to each coordinate, mm (>= 0)
     * @param seed    seed of the noise
     * @return the run's result (its status says whether the surface was written: only when ok)
     */
    public static PointResult write(RunSetup setup, Map<String, Double> truth, double timeS, double noiseMm,
            long seed, Path obj) {
        if (!(noiseMm >= 0) || !Double.isFinite(noiseMm)) {
            throw new IllegalArgumentException("noise must be a finite standard deviation >= 0 mm, got " + noiseMm);
        }
        List<String> names = new ArrayList<>(truth.keySet());
        double[] v = names.stream().mapToDouble(truth::get).toArray();
        RunSetup s = setup.withMeasures(List.of(new Export(timeS, noiseMm, seed, obj.toString(), truth.toString())));
        PointResult r = SceneRun.run(s, names, new Point(0, v));
        if (!r.ok()) {
            throw new IllegalStateException("the run at " + truth + " did not finish (" + r.status() + ": "
                    + r.message() + "); no target written");
        }
        return r;
    }

    /** Writes the noisy surface when the run reaches its time (runs in this JVM only). */
    private record Export(double timeS, double noiseMm, long seed, String file, String truth) implements Measure {
        @Override
        public Probe start(DiaphragmRunView run) {
            return new Probe() {
                private boolean done;

                @Override
                public void afterStep(double t, double[] x) {
                    if (done || t < timeS - 1e-9) {
                        return;
                    }
                    done = true;
                    Random r = new Random(seed);
                    int n = run.diaphragmNodes();
                    double[] xyz = new double[3 * n];
                    for (int i = 0; i < 3 * n; i++) {
                        xyz[i] = x[i] + 1e-3 * noiseMm * r.nextGaussian();
                    }
                    try {
                        ObjWriter.write(Path.of(file), new TriangleMesh(xyz, run.triangles()), MeshUnits.MM,
                                List.of("tensim synthetic target: diaphragm at t = " + t + " s, parameters " + truth,
                                        "Gaussian noise " + noiseMm + " mm per coordinate, seed " + seed), 6);
                    } catch (IOException e) {
                        throw new UncheckedIOException(e);
                    }
                }

                @Override
                public void finish(Map<String, Double> fields) {
                }
            };
        }
    }
}

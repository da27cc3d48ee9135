package org.tensim.experiment.diaphragm;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.tensim.scene.diaphragm.BreathingCycle;
import org.tensim.scene.diaphragm.DiaphragmControls;
import org.tensim.scene.diaphragm.DiaphragmParameters;
import org.tensim.scene.diaphragm.DiaphragmScene;

/**
 * The displacement samples of the same-mesh RK2 reference, kept in the study's output folder: at the
 * paper's resolution RK2 needs 56,000 steps per simulated second, over an hour for one breathing cycle
 * on a shared two-core machine, so a study that is run again with other configurations reuses them.
 * The file is named by the scene's size, step, sample interval and a hash of the tissue parameters,
 * the boundary conditions (attachment, muscle load),
 * the cycle, the controls and the code's version ({@link org.tensim.io.Provenance#codeVersion}), so that another
 * scene, or the same scene built or stepped by other code, never reads it. Format (big-endian): the diaphragm
 * node count and the apex node (ints), then per sample its time (s) and the 3 n displacements (m).
 */
final class ReferenceCache {
    private ReferenceCache() {
    }

    /** Where the samples of this scene's reference are kept. */
    static Path file(Path out, int rings, DiaphragmScene scene, DiaphragmParameters p,
            org.tensim.scene.diaphragm.BoundaryConditions bc, BreathingCycle cycle, DiaphragmControls controls) {
        int key = java.util.Objects.hash(p.toString(), bc.toString(), cycle.periodS(), cycle.expirationRatio(),
                cycle.pauseShare(),
                controls.ribAmplitude(), controls.muscleAmplitudePa(), org.tensim.io.Provenance.codeVersion());
        return out.resolve(String.format(Locale.ROOT, "rk2-reference-%drings-%dnodes-%dsprings-dt%.6e-every%.3fs-%08x.bin",
                rings, scene.topology().nodeCount(), scene.topology().springs().size(), scene.recommendedTimeStep(),
                StudyRun.SAMPLE_S, key));
    }

    /**
     * Where the samples of a scene's reference other than the double dome's RK2 are kept ({@link ThoraxRealTimeStudy}):
     * named by the configuration, the scene's size, the step and a hash of {@code definition}'s text (the caller's
     * scene definition with a digest of its files' contents, {@link org.tensim.io.FileDigest}) and of the code's
     * version.
     */
    static Path file(Path out, String config, DiaphragmScene scene, Object definition, double dt) {
        int key = (definition + " " + org.tensim.io.Provenance.codeVersion()).hashCode();
        return out.resolve(String.format(Locale.ROOT, "%s-reference-%dnodes-dt%.6e-every%.3fs-%08x.bin", config,
                scene.topology().nodeCount(), dt, StudyRun.SAMPLE_S, key));
    }

    /**
     * The first {@code count} samples in {@code file} if it holds them at the given times (within one RK2
     * step), else null.
     */
    static List<double[]> load(Path file, int nd, int apex, double[] times, double dt) throws IOException {
        if (!Files.isRegularFile(file)) {
            return null;
        }
        try (DataInputStream in = new DataInputStream(new BufferedInputStream(Files.newInputStream(file)))) {
            if (in.readInt() != nd || in.readInt() != apex) {
                return null;
            }
            List<double[]> samples = new ArrayList<>();
            for (double t : times) {
                double ts = in.readDouble();
                if (Math.abs(ts - t) > dt) {
                    return null;
                }
                double[] d = new double[3 * nd];
                for (int k = 0; k < d.length; k++) {
                    d[k] = in.readDouble();
                }
                samples.add(d);
            }
            return samples;
        } catch (java.io.EOFException e) {
            return null; // fewer samples than asked: the reference is run again
        }
    }

    static void save(Path file, StudyRun r, int apex) throws IOException {
        int nd = r.samples().get(0).length / 3;
        try (DataOutputStream o = new DataOutputStream(new BufferedOutputStream(Files.newOutputStream(file)))) {
            o.writeInt(nd);
            o.writeInt(apex);
            for (int s = 0; s < r.samples().size(); s++) {
                o.writeDouble(r.sampleTimesS()[s]);
                for (double d : r.samples().get(s)) {
                    o.writeDouble(d);
                }
            }
        }
    }
}

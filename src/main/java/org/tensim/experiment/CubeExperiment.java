package org.tensim.experiment;

import org.tensim.scene.CubeParameters;
import org.tensim.scene.file.CubeSceneFile;
import org.tensim.scene.file.Scene;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/**
 * The paper's cube comparison (Fig. 3): the mass-spring and the tensegrity cube
 * run side by side, in lockstep, under the same sinusoidal force; the
 * displacement of point P of each is sampled after every step. The cubes, their
 * fixed bottoms, loads and point P are the scene file docs/examples/cube.yaml's
 * ({@link CubeSceneFile}), with the parameters' values set over the file's.
 */
public final class CubeExperiment {
    /** Peak Y displacement of P reported by the paper for the MSS cube, m. */
    public static final double PAPER_MSS_PEAK_Y_M = -8;
    /** Peak Y displacement of P reported by the paper for the TS cube, m. */
    public static final double PAPER_TS_PEAK_Y_M = -0.075;

    /** Receives one sample per step: time (s) and P's displacement (m) in both cubes. */
    @FunctionalInterface
    public interface SampleSink {
        void sample(double t, double[] mssDisplacement, double[] tsDisplacement) throws java.io.IOException;
    }

    /**
     * Outcome of a run.
     *
     * @param mssPeakY  most negative Y displacement of P in the MSS cube, m
     * @param tsPeakY   most negative Y displacement of P in the TS cube, m
     * @param steps     steps made by each cube
     * @param wallS     wall time of the whole run, s
     * @param tsMaxLinkError largest relative rigid-link length error seen after projection
     */
    public record Result(double mssPeakY, double tsPeakY, long steps, double dtS, double wallS,
            double tsMaxLinkError) {
    }

    private final CubeParameters p;
    private final Simulation mss;
    private final Simulation ts;
    private final int mssProbe;
    private final int tsProbe;

    /** Both cubes with the paper's RK2 integrator. */
    public CubeExperiment(CubeParameters p) {
        this(p, "rk2");
    }

    /** Both cubes with the named integrator (see {@link Integrators#names()}). */
    public CubeExperiment(CubeParameters p, String integrator) {
        this.p = p;
        Scene s = CubeSceneFile.load(p);
        mss = new Simulation(SystemState.compile(s.bodies().get(CubeSceneFile.MASS_SPRING).topology()),
                Integrators.create(integrator));
        ts = new Simulation(SystemState.compile(s.bodies().get(CubeSceneFile.TENSEGRITY).topology()),
                Integrators.create(integrator));
        mssProbe = CubeSceneFile.probe(s, CubeSceneFile.MASS_SPRING);
        tsProbe = CubeSceneFile.probe(s, CubeSceneFile.TENSEGRITY);
    }

    public Simulation massSpring() {
        return mss;
    }

    public Simulation tensegrity() {
        return ts;
    }

    /** Runs both cubes for the configured duration, passing every step's sample to sink. */
    public Result run(SampleSink sink) throws java.io.IOException {
        long start = System.nanoTime();
        double[] dm = new double[3];
        double[] dt = new double[3];
        double mssPeak = 0;
        double tsPeak = 0;
        double linkErr = 0;
        long n = p.steps();
        sink.sample(0, dm, dt);
        for (long i = 0; i < n; i++) {
            mss.step(p.dtS());
            ts.step(p.dtS());
            linkErr = Math.max(linkErr, ts.projection().maxRelativeError());
            mss.state().displacement(mssProbe, dm);
            ts.state().displacement(tsProbe, dt);
            mssPeak = Math.min(mssPeak, dm[1]);
            tsPeak = Math.min(tsPeak, dt[1]);
            sink.sample(mss.time(), dm, dt);
        }
        return new Result(mssPeak, tsPeak, n, p.dtS(), (System.nanoTime() - start) / 1e9, linkErr);
    }
}

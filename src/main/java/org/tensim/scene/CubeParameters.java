package org.tensim.scene;

import org.tensim.model.Check;
import org.tensim.model.Vec3;

/**
 * Every parameter of the paper's cube experiment (Fig. 3) in one place. The
 * paper gives none but the size (10 x 10 x 10 m) and the peaks it measured;
 * {@link #paper()} holds the values chosen to reproduce those peaks, and
 * {@code docs/cube.md} explains how they were chosen.
 *
 * @param sideM             cube side, m (paper: 10)
 * @param nodeMassKg        mass of every node, kg
 * @param stiffnessNPerM    stiffness of every spring, N/m
 * @param dampingNsPerM     axial damping of every spring, N s/m
 * @param forceAmplitudeN   peak of the sinusoidal force on each loaded node, N
 * @param forceFrequencyHz  frequency of the force, Hz
 * @param forceTiltDeg      angle of the force from straight down (-y) towards +x, degrees
 * @param dtS               time step, s
 * @param durationS         simulated time, s
 */
public record CubeParameters(double sideM, double nodeMassKg, double stiffnessNPerM, double dampingNsPerM,
        double forceAmplitudeN, double forceFrequencyHz, double forceTiltDeg, double dtS, double durationS) {
    public CubeParameters {
        Check.positive("cube side", "m", sideM);
        Check.positive("cube node mass", "kg", nodeMassKg);
        Check.positive("cube spring stiffness", "N/m", stiffnessNPerM);
        Check.nonNegative("cube spring damping", "N s/m", dampingNsPerM);
        Check.nonNegative("cube force amplitude", "N", forceAmplitudeN);
        Check.positive("cube force frequency", "Hz", forceFrequencyHz);
        Check.finite("cube force tilt", "degrees", forceTiltDeg);
        if (Math.abs(forceTiltDeg) >= 90) {
            throw new IllegalArgumentException("cube force tilt must be between -90 and 90 degrees, got "
                    + forceTiltDeg);
        }
        Check.positive("cube time step", "s", dtS);
        Check.positive("cube duration", "s", durationS);
        if (dtS > durationS) {
            throw new IllegalArgumentException("cube time step " + dtS + " s is longer than the run (" + durationS
                    + " s): the run would make no step; give a time step <= the duration");
        }
    }

    /** The defaults used by {@code ./tensim cube}; see docs/cube.md. */
    public static CubeParameters paper() {
        return new CubeParameters(10, 1, 100, 2, 400, 0.25, 3, 1e-3, 4);
    }

    public CubeParameters withTimeStep(double s) {
        return new CubeParameters(sideM, nodeMassKg, stiffnessNPerM, dampingNsPerM, forceAmplitudeN,
                forceFrequencyHz, forceTiltDeg, s, durationS);
    }

    public CubeParameters withDuration(double s) {
        return new CubeParameters(sideM, nodeMassKg, stiffnessNPerM, dampingNsPerM, forceAmplitudeN,
                forceFrequencyHz, forceTiltDeg, dtS, s);
    }

    /** Unit direction of the force: down (-y), tilted towards +x. */
    public Vec3 forceDirection() {
        double r = Math.toRadians(forceTiltDeg);
        return new Vec3(Math.sin(r), -Math.cos(r), 0);
    }

    /** Number of steps of a run. */
    public long steps() {
        return Math.round(durationS / dtS);
    }
}

package org.tensim.scene.diaphragm;

import java.util.List;
import org.tensim.model.Check;
import org.tensim.model.ForceLaw;

/**
 * Muscle action after Nedel and Thalmann (1998), as the paper uses it: vertical
 * (inferior-superior) action lines through given points, each with a radius of
 * action. At breathing level {@code s(t)} a muscle node i at horizontal distance
 * {@code d_i} from its nearest line gets the vertical force
 * <pre>
 *   f_i = - P s(t) w(d_i) A_i / 2 e_z,      w(d) = cos^2(pi d / (2 R))  for d &lt; R,   0 beyond
 * </pre>
 * with P the live muscle amplitude of {@link DiaphragmControls} (Pa), A_i the
 * node's share of the shell's area (both faces: hence the half, so that P is a force
 * per unit area of the diaphragm) and R the line's radius of action. The intensity
 * is 1 on the line and falls smoothly (zero slope) to 0 at R. The force pulls the
 * dome down (contraction) during inspiration and vanishes as s falls during
 * expiration (relaxation); where several lines cover a node the largest weight is
 * used. Tendon nodes get no force: the central tendon is not contractile.
 */
public final class ActionLines {
    /**
     * One vertical action line.
     *
     * @param x       x of the line, m
     * @param y       y of the line, m
     * @param radiusM radius of action R, m (> 0)
     */
    public record Line(double x, double y, double radiusM) {
        public Line {
            Check.finite("action line x", "m", x);
            Check.finite("action line y", "m", y);
            Check.positive("action line radius", "m", radiusM);
        }
    }

    private final List<Line> lines;
    private final BreathingCycle cycle;
    private final DiaphragmControls controls;
    private double cachedTime = Double.NaN;
    private double cachedLevel;

    public ActionLines(List<Line> lines, BreathingCycle cycle, DiaphragmControls controls) {
        if (lines.isEmpty()) {
            throw new IllegalArgumentException("at least one action line is needed");
        }
        this.lines = List.copyOf(lines);
        this.cycle = cycle;
        this.controls = controls;
    }

    public List<Line> lines() {
        return lines;
    }

    /** The intensity w at horizontal position (x, y), in [0, 1]: the largest over the lines. */
    public double weight(double x, double y) {
        double w = 0;
        for (Line l : lines) {
            double d = Math.hypot(x - l.x(), y - l.y());
            if (d < l.radiusM()) {
                double c = Math.cos(0.5 * Math.PI * d / l.radiusM());
                w = Math.max(w, c * c);
            }
        }
        return w;
    }

    /**
     * P s(t), Pa. Cached per time value: every muscle node asks at each force pass, and
     * the breathing level is the same for all of them.
     */
    public double pressurePa(double t) {
        if (t != cachedTime) {
            cachedLevel = cycle.level(t);
            cachedTime = t;
        }
        return controls.muscleAmplitudePa() * cachedLevel;
    }

    /**
     * The force law of one node: {@code f_z -= areaWeight * P s(t)}.
     *
     * @param areaWeightM2 {@code w(d_i) A_i / 2}, m^2
     */
    public ForceLaw lawFor(double areaWeightM2) {
        Check.nonNegative("action line area weight", "m^2", areaWeightM2);
        return (t, f, o) -> f[o + 2] -= areaWeightM2 * pressurePa(t);
    }
}

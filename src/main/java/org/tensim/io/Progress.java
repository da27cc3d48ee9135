package org.tensim.io;

import java.io.PrintStream;
import java.util.Locale;
import me.tongfei.progressbar.ConsoleProgressBarConsumer;
import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import me.tongfei.progressbar.ProgressBarStyle;

/**
 * Progress of a long run, on standard error only (standard output stays the
 * command's result). On a terminal: a progress bar (me.tongfei:progressbar) with
 * the simulated time, the real-time factor (simulated seconds per wall second)
 * and the ETA, shown once the run has lasted {@value #QUIET_S} s. Without a
 * terminal (a pipeline): one line per {@value #LINE_PERCENT} % of the run, from
 * {@value #QUIET_S} s on, so that short runs print nothing extra. The variable
 * TENSIM_PROGRESS=bar|lines|none overrides the choice.
 * {@link #update} is cheap (a comparison) between refreshes.
 */
public final class Progress implements AutoCloseable {
    /** Runs shorter than this print no progress, s. */
    static final double QUIET_S = 2;
    /** Step between progress lines without a terminal, percent. */
    static final int LINE_PERCENT = 10;
    private static final int BAR_TICKS = 1000;

    private enum Mode { BAR, LINES, NONE }

    private final String task;
    private final double totalS;
    private final Mode mode;
    private final PrintStream err;
    private final double quietS;
    private final long start = System.nanoTime();
    private double nextCheck;
    private int nextPercent = LINE_PERCENT;
    private ProgressBar bar;

    private Progress(String task, double totalS, Mode mode, PrintStream err, double quietS) {
        this.task = task;
        this.totalS = totalS;
        this.mode = mode;
        this.err = err;
        this.quietS = quietS;
    }

    /** Progress of {@code task} over {@code totalSimulatedS} seconds of simulated time. */
    public static Progress start(String task, double totalSimulatedS) {
        return new Progress(task, totalSimulatedS, mode(System.getenv("TENSIM_PROGRESS"), System.console() != null),
                System.err, QUIET_S);
    }

    /** Progress lines (no terminal) into {@code err}, from {@code quietS} seconds on: for tests. */
    static Progress lines(String task, double totalSimulatedS, PrintStream err, double quietS) {
        return new Progress(task, totalSimulatedS, Mode.LINES, err, quietS);
    }

    private static Mode mode(String setting, boolean terminal) {
        if (setting != null) {
            switch (setting.trim().toLowerCase(Locale.ROOT)) {
                case "bar": return Mode.BAR;
                case "lines": return Mode.LINES;
                case "none": return Mode.NONE;
                default: break;
            }
        }
        return terminal ? Mode.BAR : Mode.LINES;
    }

    /** Reports simulated time {@code t} (s). */
    public void update(double t) {
        if ((t < nextCheck && t < totalS) || mode == Mode.NONE || !(totalS > 0)) {
            return;
        }
        nextCheck = t + totalS / BAR_TICKS;
        double wall = (System.nanoTime() - start) / 1e9;
        if (wall < quietS) {
            return;
        }
        double rt = t / Math.max(wall, 1e-9);
        String extra = String.format(Locale.ROOT, "t = %.3f of %.3f s, %.3g x real time", t, totalS, rt);
        if (mode == Mode.BAR) {
            try {
                if (bar == null) {
                    // Created late (after the quiet time): it starts from where the run is, so its ETA is right.
                    bar = new ProgressBarBuilder().setTaskName(task).setInitialMax(BAR_TICKS)
                            .startsFrom(Math.round(BAR_TICKS * t / totalS), java.time.Duration.ofNanos(
                                    System.nanoTime() - start))
                            .setStyle(ProgressBarStyle.ASCII).setUpdateIntervalMillis(500).continuousUpdate()
                            .setConsumer(new ConsoleProgressBarConsumer(err)).build();
                }
                bar.stepTo(Math.min(BAR_TICKS, Math.round(BAR_TICKS * t / totalS)));
                bar.setExtraMessage(extra);
                return;
            } catch (RuntimeException | LinkageError e) {
                bar = null;
                // a terminal the library cannot drive: fall back to lines
            }
        }
        int percent = (int) Math.floor(100 * t / totalS);
        if (percent >= nextPercent) {
            double eta = (totalS - t) / Math.max(rt, 1e-12);
            err.println(String.format(Locale.ROOT, "%s: %d %%, %s, ETA %.0f s", task, percent, extra, eta));
            nextPercent = (percent / LINE_PERCENT + 1) * LINE_PERCENT;
        }
    }

    /** Ends the bar (if one was shown). */
    @Override
    public void close() {
        if (bar != null) {
            bar.close();
            bar = null;
        }
    }
}

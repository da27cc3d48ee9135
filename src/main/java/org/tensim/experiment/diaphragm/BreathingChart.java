package org.tensim.experiment.diaphragm;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.knowm.xchart.XYChart;
import org.tensim.io.Charts;

/** breathing.png of a diaphragm run, from its probe.csv. */
final class BreathingChart {
    private BreathingChart() {
    }

    /**
     * The chart of probe.csv: the dome apex's vertical displacement and the diaphragm's transverse and
     * antero-posterior extent changes against time, mm; the divergence marked when there was one (NaN: none).
     */
    static void write(Path png, Path probeCsv, double divergedAt) throws IOException {
        List<String> lines = Files.readAllLines(probeCsv);
        int n = lines.size() - 1;
        if (n < 2) {
            return;
        }
        double[] t = new double[n];
        double[] dz = new double[n];
        double[] ex = new double[n];
        double[] ey = new double[n];
        for (int i = 0; i < n; i++) {
            String[] f = lines.get(i + 1).split(",");
            t[i] = Double.parseDouble(f[0]);
            dz[i] = Double.parseDouble(f[2]);
            ex[i] = Double.parseDouble(f[3]) - Double.parseDouble(lines.get(1).split(",")[3]);
            ey[i] = Double.parseDouble(f[4]) - Double.parseDouble(lines.get(1).split(",")[4]);
        }
        XYChart c = Charts.lineChart("Breathing: dome apex and diaphragm extents (all nodes)", "t, s", "mm", 900,
                500);
        c.getStyler().setXAxisDecimalPattern("0.0");
        Charts.addLine(c, "apex z displacement", t, dz);
        Charts.addLine(c, "transverse extent change", t, ex);
        Charts.addLine(c, "antero-posterior extent change", t, ey);
        if (!Double.isNaN(divergedAt)) {
            Charts.markDiverged(c, divergedAt);
        }
        Charts.savePng(c, png);
    }
}

package org.tensim.app;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.tensim.analysis.lungs.MeasuredCase;
import org.tensim.analysis.lungs.SiProfile;
import org.tensim.cli.OptionChecks;
import org.tensim.io.Json;
import org.tensim.io.ProjectFolder;
import org.tensim.io.landmarks.DirLabLandmarks;
import org.tensim.io.landmarks.LandmarkFormatException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code tensim lung-landmarks}: the measured DIR-Lab cases' figures of lung motion, in normalised terms. */
@Command(name = "lung-landmarks", mixinStandardHelpOptions = true,
        description = {"Prints the figures of lung motion that the DIR-Lab 4D-CT landmarks give (docs/lungs.md).",
            "For each case, from its 300 landmarks at end-exhale and end-inhale: the superior-inferior displacement"
                + " in five bins of normalised height (0 at the apex, 1 at the base) as ratios to the basal bin, the"
                + " basal superior-inferior displacement in mm and the mean 3D displacement; from its 75 landmarks"
                + " at six phases, each phase's share of the end-inhale displacement. Both lungs together, then each"
                + " lung (split at the gap across x). The last line is one JSON object with every figure, by case."})
public final class LungLandmarksCommand implements Callable<Integer> {
    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Option(names = "--landmarks", paramLabel = "DIR", description = "The folder of the caseN-300-ee-ei.csv and"
            + " caseN-75-six-phases.csv files (default: ../shared/data/4dct-lung-landmarks).")
    Path folder;

    @Option(names = "--cases", split = ",", paramLabel = "N[,N...]",
            description = "The cases to read, 1 to 5 (default: ${DEFAULT-VALUE}).")
    List<Integer> cases = List.of(1, 2, 3, 4, 5);

    @Override
    public Integer call() throws Exception {
        Path dir = folder != null ? folder : ProjectFolder.resolve("..", "shared", "data", "4dct-lung-landmarks");
        if (!Files.isDirectory(dir)) {
            throw OptionChecks.usage(spec, "--landmarks " + dir + ": no such folder (expected the folder of the"
                    + " DIR-Lab caseN-300-ee-ei.csv and caseN-75-six-phases.csv files)");
        }
        PrintWriter out = spec.commandLine().getOut();
        Map<String, Object> all = new LinkedHashMap<>();
        out.println("case  lung     points  SI ratio by height bin, apex to base   basal SI  mean 3D"
                + "  share t10 t20 t30 t40");
        for (int n : cases) {
            if (n < 1 || n > 5) {
                throw OptionChecks.usage(spec, "--cases " + n + ": expected a case from 1 to 5");
            }
            MeasuredCase c;
            try {
                c = MeasuredCase.read(dir, n);
            } catch (LandmarkFormatException e) {
                throw OptionChecks.usage(spec, e.getMessage());
            }
            row(out, n, "both", c.both(), c.shares());
            row(out, n, "low x", c.lowX(), c.sharesLowX());
            row(out, n, "high x", c.highX(), c.sharesHighX());
            all.put("case" + n, c.toMap());
        }
        out.println("(SI in mm towards the feet; shares: least-squares factor of the end-inhale field, t50 end-"
                + "exhale = 0, t00 end-inhale = 1.)");
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("source", "DIR-Lab (Castillo et al. 2009, 2010) in " + dir);
        json.put("cases", all);
        out.println(Json.line(json));
        out.flush();
        return 0;
    }

    private static void row(PrintWriter out, int n, String lung, SiProfile p, double[] s) {
        double[] r = p.ratio();
        out.println(String.format(Locale.ROOT, "%4d  %-7s %6d  %5.2f %5.2f %5.2f %5.2f %5.2f          %6.2f mm"
                + " %5.2f mm   %5.2f %5.2f %5.2f %5.2f", n, lung, p.points(), r[0], r[1], r[2], r[3], r[4],
                p.basalSiM() * 1e3, p.mean3dM() * 1e3, s[1], s[2], s[3], s[4]));
    }
}

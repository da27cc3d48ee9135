package org.tensim.experiment.diaphragm;

import java.io.IOException;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Pattern;
import org.tensim.io.CsvWriter;
import org.tensim.io.Json;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.solver.integrators.Integrators;
import org.tensim.solver.prefactored.PrefactoredBdf2;

/**
 * The real-time setting on a diaphragm in a thorax (bone surfaces, sliding contact): each configuration run from
 * rest on the one scene given, with the scene-graph sync of the GUI after every step, timed, and compared with the
 * converged contact step at its small step ({@value Integrators#CONTACT} at {@link Integrators#CONTACT_STEP_S}), the
 * scene's own reference (RK2's stable step with contact is too small to run: docs/thorax.md). The errors are
 * {@link StudyRun#errorAgainst}'s (relative RMS of the diaphragm's displacement field at the end and at the worst
 * 50 ms sample, the apex's descent), the tolerance {@link RealTimeStudy}'s. The real-time setting runs again with
 * contact off (the same scene's other bodies, the bones not touched): its step's cost beside the cost with contact;
 * its errors say how much contact changes the answer, not the solver's error.
 */
public final class ThoraxRealTimeStudy {
    /** Label of the reference configuration. */
    static final String REFERENCE = String.format(Locale.ROOT, "%s at %.0f ms / 2 threads (reference)",
            Integrators.CONTACT, 1e3 * Integrators.CONTACT_STEP_S);
    /** Label of the real-time setting in a thorax. */
    static final String SETTING = String.format(Locale.ROOT, "%s at %.0f ms / 2 threads",
            Integrators.CONTACT_REAL_TIME, 1e3 * Integrators.REAL_TIME_STEP_S);
    /** Label of the real-time setting with contact off. */
    static final String WITHOUT_CONTACT = String.format(Locale.ROOT, "%s at %.0f ms without contact / 2 threads",
            Integrators.CONTACT_REAL_TIME, 1e3 * Integrators.REAL_TIME_STEP_S);

    private ThoraxRealTimeStudy() {
    }

    /** The configurations, the reference first; the last runs on the scene without contact. */
    static List<RealTimeStudy.Config> configs() {
        List<RealTimeStudy.Config> c = new ArrayList<>();
        c.add(new RealTimeStudy.Config(REFERENCE, () -> Integrators.create(Integrators.CONTACT),
                Integrators.CONTACT_STEP_S, 2, false));
        c.add(new RealTimeStudy.Config(SETTING, () -> Integrators.create(Integrators.CONTACT_REAL_TIME),
                Integrators.REAL_TIME_STEP_S, 2, false));
        c.add(new RealTimeStudy.Config(String.format(Locale.ROOT, "%s at %.0f ms without tied links / 2 threads",
                Integrators.CONTACT_REAL_TIME, 1e3 * Integrators.REAL_TIME_STEP_S),
                () -> ((PrefactoredBdf2) Integrators.create(Integrators.CONTACT_REAL_TIME)).setLinkCoupling(0),
                Integrators.REAL_TIME_STEP_S, 2, false));
        c.add(new RealTimeStudy.Config(String.format(Locale.ROOT, "%s at %.0f ms (the double dome's setting) / 2"
                + " threads", Integrators.REAL_TIME, 1e3 * Integrators.REAL_TIME_STEP_S),
                () -> Integrators.create(Integrators.REAL_TIME), Integrators.REAL_TIME_STEP_S, 2, false));
        c.add(new RealTimeStudy.Config(WITHOUT_CONTACT, () -> Integrators.create(Integrators.CONTACT_REAL_TIME),
                Integrators.REAL_TIME_STEP_S, 2, false));
        return c;
    }

    /**
     * Runs the configurations whose label {@code only} finds (null: all; the reference always runs) for
     * {@code seconds} (capped at one breathing period), writes {@code realtime.csv} and {@code realtime.json} to
     * {@code out}, and returns the summary.
     *
     * @param scene          the diaphragm in its thorax, with contact
     * @param withoutContact the same scene with contact off (for the cost of a step without it)
     * @param source         what the scene was built from, for the summary
     * @param definition     the scene's definition with a digest of its files, whose text names the reference's
     *                       samples kept in {@code out} (a study run again on the same scene reuses them;
     *                       {@link ReferenceCache})
     */
    public static Map<String, Object> run(DiaphragmScene scene, DiaphragmScene withoutContact, String source,
            Object definition, Pattern only, double seconds, Path out, PrintStream log) throws IOException {
        Files.createDirectories(out);
        double runS = Math.min(seconds, scene.cycle().periodS());
        List<Map<String, Object>> rows = new ArrayList<>();
        StudyRun reference = null;
        Map<String, Object> setting = null;
        Map<String, Object> settingWithout = null;
        try (CsvWriter csv = new CsvWriter(out.resolve("realtime.csv"), List.of("config", "contact", "dt_s",
                "realtime_factor", "realtime_factor_cpu", "ms_per_step", "apex_descent_mm", "cg_products_per_step",
                "error_vs_reference", "worst_error_vs_reference", "apex_difference_mm"), 1)) {
            for (RealTimeStudy.Config c : configs()) {
                boolean isReference = c.label().equals(REFERENCE);
                if (!isReference && only != null && !only.matcher(c.label()).find()) {
                    continue;
                }
                boolean contact = !c.label().equals(WITHOUT_CONTACT);
                StudyRun r = isReference
                        ? StudyRun.reference(scene, "thorax", c, runS, ReferenceCache.file(out, Integrators.CONTACT,
                                scene, definition, c.dt()), log)
                        : StudyRun.simulate(contact ? scene : withoutContact, "thorax", c.label(), c, runS);
                reference = isReference ? r : reference;
                double[] e = r.errorAgainst(reference);
                Map<String, Object> row = row(c, contact, r, e);
                rows.add(row);
                setting = c.label().equals(SETTING) ? row : setting;
                settingWithout = c.label().equals(WITHOUT_CONTACT) ? row : settingWithout;
                csv.rowText(c.label(), String.valueOf(contact), String.valueOf(r.run().dt()),
                        String.valueOf(r.realtimeWall()), String.valueOf(r.realtimeCpu()),
                        String.valueOf(row.get("ms_per_step")), String.valueOf(r.apexDescentMm()),
                        String.valueOf(r.productsPerStep()), String.valueOf(e[0]), String.valueOf(e[1]),
                        String.valueOf(e[3]));
                if (log != null) {
                    log.println(String.format(Locale.ROOT, "%s: %.3f of real time (wall), %.3f (CPU), %.1f ms a"
                            + " step; against the reference %.4f at the end, %.4f at worst (t = %.2f s), apex %+.2f"
                            + " mm%s", c.label(), r.realtimeWall(), r.realtimeCpu(), row.get("ms_per_step"), e[0],
                            e[1], e[2], e[3], r.diverged() ? ", diverged" : ""));
                }
            }
        }
        Map<String, Object> summary = new LinkedHashMap<>();
        summary.put("scene", source);
        summary.put("simulated_s_per_run", runS);
        summary.put("reference", REFERENCE);
        summary.put("sync", "positions copied to a float vertex array after every step (as the GUI's scene graph)");
        summary.put("tolerance", "relative RMS displacement error against the reference <= " + RealTimeStudy.TOLERANCE
                + " at the end and at the worst sample, apex descent within " + RealTimeStudy.APEX_TOLERANCE_MM
                + " mm of the reference's at the end");
        summary.put("load_average", DiaphragmReport.round(
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage(), 2));
        if (setting != null) {
            Map<String, Object> s = new LinkedHashMap<>(setting);
            if (settingWithout != null) {
                s.put("ms_per_step_without_contact", settingWithout.get("ms_per_step"));
                s.put("realtime_factor_without_contact", settingWithout.get("realtime_factor"));
                s.put("realtime_factor_cpu_without_contact", settingWithout.get("realtime_factor_cpu"));
            }
            summary.put("realtime_setting", s);
        }
        summary.put("runs", rows);
        Json.write(out.resolve("realtime.json"), summary);
        return summary;
    }

    /** One row of the study's table. */
    private static Map<String, Object> row(RealTimeStudy.Config c, boolean contact, StudyRun r, double[] e) {
        Map<String, Object> row = new LinkedHashMap<>();
        row.put("config", c.label());
        row.put("contact", contact);
        row.put("nodes", r.run().nodes());
        row.put("threads", c.threads());
        row.put("dt_s", r.run().dt());
        row.put("realtime_factor", DiaphragmReport.round(r.realtimeWall(), 4));
        row.put("realtime_factor_cpu", DiaphragmReport.round(r.realtimeCpu(), 4));
        row.put("ms_per_step", DiaphragmReport.round(1e3 * r.run().dt() / r.realtimeWall(), 2));
        row.put("apex_descent_mm", DiaphragmReport.round(r.apexDescentMm(), 3));
        row.put("cg_products_per_step", DiaphragmReport.round(r.productsPerStep(), 1));
        row.put("error_vs_reference", DiaphragmReport.round(e[0], 4));
        row.put("worst_error_vs_reference", DiaphragmReport.round(e[1], 4));
        row.put("worst_error_time_s", DiaphragmReport.round(e[2], 3));
        row.put("apex_difference_mm", DiaphragmReport.round(e[3], 3));
        row.put("worst_apex_difference_mm", DiaphragmReport.round(e[4], 3));
        row.put("within_tolerance", contact && e[0] <= RealTimeStudy.TOLERANCE && e[1] <= RealTimeStudy.TOLERANCE
                && e[3] <= RealTimeStudy.APEX_TOLERANCE_MM);
        row.put("diverged", r.diverged());
        return row;
    }
}

package org.tensim.experiment.lungs;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.experiment.diaphragm.DiaphragmReport;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.BreathingCycle;
import org.tensim.scene.diaphragm.DiaphragmControls;
import org.tensim.scene.diaphragm.DiaphragmParameters;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.diaphragm.DoubleDomeGenerator;
import org.tensim.scene.diaphragm.ParametricRibCage;
import org.tensim.scene.lungs.ThoraxOrgans;
import org.tensim.scene.rigid.RigidMeshes;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * A headless diaphragm run with two small lungs, a 1 s breath: lung-points.csv has the header, one row per point
 * every 0.05 s over the measured cycle, listed in the run's files and manifest, and summary.json's lung_points and
 * organs.
 */
class OrganRecorderTest {
    @Test
    void theRunWritesTheLungPointsAndTheOrgansFigures(@TempDir Path dir) throws Exception {
        DiaphragmScene scene = DiaphragmScene.build(TwoSurfaces.split(DoubleDomeGenerator.shell(
                DoubleDomeGenerator.Shape.adult().withRings(12))), ParametricRibCage.adult(),
                DiaphragmParameters.defaults(), new BreathingCycle(1.0, 2.0),
                new DiaphragmControls(1, DiaphragmSetup.defaultMusclePa()), null, BoundaryConditions.defaults());
        List<org.tensim.io.mesh.TriangleMesh> lungs = List.of(ball(-0.06), ball(0.06));
        ThoraxOrgans.Options o = ThoraxOrgans.Options.defaults().withoutLiver().withCells(0.015, 0.03);
        o = new ThoraxOrgans.Options(o.lung(), null, o.rules(), o.pleuraPaPerM(), o.liverPaPerM(),
                o.liverHoldPaPerM(), o.liverBelowPaPerM(), o.liverReachM(), o.followerBandM(), 20,
                new double[] {-0.06, -0.12, 1.24});
        ThoraxOrgans organs = ThoraxOrgans.build(scene, lungs, null, o);
        scene.setRecorder(new OrganRecorder(organs, organs.install(scene)));
        Path out = dir.resolve("run");
        Map<String, Object> summary = DiaphragmReport.run(new DiaphragmSetup.Built(scene, null,
                DiaphragmSetup.SurfaceMode.SHELL, "test"), new DiaphragmReport.Options(1.0, 0, 0, 100, 0.01, null),
                out, null);
        List<String> rows = Files.readAllLines(out.resolve("lung-points.csv"));
        assertEquals("t_s,point,lung,x_mm,y_mm,z_mm", rows.get(0));
        int points = 21;
        assertEquals(1 + points * 21, rows.size(), "21 points (20 drawn, 1 probe) at 21 instants 0, 0.05 .. 1 s");
        assertTrue(rows.get(1).startsWith("0.0000,0,"), rows.get(1));
        assertTrue(rows.get(rows.size() - 1).startsWith("1.0000,20,right,"), "the probe is in the right lung: "
                + rows.get(rows.size() - 1));
        @SuppressWarnings("unchecked")
        Map<String, Object> lp = (Map<String, Object>) summary.get("lung_points");
        assertEquals(0.0, ((Number) lp.get("end_exhale_s")).doubleValue(), 1e-12);
        assertEquals(1.0 / 3, ((Number) lp.get("end_inhale_s")).doubleValue(), 1e-9, "Ti = T / (1 + E/I)");
        assertEquals(List.of(0, 0, 1), lp.get("superior"));
        assertTrue(summary.containsKey("organs"), "the organs' figures");
        @SuppressWarnings("unchecked")
        Map<String, Object> organFigures = (Map<String, Object>) summary.get("organs");
        List<?> breaths = (List<?>) organFigures.get("breaths");
        assertEquals(1, breaths.size(), "one end-inspiration in a 1 s run of a 1 s breath: " + breaths);
        Map<?, ?> breath = (Map<?, ?>) breaths.get(0);
        assertEquals(1.0 / 3, ((Number) breath.get("end_inhale_s")).doubleValue(), 1e-3);
        assertTrue(((Number) breath.get("mean_3d_mm")).doubleValue() > 0, "the points moved: " + breath);
        assertTrue(!organFigures.containsKey("breath_to_breath_change"), "no change between breaths of one breath");
        for (String lung : new String[] {"right lung on the pleura", "left lung on the pleura"}) {
            Map<?, ?> c = (Map<?, ?>) organFigures.get(lung);
            double pen = ((Number) c.get("lung_surface_max_penetration_mm")).doubleValue();
            double sep = ((Number) c.get("lung_surface_max_separation_mm")).doubleValue();
            assertTrue(pen >= 0 && pen < 5 && sep >= 0 && sep < 5, lung + ": the lung's surface within mm of its"
                    + " pleura: " + c);
        }
        assertTrue(((List<?>) summary.get("files")).contains("lung-points.csv"), "listed: " + summary.get("files"));
        assertTrue(Files.readAllLines(out.resolve(org.tensim.io.RunFolder.MANIFEST)).contains("lung-points.csv"),
                "in the manifest, so that the next run in the folder removes it");
        System.out.println("organs: " + summary.get("organs"));
    }

    private static org.tensim.io.mesh.TriangleMesh ball(double xc) {
        return RigidMeshes.sphere(new double[] {xc, -0.12, 1.25}, 0.035);
    }
}

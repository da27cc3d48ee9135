package org.tensim.experiment.lungs;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.List;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.io.thorax.Thorax;
import org.tensim.io.thorax.ThoraxLoader;
import org.tensim.io.thorax.ThoraxPart;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.lungs.LungVolumes;
import org.tensim.scene.lungs.PleuraCarriers;
import org.tensim.scene.lungs.ThoraxOrgans;
import org.tensim.solver.SurfaceSliding;

/**
 * Adds the thorax's lungs (and liver) to a built thorax diaphragm scene for a headless run: reads the organs from
 * the thorax folder, builds them into the scene's state ({@link ThoraxOrgans}), installs their couplings and an
 * {@link OrganRecorder} that writes {@code lung-points.csv} and the organs' figures into the run's summary.
 */
public final class ThoraxOrganRun {
    private ThoraxOrganRun() {
    }

    /**
     * Builds and installs the organs of the thorax at {@code thoraxDir} into {@code scene}, saying what it built on
     * {@code log}.
     *
     * @throws IllegalArgumentException naming the folder when it has no lungs (or no liver with a liver asked for)
     */
    public static ThoraxOrgans attach(DiaphragmScene scene, Path thoraxDir, ThoraxOrgans.Options o, PrintStream log)
            throws IOException {
        long t0 = System.nanoTime();
        Thorax thorax = ThoraxLoader.load(thoraxDir, EnumSet.of(ThoraxPart.Group.LUNG, ThoraxPart.Group.LIVER));
        List<TriangleMesh> lungs = LungVolumes.surfaces(thorax);
        TriangleMesh liver = null;
        if (o.liver() != null) {
            List<ThoraxPart> l = thorax.group(ThoraxPart.Group.LIVER);
            if (l.isEmpty()) {
                throw new IllegalArgumentException(thorax.partsJson() + " lists no liver part (file liver*.obj):"
                        + " expected one for the liver volume (or leave the liver out)");
            }
            liver = l.get(0).mesh();
        }
        int before = scene.topology().nodeCount();
        ThoraxOrgans organs = ThoraxOrgans.build(scene, lungs, liver, o);
        List<SurfaceSliding> terms = organs.install(scene);
        scene.setRecorder(new OrganRecorder(organs, terms));
        if (log != null) {
            PleuraCarriers.Built r = organs.pleurae().get(0);
            PleuraCarriers.Built l = organs.pleurae().get(1);
            log.printf(java.util.Locale.ROOT, "organs: %d nodes added to the %d of the diaphragm scene (lungs %d + %d,"
                    + " liver %d, %d held at the bare area, %d on the abdomen); pleura right/left %d/%d vertices:"
                    + " diaphragm %d/%d, rib %d/%d, intercostal %d/%d,"
                    + " fixed %d/%d; followers %s; built in %.1f s%n", scene.topology().nodeCount() - before, before,
                    organs.lungs().get(0).body().nodeCount(), organs.lungs().get(1).body().nodeCount(),
                    organs.liver() == null ? 0 : organs.liver().nodeCount(), organs.liverHeld().length,
                    organs.liverSupported().length, r.surface().vertexCount(),
                    l.surface().vertexCount(), r.count(PleuraCarriers.Carrier.DIAPHRAGM),
                    l.count(PleuraCarriers.Carrier.DIAPHRAGM), r.count(PleuraCarriers.Carrier.RIB),
                    l.count(PleuraCarriers.Carrier.RIB), r.count(PleuraCarriers.Carrier.INTERCOSTAL),
                    l.count(PleuraCarriers.Carrier.INTERCOSTAL), r.count(PleuraCarriers.Carrier.FIXED),
                    l.count(PleuraCarriers.Carrier.FIXED),
                    terms.stream().map(t -> Integer.toString(t.pairCount())).toList(), (System.nanoTime() - t0) * 1e-9);
        }
        return organs;
    }
}

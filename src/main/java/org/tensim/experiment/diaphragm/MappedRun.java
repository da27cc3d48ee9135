package org.tensim.experiment.diaphragm;

import java.io.IOException;
import java.io.PrintStream;
import java.util.LinkedHashMap;
import java.util.Map;
import org.tensim.io.RunFolder;
import org.tensim.model.Check;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.diaphragm.MappedDiaphragm;
import org.tensim.solver.Integrator;
import org.tensim.solver.Simulation;
import org.tensim.solver.parallel.Parallelism;
import org.tensim.solver.stability.TimeStep;

/**
 * A headless diaphragm run with the mechanics at one resolution and the body at another ({@link MappedDiaphragm}):
 * the coarse scene is stepped, and the fine scene's nodes carried by it are what {@link DiaphragmReport} measures
 * (dome descents, extents, the breathing figures), exports (VTK, displacements.csv) and draws (the slices). The
 * summary says so: {@code drawn_nodes}, {@code mechanical_nodes} and {@code mechanics} (the coarse model's size and
 * the mapping's largest offset at rest); the caller adds the pick that chose the resolution.
 */
public final class MappedRun {
    private MappedRun() {
    }

    /**
     * Runs and writes every output but the summary into the folder; returns the summary's fields.
     *
     * @param fine    the scene drawn and measured (the 43-ring mesh)
     * @param mapped  the mapping of {@code fine}'s scene onto the coarse scene that runs
     * @param chosen  the mechanics' integrator
     * @param threads threads of the mechanics' step (>= 1)
     */
    public static Map<String, Object> run(DiaphragmSetup.Built fine, MappedDiaphragm mapped,
            DiaphragmReport.Options o, Integrator chosen, int threads, RunFolder out, PrintStream log)
            throws IOException {
        Check.atLeast("thread count", threads, 1);
        DiaphragmScene coarse = mapped.coarse();
        Simulation mechanics = mapped.newMechanics();
        mechanics.setIntegrator(chosen);
        // the coarse model's step: its stable step for the integrator when none is given
        TimeStep step = coarse.timeStep(chosen, o.dtS());
        DiaphragmReport.Options at = new DiaphragmReport.Options(o.seconds(), step.seconds(), o.vtkPerCycle(),
                o.vectorScale(), o.vectorIntervalS(), o.csvTimes());
        try (Parallelism par = threads > 1 ? Parallelism.install(mechanics, threads) : null) {
            Simulation carried = mapped.newCarried(mechanics);
            carried.setIntegrator(mapped.carrier(mechanics));
            Map<String, Object> s = DiaphragmReport.run(fine, at, carried, threads,
                    par == null ? new long[0] : par.pool().workerThreadIds(), out, log);
            s.put("dt_rule", step.reason() + " (the mechanics' model)");
            s.put("drawn_nodes", mapped.drawnNodes());
            s.put("mechanical_nodes", mapped.mechanicalNodes());
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("source", coarse.spec().mesh().describe());
            m.put("nodes", coarse.topology().nodeCount());
            m.put("diaphragm_nodes", coarse.diaphragmNodes());
            m.put("springs", coarse.topology().springs().size());
            m.put("rigid_links", coarse.topology().rigidLinks().size());
            m.put("unconverged_projections", mechanics.unconvergedProjections());
            m.put("max_mapping_offset_at_rest_mm", DiaphragmReport.round(1e3 * mapped.maxResidualM(), 3));
            if (mapped.contact() != null) {
                m.put("contact", "on the drawn mesh's surface: " + mapped.contact().pairCount() + " pairs on "
                        + mapped.contact().pointCount() + " of its points, their forces carried to the mechanics'"
                        + " nodes by the mapping's transpose (the summary's contact figures are the drawn mesh's)");
            }
            s.put("mechanics", m);
            return s;
        }
    }
}

package org.tensim.bench;

import java.nio.file.Path;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.io.thorax.Thorax;
import org.tensim.io.thorax.ThoraxLoader;
import org.tensim.io.thorax.ThoraxPart.Group;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.scene.lungs.LungVolumes;
import org.tensim.scene.lungs.ThoraxOrgans;
import org.tensim.scene.shell.TwoSurfaces;
import org.tensim.solver.Simulation;
import org.tensim.solver.Stage;
import org.tensim.solver.SurfaceSliding;
import org.tensim.solver.integrators.Integrators;
import org.tensim.solver.prefactored.Bdf2Part;
import org.tensim.solver.prefactored.PrefactoredBdf2;

/**
 * The cost of the lungs' sliding on the pleura: the thorax diaphragm decimated to about 10 mm edges with the lungs
 * built in ({@link ThoraxOrgans}, the liver left out), under {@code bdf2} at 2.5 ms on one thread with the thorax's
 * contact iterations. Prints the mean step's wall time (ms) and its Newton-Krylov parts over the timed steps (the
 * warm-up steps and the first factorisation left out) and the main thread's CPU time a step (ms: less sensitive to
 * other work on the machine), then, at the state reached, each sliding term's tangent product and force pass alone
 * (CPU ms each, averaged over repeats).
 *
 * <p>Usage: {@code java -cp 'build/install/tensim/lib/*' org.tensim.bench.LungSlidingBench THORAX_DIR MESH_MM.obj
 * [WARM_STEPS [TIMED_STEPS]]} (defaults 10 and 40).
 */
public final class LungSlidingBench {
    private LungSlidingBench() {
    }

    /** Runs the benchmark; see the class comment for the arguments. */
    public static void main(String[] args) throws Exception {
        Path thoraxDir = Path.of(args[0]);
        Path mesh = Path.of(args[1]);
        int warm = args.length > 2 ? Integer.parseInt(args[2]) : 10;
        int timed = args.length > 3 ? Integer.parseInt(args[3]) : 40;
        DiaphragmSpec spec = DiaphragmSpec.defaults().withCage(DiaphragmSpec.Cage.defaults().withThorax(thoraxDir));
        spec = spec.withMesh(spec.mesh().withFile(mesh, MeshUnits.parse("mm")));
        DiaphragmSetup.Inputs in = DiaphragmSetup.read(spec);
        TwoSurfaces s = in.surfaces().surfaces().decimated(0.010);
        DiaphragmScene scene = DiaphragmScene.build(s, spec, Map.of(), in.bones(), null, spec.newControls());
        Thorax thorax = ThoraxLoader.load(thoraxDir, EnumSet.of(Group.LUNG, Group.LIVER, Group.PLEURA));
        List<TriangleMesh> lungs = LungVolumes.surfaces(thorax);
        ThoraxOrgans organs = ThoraxOrgans.build(scene, lungs, null, ThoraxOrgans.Options.defaults());
        List<SurfaceSliding> terms = organs.install(scene);
        Simulation sim = scene.newSimulation();
        PrefactoredBdf2 bdf2 = (PrefactoredBdf2) Integrators.create("bdf2");
        if (spec.cage().boneSurfaces() && spec.cage().contact()) {
            bdf2.setNewtonIterations(PrefactoredBdf2.CONTACT_NEWTON_ITERATIONS);
            bdf2.setKrylovIterations(PrefactoredBdf2.CONTACT_KRYLOV_ITERATIONS);
        }
        sim.setIntegrator(bdf2);
        double dt = 0.0025;
        System.out.printf(Locale.ROOT, "%d nodes; terms %s%n", scene.topology().nodeCount(), terms);
        for (int i = 0; i < warm; i++) {
            sim.step(dt);
        }
        double[] before = parts(sim, bdf2);
        long products0 = bdf2.jacobianProducts();
        java.lang.management.ThreadMXBean mx = java.lang.management.ManagementFactory.getThreadMXBean();
        long cpu0 = mx.getCurrentThreadCpuTime();
        long t0 = System.nanoTime();
        for (int i = 0; i < timed; i++) {
            sim.step(dt);
        }
        double wall = (System.nanoTime() - t0) * 1e-6 / timed;
        double cpu = (mx.getCurrentThreadCpuTime() - cpu0) * 1e-6 / timed;
        double[] after = parts(sim, bdf2);
        StringBuilder out = new StringBuilder(String.format(Locale.ROOT, "steps %d-%d at %.4f s: wall %.1f ms a step"
                + " (cpu %.1f)", warm + 1, warm + timed, dt, wall, cpu));
        for (int p = 0; p < after.length; p++) {
            String name = p < Bdf2Part.values().length ? Bdf2Part.values()[p].name() : "INTEGRATE";
            out.append(String.format(Locale.ROOT, ", %s %.1f", name.toLowerCase(Locale.ROOT),
                    (after[p] - before[p]) / timed));
        }
        out.append(String.format(Locale.ROOT, " ms; %.1f products a step",
                (bdf2.jacobianProducts() - products0) / (double) timed));
        System.out.println(out.append("; load ").append(String.format(Locale.ROOT, "%.1f",
                java.lang.management.ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage())));
        double[] x = sim.state().x.clone();
        Random r = new Random(1);
        double[] z = new double[x.length];
        for (int i = 0; i < z.length; i++) {
            z[i] = r.nextGaussian();
        }
        double[] y = new double[x.length];
        double[] f = new double[x.length];
        double[] v = new double[x.length];
        for (SurfaceSliding term : terms) {
            term.linearise(sim.time(), x);
            int n = 300;
            for (int i = 0; i < n; i++) {
                term.multiplyAdd(z, y, null, 1);
                term.addForces(sim.time(), x, v, f);
            }
            long a = mx.getCurrentThreadCpuTime();
            for (int i = 0; i < n; i++) {
                term.multiplyAdd(z, y, null, 1);
            }
            long b = mx.getCurrentThreadCpuTime();
            for (int i = 0; i < n; i++) {
                term.addForces(sim.time(), x, v, f);
            }
            long c = mx.getCurrentThreadCpuTime();
            System.out.printf(Locale.ROOT, "%s: product %.3f ms, force pass %.3f ms (cpu)%n", term, (b - a) * 1e-6 / n,
                    (c - b) * 1e-6 / n);
        }
    }

    /** The bdf2 parts' and the INTEGRATE stage's total ms so far. */
    private static double[] parts(Simulation sim, PrefactoredBdf2 b) {
        Bdf2Part[] ps = Bdf2Part.values();
        double[] t = new double[ps.length + 1];
        for (int p = 0; p < ps.length; p++) {
            t[p] = b.partMillisPerStep(ps[p]) * sim.steps();
        }
        t[ps.length] = sim.profile().meanMillis(Stage.INTEGRATE) * sim.profile().steps();
        return t;
    }
}

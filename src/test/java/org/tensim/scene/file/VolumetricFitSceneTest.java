package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.BitSet;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tensim.analysis.LinearStatics;
import org.tensim.model.Topology;
import org.tensim.model.VolumeElement;
import org.tensim.solver.Simulation;
import org.tensim.solver.SystemState;
import org.tensim.solver.integrators.Integrators;

/** A volume body of a scene file with {@code fit: volumetric}: its nu honoured by a volume term a cell. */
class VolumetricFitSceneTest {
    @Test
    void theBlockWithTheVolumetricFitCarriesItsVolumeTermsAndSettlesOnItsStatics() {
        Scene s = SceneLoader.load(Path.of("docs/examples/block.yaml"),
                List.of("bodies.block.fit=volumetric", "bodies.block.material.nu=0.4"));
        Topology t = s.bodies().get("block").topology();
        // 4 x 4 x 4 cells, each with K = lambda - mu of E = 1 kPa, nu = 0.4 (times its fill, 1).
        assertEquals(64, t.volumeElements().size());
        double lambda = 1e3 * 0.4 / (1.4 * 0.2);
        double mu = 1e3 / 2.8;
        for (VolumeElement v : t.volumeElements()) {
            assertEquals(lambda - mu, v.modulusPa(), 1e-9);
            assertEquals(125e-9, v.restVolumeM3(), 1e-18);
        }
        BitSet top = s.regions().get("top").in("block");
        BitSet base = s.regions().get("base").in("block");
        boolean[] fixed = new boolean[3 * t.nodeCount()];
        double[] load = new double[3 * t.nodeCount()];
        base.stream().forEach(n -> fixed[3 * n] = fixed[3 * n + 1] = fixed[3 * n + 2] = true);
        top.stream().forEach(n -> load[3 * n + 1] = -0.16e-3);
        double[] u = LinearStatics.solve(t, fixed, load, 1e-10).displacementM();
        Simulation sim = new Simulation(SystemState.compile(t), Integrators.create(s.run().integrator()));
        for (long i = 0; i < s.run().steps(); i++) {
            sim.step(s.run().dtS());
        }
        double statics = top.stream().mapToDouble(n -> u[3 * n + 1]).sum() / top.cardinality();
        double[] d = new double[3];
        double run = 0;
        for (int n = top.nextSetBit(0); n >= 0; n = top.nextSetBit(n + 1)) {
            sim.state().displacement(n, d);
            run += d[1] / top.cardinality();
        }
        System.out.printf("block, volumetric fit at nu 0.4: top %.5g m after the run, statics %.5g m (strain %.3f %%)"
                + "%n", run, statics, -100 * statics / 0.02);
        assertTrue(statics < -1e-5, "the block shortens: " + statics);
        assertEquals(statics, run, 0.01 * Math.abs(statics), "the run settles on the statics");
    }
}

package org.tensim.tutorial;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import org.junit.jupiter.api.Test;
import org.tensim.io.ProjectFolder;
import org.tensim.model.Node;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.solver.Simulation;

/**
 * The code of docs/tutorials/library.md, compiled and run: a spring hangs from a fixed node and carries a second
 * mass on a rigid link, under gravity. The tutorial's claims are checked as physics: the link keeps its length after
 * every step, and the damped system comes to rest where the spring carries both masses, an extension of
 * (m_b + m_c) g / k, up to the paper's loop's first-order offset along a loaded link (docs/solvers.md, "RK2's
 * stage 3"): halved with the step.
 */
class LibraryTutorialTest {
    // tutorial:begin
    static double[] hangingChain(double dt) {
        Topology t = new Topology();
        Node a = t.addNode(0, 0, 0, 1.0).fix();                // x, y, z in m; mass in kg; a never moves
        Node b = t.addNode(0, -1.0, 0, 1.0);
        Node c = t.addNode(0, -1.5, 0, 1.0);
        t.addSpring(a, b, 100, 5);                               // N/m, N s/m; rest length: the distance now (1 m)
        t.addRigidLink(b, c);                                    // length: the distance now (0.5 m), kept every step
        t.setGravity(new Vec3(0, -9.81, 0));                     // m/s^2

        Simulation sim = Simulation.of(t);                       // compiled into flat arrays; the paper's RK2
        double[] worstLinkError = {0};
        sim.addListener(s -> {                                   // after every step, on the simulating thread
            double dx = s.state().position(c.id(), 0) - s.state().position(b.id(), 0);
            double dy = s.state().position(c.id(), 1) - s.state().position(b.id(), 1);
            double dz = s.state().position(c.id(), 2) - s.state().position(b.id(), 2);
            worstLinkError[0] = Math.max(worstLinkError[0], Math.abs(Math.sqrt(dx * dx + dy * dy + dz * dz) - 0.5));
        });
        sim.runUntil(20.0, dt);                                  // end time and step, s

        double by = sim.state().position(b.id(), 1);             // m
        return new double[] {by, worstLinkError[0], sim.time(), sim.steps()};
    }
    // tutorial:end

    @Test
    void theRigidLinkKeepsItsLengthAndTheSpringCarriesBothMassesToFirstOrderInTheStep() {
        double expectedY = -1.0 - 2 * 9.81 / 100;                // rest length plus (m_b + m_c) g / k, m
        double[] coarse = hangingChain(1e-3);
        double[] fine = hangingChain(5e-4);
        assertEquals(20.0, coarse[2], 1e-9, "simulated time, s");
        assertEquals(20000, coarse[3], "steps of 1 ms in 20 s");
        for (double[] r : new double[][] {coarse, fine}) {
            assertTrue(r[1] <= 1e-9 * 0.5, "largest link length error " + r[1] + " m, tolerance 1e-9 of 0.5 m");
        }
        double eCoarse = coarse[0] - expectedY;
        double eFine = fine[0] - expectedY;
        assertTrue(Math.abs(eFine) < 3e-4, "rest height off by " + eFine + " m at 0.5 ms");
        assertEquals(2.0, eCoarse / eFine, 0.1, "offset at 1 ms over offset at 0.5 ms (first order: 2)");
    }

    /** The page shows this file's code between the tutorial markers, line for line (indentation aside). */
    @Test
    void theTutorialPageShowsThisCode() throws Exception {
        String source = Files.readString(ProjectFolder.resolve("src", "test", "java", "org", "tensim", "tutorial",
                "LibraryTutorialTest.java"));
        String code = source.substring(source.indexOf("// tutorial:begin") + "// tutorial:begin".length(),
                source.indexOf("    // tutorial:end"));
        String page = Files.readString(ProjectFolder.resolve("docs", "tutorials", "library.md"));
        for (String line : code.strip().split("\n")) {
            assertTrue(page.contains(line.strip()), "docs/tutorials/library.md lacks the line: " + line.strip());
        }
    }
}

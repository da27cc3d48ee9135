package org.tensim.scene.tunable;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.CubeParameters;
import org.tensim.scene.CubeScene;
import org.tensim.solver.Simulation;

class RigidLinksAsSpringsTest {
    @Test
    void linksBecomeSpringsOfTheSameLengthAndEverythingElseIsKept() {
        Topology t = CubeScene.tensegrity(CubeParameters.paper()).topology;
        t.setViscousDamping(0.5);
        t.setGravity(new Vec3(0, -1, 0));
        int held = -1;
        for (int i = 0; i < t.nodeCount() && held < 0; i++) {
            if (!t.node(i).isFixed() && !t.node(i).isDriven()) {
                held = i;
            }
        }
        t.node(held).hold(5); // x and z, as a scene file's {type: fixed, axes: [x, z]}
        Topology c = RigidLinksAsSprings.of(t);
        assertEquals(5, c.node(held).heldAxes(), "a node held on some axes stays held on them");
        assertEquals(t.nodeCount(), c.nodeCount());
        assertEquals(0, c.rigidLinks().size());
        assertEquals(t.springs().size() + t.rigidLinks().size(), c.springs().size());
        for (int i = 0; i < t.rigidLinks().size(); i++) {
            var l = t.rigidLinks().get(i);
            var s = c.springs().get(t.springs().size() + i);
            assertEquals(l.a(), s.a());
            assertEquals(l.length(), s.restLength());
            assertEquals(CubeParameters.paper().stiffnessNPerM(), s.stiffness(), 1e-9, "all cube springs alike");
        }
        for (int i = 0; i < t.nodeCount(); i++) {
            assertEquals(t.node(i).isFixed(), c.node(i).isFixed());
            assertEquals(t.node(i).heldAxes(), c.node(i).heldAxes());
            assertEquals(t.node(i).position(), c.node(i).position());
        }
        assertSame(t.forces().get(0).law(), c.forces().get(0).law());
        assertEquals(0.5, c.viscousDamping());
        assertEquals(t.gravity(), c.gravity());
    }

    @Test
    void theSpringVariantDeformsMoreThanTheRigidOne() {
        CubeParameters p = CubeParameters.paper();
        Topology rigid = CubeScene.tensegrity(p).topology;
        int probe = CubeScene.tensegrity(p).probe.id();
        Simulation a = Simulation.of(rigid);
        Simulation b = Simulation.of(RigidLinksAsSprings.of(CubeScene.tensegrity(p).topology));
        a.runUntil(1.0, p.dtS());
        b.runUntil(1.0, p.dtS());
        double[] da = new double[3];
        double[] db = new double[3];
        a.state().displacement(probe, da);
        b.state().displacement(probe, db);
        assertTrue(Math.abs(db[1]) > 5 * Math.abs(da[1]), "springs instead of struts: " + db[1] + " m against "
                + da[1] + " m");
    }
}

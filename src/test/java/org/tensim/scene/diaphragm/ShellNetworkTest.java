package org.tensim.scene.diaphragm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.tensim.model.Topology;
import org.tensim.scene.shell.ShellMaterial;
import org.tensim.solver.ForceModel;
import org.tensim.solver.SystemState;

/** The shell's springs and triangles are objective: rigid motions change neither its energy nor its balance. */
class ShellNetworkTest {
    @ParameterizedTest
    @EnumSource(TissueModel.class)
    void energyIsInvariantUnderRigidMotionsAndForcesBalance(TissueModel model) {
        TwoSurfaces s = TwoSurfaces.split(DoubleDomeGenerator.shell(DoubleDomeGenerator.Shape.adult().withRings(5)));
        Topology t = ShellNetwork.standalone(s, new ShellMaterial(40e3, 0.45, s.thicknessM(), 1060), model, 1);
        assertTrue(t.springs().size() + t.triangles().size() > 3 * s.mesh().vertexCount(), "a connected network: "
                + t.springs().size() + " springs, " + t.triangles().size() + " triangles");
        ForceModel fm = new ForceModel(SystemState.compile(t));
        double[] x = SystemState.compile(t).x.clone();
        Random rnd = new Random(7);
        for (int k = 0; k < x.length; k++) {
            x[k] += 0.3 * s.thicknessM() * rnd.nextGaussian();
        }
        double e = fm.elasticEnergy(x);
        assertTrue(e > 0, "a deformed shell stores energy");
        // A rotation of 0.9 rad about an oblique axis through an arbitrary point, then a translation.
        double[] axis = {0.3, -0.5, 0.81};
        double n = Math.sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
        double c = Math.cos(0.9);
        double sn = Math.sin(0.9);
        double[] y = new double[x.length];
        for (int v = 0; v < x.length / 3; v++) {
            double[] p = {x[3 * v] - 0.1, x[3 * v + 1] + 0.2, x[3 * v + 2] - 1.0};
            double[] a = {axis[0] / n, axis[1] / n, axis[2] / n};
            double dot = a[0] * p[0] + a[1] * p[1] + a[2] * p[2];
            double[] cr = {a[1] * p[2] - a[2] * p[1], a[2] * p[0] - a[0] * p[2], a[0] * p[1] - a[1] * p[0]};
            for (int d = 0; d < 3; d++) {
                y[3 * v + d] = p[d] * c + cr[d] * sn + a[d] * dot * (1 - c) + 0.05 * (d + 1);
            }
        }
        assertEquals(e, fm.elasticEnergy(y), 1e-9 * e, "energy after a rigid motion");
        // Internal forces: no net force and no net torque (linear and angular momentum kept).
        double[] f = new double[x.length];
        fm.springs(y, f);
        fm.triangles(y, f);
        double[] sum = new double[3];
        double[] torque = new double[3];
        double scale = 0;
        for (int v = 0; v < x.length / 3; v++) {
            double fx = f[3 * v];
            double fy = f[3 * v + 1];
            double fz = f[3 * v + 2];
            sum[0] += fx;
            sum[1] += fy;
            sum[2] += fz;
            torque[0] += y[3 * v + 1] * fz - y[3 * v + 2] * fy;
            torque[1] += y[3 * v + 2] * fx - y[3 * v] * fz;
            torque[2] += y[3 * v] * fy - y[3 * v + 1] * fx;
            scale += Math.abs(fx) + Math.abs(fy) + Math.abs(fz);
        }
        for (int d = 0; d < 3; d++) {
            assertEquals(0, sum[d], 1e-12 * scale, "net force " + d);
            assertEquals(0, torque[d], 1e-11 * scale, "net torque " + d);
        }
    }
}

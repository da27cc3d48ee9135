package org.tensim.analysis;

import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.LinearMapping;
import org.tensim.model.Topology;
import org.tensim.model.Vec3;
import org.tensim.scene.volume.VolumeBody;

/**
 * Small-displacement statics of a volume body loaded on its embedded surface ({@link LinearStatics}): a uniform
 * traction on the surface triangles whose corners all satisfy a test goes to their vertices as {@code area / 3}
 * of the triangle's force each (the consistent load of linear triangles), and to the lattice nodes through the
 * mapping's transpose; the displacement of the surface is the mapping applied to the nodes'.
 */
final class VolumeStatics {
    /** Which surface vertices a load or a measure takes. */
    @FunctionalInterface
    interface Pick {
        boolean test(double x, double y, double z);
    }

    /** A solved volume: node and surface displacements (m, 3 each) and the surface load (N, 3 per vertex). */
    record Solved(double[] nodeDisplacementM, double[] surfaceDisplacementM, double[] surfaceForceN, int iterations) {
    }

    private VolumeStatics() {
    }

    /** Surface vertex forces (N) of a uniform traction (Pa, 3 components) on the triangles whose corners all pass. */
    static double[] traction(TriangleMesh s, Pick where, double[] tractionPa) {
        double[] f = new double[3 * s.vertexCount()];
        for (int t = 0; t < s.triangleCount(); t++) {
            boolean all = true;
            for (int k = 0; k < 3; k++) {
                int v = s.corner(t, k);
                all &= where.test(s.coord(v, 0), s.coord(v, 1), s.coord(v, 2));
            }
            if (!all) {
                continue;
            }
            double share = s.area(t) / 3;
            for (int k = 0; k < 3; k++) {
                int v = s.corner(t, k);
                for (int a = 0; a < 3; a++) {
                    f[3 * v + a] += share * tractionPa[a];
                }
            }
        }
        return f;
    }

    /** Solves K u = T^T f for the surface forces f, with the given fixed degrees of freedom (3 per node). */
    static Solved solve(Topology t, VolumeBody body, boolean[] fixed, double[] surfaceForceN, double tolerance) {
        LinearMapping m = body.surfaceMapping();
        double[] nodeForce = new double[3 * t.nodeCount()];
        m.addTranspose(surfaceForceN, nodeForce);
        LinearStatics.Solution u = LinearStatics.solve(t, fixed, nodeForce, tolerance);
        double[] us = new double[3 * m.pointCount()];
        m.apply(u.displacementM(), us);
        return new Solved(u.displacementM(), us, surfaceForceN, u.iterations());
    }

    /** Fixes axis {@code axis} of every node whose coordinate along {@code normal} is within a hair of {@code at}. */
    static void fixPlane(Topology t, boolean[] fixed, int normal, double at, int axis, double scale) {
        for (int n = 0; n < t.nodeCount(); n++) {
            Vec3 p = t.node(n).position();
            double c = normal == 0 ? p.x() : normal == 1 ? p.y() : p.z();
            if (Math.abs(c - at) <= 1e-9 * scale) {
                fixed[3 * n + axis] = true;
            }
        }
    }

    /** The work-conjugate displacement {@code sum f . u / sum |f|} of the loaded vertices, m. */
    static double conjugate(double[] f, double[] u) {
        double work = 0;
        double total = 0;
        for (int v = 0; v < f.length / 3; v++) {
            double fx = f[3 * v];
            double fy = f[3 * v + 1];
            double fz = f[3 * v + 2];
            work += fx * u[3 * v] + fy * u[3 * v + 1] + fz * u[3 * v + 2];
            total += Math.sqrt(fx * fx + fy * fy + fz * fz);
        }
        return work / total;
    }

    /** Area-weighted mean of displacement component {@code axis} over the triangles whose corners all pass, m. */
    static double meanOver(TriangleMesh s, Pick where, double[] u, int axis) {
        double[] unit = new double[3];
        unit[axis] = 1;
        double[] w = traction(s, where, unit);
        double num = 0;
        double den = 0;
        for (int v = 0; v < s.vertexCount(); v++) {
            num += w[3 * v + axis] * u[3 * v + axis];
            den += w[3 * v + axis];
        }
        return num / den;
    }
}

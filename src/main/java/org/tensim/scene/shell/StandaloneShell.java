package org.tensim.scene.shell;

import java.util.Set;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Topology;

/**
 * A shell network on its own ({@link ShellNetwork}): the accuracy scenes, the shell's tests and the scene files'
 * {@code type: shell} bodies.
 */
public final class StandaloneShell {
    private StandaloneShell() {
    }

    /**
     * A shell on its own, one material throughout: node v is vertex v, of mass
     * {@code rho A_v t / 2} (its share of the prisms' volume), with the model's springs and triangles
     * (at rest in the current positions, undamped) and, in the material models, its rigid columns.
     * For the accuracy scenes.
     */
    public static Topology of(TwoSurfaces s, ShellMaterial m, TissueModel model, double bendingFactor) {
        return of(s, m, model, bendingFactor, 0);
    }

    /**
     * As {@link #of(TwoSurfaces, ShellMaterial, TissueModel, double)} with stiffness-proportional damping: each
     * spring of stiffness k gets {@code c = beta k} (N s/m), each membrane triangle and shear element the
     * Kelvin-Voigt damping time beta.
     *
     * @param betaS the damping time beta, s (&gt;= 0; 0 undamped)
     */
    public static Topology of(TwoSurfaces s, ShellMaterial m, TissueModel model, double bendingFactor,
            double betaS) {
        return of(s, m, model, bendingFactor, betaS, (i, j) -> m.youngPa());
    }

    /**
     * As {@link #of(TwoSurfaces, ShellMaterial, TissueModel, double, double)} with Young's modulus edge by edge, as
     * the diaphragm gives its tendon and muscle theirs ({@link ShellNetwork}: a spring takes its edge's E, a
     * membrane triangle or shear element the mean of its three edges'); {@code m}'s E stays the paper model's
     * columns' and its nu, thickness and density the whole shell's. A scene file's zones of their own E.
     *
     * @param young E along an edge (i, j), Pa (&gt; 0)
     */
    public static Topology of(TwoSurfaces s, ShellMaterial m, TissueModel model, double bendingFactor,
            double betaS, ShellNetwork.EdgeModulus young) {
        org.tensim.model.Check.nonNegative("shell damping time", "s", betaS);
        TriangleMesh mesh = s.mesh();
        double[] area = SurfaceGeometry.vertexAreas(mesh);
        Topology t = new Topology();
        for (int v = 0; v < mesh.vertexCount(); v++) {
            double mass = m.densityKgPerM3() * area[v] * s.thicknessM() / 2;
            t.addNode(mesh.coord(v, 0), mesh.coord(v, 1), mesh.coord(v, 2), mass);
        }
        Set<Long> pairs = new java.util.HashSet<>();
        ShellNetwork.Sink sink = new ShellNetwork.Sink() {
            @Override
            public boolean add(int i, int j, double stiffness) {
                if (i == j || !pairs.add(ShellNetwork.key(i, j))) {
                    return false;
                }
                t.addSpring(i, j, stiffness, TwoSurfaces.distance(mesh, i, j), betaS * stiffness);
                return true;
            }

            @Override
            public boolean contains(int i, int j) {
                return pairs.contains(ShellNetwork.key(i, j));
            }

            @Override
            public void triangle(int[] p, int[] q, double thicknessM, double youngPa, double poisson) {
                t.addTriangle(p, q, thicknessM, youngPa, poisson, betaS);
            }

            @Override
            public void shear(int[] upper, int[] lower, double kappaGPa, double thicknessM) {
                t.addShear(upper, lower, kappaGPa, thicknessM, betaS);
            }
        };
        ShellNetwork n = new ShellNetwork(s, area, young, m, model, bendingFactor);
        n.membrane(sink);
        boolean[] linked = new boolean[mesh.vertexCount()];
        Set<Long> linkPairs = new java.util.HashSet<>();
        if (model.rigidColumns()) {
            for (int[] c : ShellNetwork.columnPairs(s, v -> true)) {
                linked[c[0]] = true;
                linked[c[1]] = true;
                linkPairs.add(ShellNetwork.key(c[0], c[1]));
                t.addRigidLink(t.node(c[0]), t.node(c[1]));
            }
        }
        n.thickness(sink, linkPairs, linked);
        return t;
    }
}

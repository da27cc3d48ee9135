package org.tensim.analysis;

import java.util.ArrayList;
import java.util.List;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Check;
import org.tensim.model.Topology;
import org.tensim.scene.shell.ShellMaterial;
import org.tensim.scene.shell.ShellNetwork;
import org.tensim.scene.shell.StandaloneShell;
import org.tensim.scene.shell.TissueModel;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * Static scenes with known answers for the two-surface shell (the diaphragm's discretisation,
 * {@link ShellNetwork}), solved by {@link LinearStatics}:
 * <ul>
 * <li>the patch test: a flat rectangular membrane under a uniform uniaxial tension sigma on its
 * end; every mesh should give the uniform stretch {@code sigma / E};</li>
 * <li>a clamped circular plate of radius a under a uniform pressure p, whose centre deflection
 * is Kirchhoff's {@code w0 = p a^4 / (64 D)}, {@code D = E t^3 / (12 (1 - nu^2))}.</li>
 * </ul>
 */
public final class ShellStatics {
    /** CG residual, relative to the load. */
    public static final double TOLERANCE = 1e-10;

    /**
     * One solved mesh.
     *
     * @param elementSizeM   the mesh spacing h, m
     * @param nodes          nodes of the shell (both faces)
     * @param measured       the measured figure (stretch, or centre deflection in m)
     * @param exact          the known answer, same unit
     * @param spread         the patch test's largest relative deviation of an element's stretch from the exact
     *                       one (0 for the plate)
     * @param iterations     CG iterations
     */
    public record Case(double elementSizeM, int nodes, double measured, double exact, double spread, int iterations) {
        /** |measured / exact - 1|. */
        public double relativeError() {
            return Math.abs(measured / exact - 1);
        }
    }

    private ShellStatics() {
    }

    /**
     * The patch test on a {@code lengthM x widthM} rectangle with {@code cells} elements along it.
     *
     * @param sigmaPa the tension on the end x = length, Pa (force per unit area of the section t x width)
     */
    public static Case patch(ShellMaterial m, TissueModel model, FlatMeshes.Pattern pattern, int cells,
            double lengthM, double widthM, double sigmaPa) {
        TriangleMesh flat = FlatMeshes.rectangle(pattern, cells, lengthM, widthM, 11);
        TwoSurfaces s = TwoSurfaces.offset(flat, m.thicknessM());
        Topology t = StandaloneShell.of(s, m, model, 1);
        int nv = s.mesh().vertexCount();
        double[] x = s.mesh().coordinates();
        double[] f = new double[3 * nv];
        boolean[] fixed = new boolean[3 * nv];
        double tol = 1e-9 * lengthM;
        double width = 0;
        for (int v = 0; v < nv; v++) {
            width = Math.max(width, x[3 * v + 1]);
        }
        // End tractions lumped by the boundary edges of each face (half the section on each face).
        for (int tr = 0; tr < flat.triangleCount(); tr++) {
            for (int k = 0; k < 3; k++) {
                int i = flat.corner(tr, k);
                int j = flat.corner(tr, (k + 1) % 3);
                if (Math.abs(x[3 * i] - lengthM) < tol && Math.abs(x[3 * j] - lengthM) < tol) {
                    double share = sigmaPa * m.thicknessM() / 2 * Math.abs(x[3 * i + 1] - x[3 * j + 1]) / 2;
                    for (int v : new int[] {i, j, i + nv / 2, j + nv / 2}) {
                        f[3 * v] += share; // each end node of the edge, on both faces
                    }
                }
            }
        }
        int mid = -1;
        for (int v = 0; v < nv / 2; v++) {
            if (Math.abs(x[3 * v]) < tol) {
                fixed[3 * v] = true;
                fixed[3 * (v + nv / 2)] = true;
                if (mid < 0 || Math.abs(x[3 * v + 1] - width / 2) < Math.abs(x[3 * mid + 1] - width / 2)) {
                    mid = v;
                }
            }
        }
        fixed[3 * mid + 1] = true;
        fixed[3 * (mid + nv / 2) + 1] = true;
        fixed[3 * mid + 2] = true; // the upper node: a rigid column ties the lower one to it
        LinearStatics.Solution sol = LinearStatics.solve(t, fixed, f, TOLERANCE);
        double[] u = sol.displacementM();
        double exact = sigmaPa / m.youngPa();
        double end = 0;
        int count = 0;
        double spread = 0;
        for (int v = 0; v < nv; v++) {
            if (Math.abs(x[3 * v] - lengthM) < tol) {
                end += u[3 * v];
                count++;
            }
        }
        for (int tr = 0; tr < s.mesh().triangleCount(); tr++) {
            spread = Math.max(spread, Math.abs(stretchX(s.mesh(), tr, u) / exact - 1));
        }
        return new Case(lengthM / cells, nv, end / count / lengthM, exact, spread, sol.iterations());
    }

    /** du_x/dx of a linear triangle (flat, in z = const). */
    static double stretchX(TriangleMesh mesh, int tr, double[] u) {
        int a = mesh.corner(tr, 0);
        int b = mesh.corner(tr, 1);
        int c = mesh.corner(tr, 2);
        double x1 = mesh.coord(b, 0) - mesh.coord(a, 0);
        double y1 = mesh.coord(b, 1) - mesh.coord(a, 1);
        double x2 = mesh.coord(c, 0) - mesh.coord(a, 0);
        double y2 = mesh.coord(c, 1) - mesh.coord(a, 1);
        double u1 = u[3 * b] - u[3 * a];
        double u2 = u[3 * c] - u[3 * a];
        double det = x1 * y2 - x2 * y1;
        return (u1 * y2 - u2 * y1) / det;
    }

    /**
     * The clamped circular plate: radius {@code radiusM}, {@code rings} rings (element size a / rings),
     * pressure {@code pressurePa} on the upper face; both faces fixed on the rim.
     */
    public static Case plate(ShellMaterial m, TissueModel model, int rings, double radiusM, double pressurePa) {
        Check.positive("plate pressure", "Pa", pressurePa);
        TriangleMesh flat = FlatMeshes.disc(rings, radiusM);
        TwoSurfaces s = TwoSurfaces.offset(flat, m.thicknessM());
        Topology t = StandaloneShell.of(s, m, model, 1);
        int nv = s.mesh().vertexCount();
        int half = nv / 2;
        double[] f = new double[3 * nv];
        boolean[] fixed = new boolean[3 * nv];
        double[] area = new double[half];
        for (int tr = 0; tr < flat.triangleCount(); tr++) {
            for (int k = 0; k < 3; k++) {
                area[flat.corner(tr, k)] += flat.area(tr) / 3;
            }
        }
        for (int v = 0; v < half; v++) {
            f[3 * v + 2] = -pressurePa * area[v];
            double r = Math.hypot(flat.coord(v, 0), flat.coord(v, 1));
            if (r > radiusM * (1 - 1e-9)) {
                for (int d = 0; d < 3; d++) {
                    fixed[3 * v + d] = true;
                    fixed[3 * (v + half) + d] = true;
                }
            }
        }
        LinearStatics.Solution sol = LinearStatics.solve(t, fixed, f, TOLERANCE);
        double w0 = -(sol.displacementM()[2] + sol.displacementM()[3 * half + 2]) / 2;
        double exact = pressurePa * Math.pow(radiusM, 4) / (64 * m.bendingRigidityNm());
        return new Case(radiusM / rings, nv, w0, exact, 0, sol.iterations());
    }

    /**
     * The clamped circular plate's centre deflection with Mindlin-Reissner's transverse shear, m:
     * {@code w0 = p a^4 / (64 D) + p a^2 / (4 kappa G t)}, kappa = 5/6 (e.g. Reddy, "Theory and Analysis
     * of Elastic Plates and Shells", 2nd ed. 2006, the clamped circular Mindlin plate; the shear term is
     * {@code 8 / (3 kappa (1 - nu)) (t / a)^2} of Kirchhoff's, 0.2 % for the diaphragm's t / a). The
     * material model's shell converges to this, not to Kirchhoff's, as h falls below t.
     */
    public static double mindlinPlate(ShellMaterial m, double radiusM, double pressurePa) {
        double kappaG = ShellNetwork.SHEAR_CORRECTION * m.youngPa() / (2 * (1 + m.poisson()));
        return pressurePa * Math.pow(radiusM, 4) / (64 * m.bendingRigidityNm())
                + pressurePa * radiusM * radiusM / (4 * kappaG * m.thicknessM());
    }

    /**
     * The order of convergence: least-squares slope of log(error) against log(h) over the cases
     * (finest last); NaN with fewer than two positive errors.
     */
    public static double order(List<Case> cases) {
        List<double[]> pts = new ArrayList<>();
        for (Case c : cases) {
            if (c.relativeError() > 0) {
                pts.add(new double[] {Math.log(c.elementSizeM()), Math.log(c.relativeError())});
            }
        }
        if (pts.size() < 2) {
            return Double.NaN;
        }
        double mx = 0;
        double my = 0;
        for (double[] p : pts) {
            mx += p[0] / pts.size();
            my += p[1] / pts.size();
        }
        double sxy = 0;
        double sxx = 0;
        for (double[] p : pts) {
            sxy += (p[0] - mx) * (p[1] - my);
            sxx += (p[0] - mx) * (p[0] - mx);
        }
        return sxy / sxx;
    }
}

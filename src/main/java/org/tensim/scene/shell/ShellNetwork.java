package org.tensim.scene.shell;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.tensim.io.mesh.TriangleMesh;

/**
 * The springs, membrane triangles and transverse shear elements of a two-surface shell
 * ({@link TwoSurfaces}) for a {@link TissueModel}: the faces' membrane, the mid-surface's and the
 * transverse shear (material model), and the columns and diagonals across the thickness. Used by the diaphragm and by the flat shells of the accuracy
 * scenes, so both are built by the same rules.
 */
public final class ShellNetwork {
    /** Where springs (N/m; the first spring on a node pair wins) and membrane triangles go. */
    public interface Sink {
        boolean add(int i, int j, double stiffness);

        boolean contains(int i, int j);

        /**
         * A membrane triangle ({@link org.tensim.model.TriangleElement}) whose corner k is the midpoint of
         * nodes p[k] and q[k], of thickness {@code thicknessM} (m), Young's modulus {@code youngPa} (Pa)
         * and Poisson's ratio {@code poisson}.
         */
        void triangle(int[] p, int[] q, double thicknessM, double youngPa, double poisson);

        /**
         * A transverse shear element ({@link org.tensim.model.TransverseShear}) on the upper triangle
         * {@code upper} whose corners' columns end at {@code lower}, of shear modulus {@code kappaGPa}
         * (Pa, kappa G) and thickness {@code thicknessM} (m).
         */
        void shear(int[] upper, int[] lower, double kappaGPa, double thicknessM);
    }

    /**
     * Largest offset of a shear element's pair from the upper vertex's normal, in thicknesses (see
     * {@link #shearPair}): at 0.5 the spurious shear of a bent element costs at most about its bending energy.
     */
    public static final double SHEAR_PAIR_OFFSET = 0.5;
    /**
     * Share of the membrane on the prisms' diagonals along the upper edges that no shear element covers
     * (material model): the 3 % of the model before the shear elements ({@link SandwichShell#SHEAR_SHARE}),
     * an effective shear modulus of about {@code 0.03 E (t / h)^2}, too soft but free of locking.
     */
    public static final double FALLBACK_DIAGONAL_SHARE = 0.03;

    /** Mindlin-Reissner's shear correction factor for a homogeneous plate (Reissner 1945; Mindlin 1951). */
    public static final double SHEAR_CORRECTION = 5.0 / 6;

    /** Young's modulus of the tissue along an edge (i, j), Pa. */
    @FunctionalInterface
    public interface EdgeModulus {
        double youngPa(int i, int j);
    }

    private final TwoSurfaces s;
    private final TriangleMesh mesh;
    private final double[] area;
    private final EdgeModulus young;
    private final double columnYoungPa;
    private final TissueModel model;
    private final ShellMaterial material;
    private final double bendingFactor;
    private final double thickness;
    private final double shearShare = SandwichShell.SHEAR_SHARE;
    /** Upper edges covered by a transverse shear element (keys as {@link #key}); no diagonals there. */
    private final Set<Long> shearEdges = new java.util.HashSet<>();
    private final Map<Long, double[]> edgeArea = new HashMap<>();
    private final List<List<Integer>> neighbours = new ArrayList<>();

    /**
     * @param s             the two faces (their median distance is the thickness t)
     * @param vertexArea    each vertex's third of its triangles' area, m^2
     * @param young         E along an edge, Pa (muscle or tendon)
     * @param material      the muscle: its E is the columns' in the paper's model, its nu sets the faces' share
     * @param model         which identification
     * @param bendingFactor folding-spring factor of the paper's model (ignored by the material model)
     */
    public ShellNetwork(TwoSurfaces s, double[] vertexArea, EdgeModulus young, ShellMaterial material,
            TissueModel model, double bendingFactor) {
        this.s = s;
        this.mesh = s.mesh();
        this.area = vertexArea;
        this.young = young;
        this.material = material;
        this.columnYoungPa = material.youngPa();
        this.model = model;
        this.bendingFactor = bendingFactor;
        this.thickness = s.thicknessM();
        int nv = mesh.vertexCount();
        for (int v = 0; v < nv; v++) {
            neighbours.add(new ArrayList<>());
        }
        for (int tr = 0; tr < mesh.triangleCount(); tr++) {
            boolean face = model == TissueModel.PAPER || onOneFace(tr);
            double a = mesh.area(tr);
            for (int k = 0; k < 3; k++) {
                int i = mesh.corner(tr, k);
                int j = mesh.corner(tr, (k + 1) % 3);
                double[] sum = edgeArea.get(key(i, j));
                if (sum == null) {
                    sum = new double[1];
                    edgeArea.put(key(i, j), sum);
                    neighbours.get(i).add(j);
                    neighbours.get(j).add(i);
                }
                sum[0] += face ? a : 0;
            }
        }
    }

    /**
     * The material model's transverse shear: one element ({@link org.tensim.model.TransverseShear}) per
     * upper triangle whose three corners are paired across the thickness by a rigid column ({@code linkPairs})
     * or near the normal ({@link #shearPair}), of shear
     * modulus {@code kappa G = 5/6 E / (2 (1 + nu))} (E the mean of the triangle's edges', nu the tissue's).
     * Records the upper edges the elements cover in {@link #shearEdges}.
     */
    private void shear(Sink sink, Set<Long> linkPairs) {
        double nu = material.poisson();
        double[] normals = SurfaceGeometry.vertexNormals(mesh);
        for (int tr = 0; tr < mesh.triangleCount(); tr++) {
            int[] c = {mesh.corner(tr, 0), mesh.corner(tr, 1), mesh.corner(tr, 2)};
            if (!onOneFace(tr) || !s.isUpper(c[0])) {
                continue;
            }
            int[] q = new int[3];
            boolean paired = true;
            for (int k = 0; k < 3 && paired; k++) {
                q[k] = s.partner(c[k]);
                paired = q[k] >= 0 && (linkPairs.contains(key(c[k], q[k])) || shearPair(c[k], q[k], normals));
            }
            if (paired) {
                double e = (young.youngPa(c[0], c[1]) + young.youngPa(c[1], c[2]) + young.youngPa(c[2], c[0])) / 3;
                sink.shear(c, q, SHEAR_CORRECTION * e / (2 * (1 + nu)), thickness);
                for (int k = 0; k < 3; k++) {
                    shearEdges.add(key(c[k], c[(k + 1) % 3]));
                }
            }
        }
    }

    /**
     * Whether upper vertex u and its partner l can carry a shear element: at most 3 thicknesses apart,
     * and l within {@link #SHEAR_PAIR_OFFSET} thicknesses of u's normal. Why the offset: the element's
     * shear strain is free of locking when the pairs lie along the normals (no shear under pure bending,
     * {@link org.tensim.model.TransverseShear}); a pair offset by d along the face picks up a spurious
     * shear strain of about {@code kappa d} under a curvature kappa, which costs about
     * {@code 4 (d / t)^2} times the bending energy. The generated shells pair along the normals; a real
     * mesh whose faces were meshed apart (BodyParts3D: median offset 0.43 t) or a clustered one (0.6 t)
     * does not everywhere, and there the prisms' diagonals resist the sliding instead ({@link #thickness}).
     */
    private boolean shearPair(int u, int l, double[] normals) {
        double[] c = new double[3];
        double along = 0;
        double len2 = 0;
        for (int d = 0; d < 3; d++) {
            c[d] = mesh.coord(l, d) - mesh.coord(u, d);
            along += c[d] * normals[3 * u + d];
            len2 += c[d] * c[d];
        }
        double offset = Math.sqrt(Math.max(0, len2 - along * along));
        return Math.sqrt(len2) <= 3 * thickness && offset <= SHEAR_PAIR_OFFSET * thickness;
    }

    /** A face edge's membrane spring for the whole thickness (Van Gelder), N/m. */
    private double edgeMembrane(int i, int j, double adjacentArea, double length) {
        return TriangleMembrane.edgeStiffness(young.youngPa(i, j) * thickness, adjacentArea, length);
    }

    private boolean onOneFace(int tr) {
        boolean u = s.isUpper(mesh.corner(tr, 0));
        return s.isUpper(mesh.corner(tr, 1)) == u && s.isUpper(mesh.corner(tr, 2)) == u;
    }

    /** The faces' springs (and, in the paper's model, the folding springs), or the material model's triangles. */
    public void membrane(Sink springs) {
        if (model == TissueModel.MATERIAL) {
            triangles(springs);
            return;
        }
        List<Long> keys = new ArrayList<>(edgeArea.keySet());
        Collections.sort(keys); // deterministic order
        SandwichShell sandwich = model == TissueModel.SPRINGS ? SandwichShell.of(material, thickness) : null;
        for (long e : keys) {
            int i = (int) (e >>> 32);
            int j = (int) e;
            double len = TwoSurfaces.distance(mesh, i, j);
            double a = edgeArea.get(e)[0];
            if (sandwich == null) {
                springs.add(i, j, young.youngPa(i, j) * (thickness / 2) * a / (len * len));
            } else if (a > 0 && s.isUpper(i) == s.isUpper(j)) {
                springs.add(i, j, sandwich.faceEdge(edgeMembrane(i, j, a, len)));
            }
        }
        if (model == TissueModel.PAPER) {
            PaperShellSprings.folding(s, edgeArea, young, thickness, bendingFactor, springs);
        }
    }

    /**
     * The material model's membrane: every face triangle with the face share c of the thickness, and
     * for every upper triangle whose corners have partners (at most 3 thicknesses away) a mid-surface
     * triangle on the midpoints of each corner and its partner, with the mid share. A triangle's
     * modulus is the mean of its edges' (muscle, tendon).
     */
    private void triangles(Sink sink) {
        SandwichShell sandwich = SandwichShell.ofElements(material, thickness, shearShare);
        double nu = material.poisson();
        for (int tr = 0; tr < mesh.triangleCount(); tr++) {
            if (!onOneFace(tr)) {
                continue;
            }
            int[] c = {mesh.corner(tr, 0), mesh.corner(tr, 1), mesh.corner(tr, 2)};
            double e = (young.youngPa(c[0], c[1]) + young.youngPa(c[1], c[2]) + young.youngPa(c[2], c[0])) / 3;
            sink.triangle(c, c, sandwich.faceShare() * thickness, e, nu);
            int[] q = new int[3];
            boolean paired = s.isUpper(c[0]);
            for (int k = 0; k < 3 && paired; k++) {
                q[k] = s.partner(c[k]);
                paired = q[k] >= 0 && TwoSurfaces.distance(mesh, c[k], q[k]) <= 3 * thickness;
            }
            if (paired && sandwich.midShare() > 0 && midArea(c, q) > 1e-3 * mesh.area(tr)) {
                sink.triangle(c, q, sandwich.midShare() * thickness, e, nu);
            }
        }
    }

    /** Area of the triangle on the midpoints of p[k] and q[k], m^2. */
    private double midArea(int[] p, int[] q) {
        double[] m = new double[9];
        for (int k = 0; k < 3; k++) {
            for (int d = 0; d < 3; d++) {
                m[3 * k + d] = 0.5 * (mesh.coord(p[k], d) + mesh.coord(q[k], d));
            }
        }
        double ax = m[3] - m[0];
        double ay = m[4] - m[1];
        double az = m[5] - m[2];
        double bx = m[6] - m[0];
        double by = m[7] - m[1];
        double bz = m[8] - m[2];
        double cx = ay * bz - az * by;
        double cy = az * bx - ax * bz;
        double cz = ax * by - ay * bx;
        return 0.5 * Math.sqrt(cx * cx + cy * cy + cz * cz);
    }

    /**
     * The springs across the thickness: none along a rigid link ({@code linkPairs}, keys as
     * {@link #key}); {@code linked[v]} marks the nodes that carry one.
     */
    public void thickness(Sink springs, Set<Long> linkPairs, boolean[] linked) {
        if (model == TissueModel.PAPER) {
            PaperShellSprings.thickness(s, area, columnYoungPa, neighbours, springs, linkPairs, linked);
            return;
        }
        boolean elements = model == TissueModel.MATERIAL;
        if (elements) {
            shear(springs, linkPairs);
        }
        SandwichShell sandwich = elements
                ? SandwichShell.ofElements(material, thickness, FALLBACK_DIAGONAL_SHARE) : SandwichShell.of(material, thickness);
        int nv = mesh.vertexCount();
        boolean[] columnDone = new boolean[nv];
        for (int u = 0; u < nv; u++) {
            if (!s.isUpper(u)) {
                continue;
            }
            for (int j : neighbours.get(u)) {
                int l = s.partner(j);
                double a = edgeArea.get(key(u, j))[0];
                if (!s.isUpper(j) || l < 0 || a == 0 || linkPairs.contains(key(u, l))
                        || (elements && shearEdges.contains(key(u, j)))) {
                    continue;
                }
                double e = TwoSurfaces.distance(mesh, u, j);
                double d = TwoSurfaces.distance(mesh, u, l);
                if (d > 3 * (thickness + e)) {
                    continue; // a partner on the far side of a badly paired mesh
                }
                springs.add(u, l, sandwich.diagonal(edgeMembrane(u, j, a, e), e, d));
            }
            int l = s.partner(u);
            if (l >= 0 && !linked[u] && !linked[l]) {
                double len = TwoSurfaces.distance(mesh, u, l);
                columnDone[l] |= springs.add(u, l, young.youngPa(u, l) * area[u] / len);
            }
            columnDone[u] = true;
        }
        for (int l = 0; l < nv; l++) {
            int u = s.partner(l);
            if (s.isUpper(l) || columnDone[l] || linked[l] || u < 0 || springs.contains(u, l)) {
                continue;
            }
            double len = TwoSurfaces.distance(mesh, u, l);
            if (len > 0 && len <= 3 * thickness) {
                springs.add(u, l, young.youngPa(u, l) * area[l] / len);
            }
        }
    }

    /**
     * Struts across the thickness: each eligible node with its partner (also eligible) on the other
     * face, shortest first, each node at most once, length 0.3 to 2.5 thicknesses (disjoint struts:
     * "compression discontinuous", paper section 2.1). Pairs are (upper, lower).
     */
    public static List<int[]> columnPairs(TwoSurfaces s, java.util.function.IntPredicate eligible) {
        TriangleMesh mesh = s.mesh();
        int nv = mesh.vertexCount();
        double th = s.thicknessM();
        List<int[]> cand = new ArrayList<>();
        for (int v = 0; v < nv; v++) {
            int q = s.partner(v);
            if (eligible.test(v) && q >= 0 && eligible.test(q)) {
                cand.add(s.isUpper(v) ? new int[] {v, q} : new int[] {q, v});
            }
        }
        cand.sort((x, y) -> Double.compare(TwoSurfaces.distance(mesh, x[0], x[1]),
                TwoSurfaces.distance(mesh, y[0], y[1])));
        boolean[] used = new boolean[nv];
        List<int[]> out = new ArrayList<>();
        for (int[] c : cand) {
            double len = TwoSurfaces.distance(mesh, c[0], c[1]);
            if (used[c[0]] || used[c[1]] || len < 0.3 * th || len > 2.5 * th) {
                continue;
            }
            used[c[0]] = true;
            used[c[1]] = true;
            out.add(c);
        }
        return out;
    }

    /** Key of an unordered node pair. */
    public static long key(int i, int j) {
        return ((long) Math.min(i, j) << 32) | Math.max(i, j);
    }
}

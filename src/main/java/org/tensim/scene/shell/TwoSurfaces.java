package org.tensim.scene.shell;

import java.util.Arrays;
import org.tensim.io.mesh.SurfaceDistance;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.io.mesh.VertexClustering;
import org.tensim.model.Check;

/**
 * The paper's objects are "defined by two boundary surfaces" (section 2.2). This
 * class holds a mesh whose vertices are split into an upper (thoracic) and a lower
 * (abdominal) surface, and pairs each vertex with its nearest vertex on the other
 * surface, from which the tensile connections across the thickness are made.
 *
 * <p>Two ways to get there:
 * <ul>
 * <li>{@link #split(TriangleMesh)}: a thin closed shell (the BodyParts3D diaphragm,
 * the project's double dome). A triangle belongs to the upper surface when its
 * outward normal points away from a reference point inside the abdomen (the centre
 * of the mesh's bounding box in x and y, at its lowest z): for a dome-shaped shell
 * the thoracic face looks away from the abdomen everywhere, on the top and on the
 * steep sides alike. A vertex takes the side of the area-weighted sum of its
 * triangles. The winding's sense is taken from the sign of the enclosed volume, so
 * an inward-wound file works too.</li>
 * <li>{@link #offset(TriangleMesh, double)}: a single surface, taken as the upper
 * one; the lower surface is a copy moved by the thickness along the vertex normals
 * (oriented to point away from the abdomen).</li>
 * </ul>
 */
public final class TwoSurfaces {
    private final TriangleMesh mesh;
    private final boolean[] upper;
    private final int[] partner;
    private final double thicknessM;
    private final int[] upperTriangles;
    /** The free rim of the mesh these surfaces were simplified from (m, 3 per point), or null: this mesh's own. */
    private final double[] sourceRim;

    private TwoSurfaces(TriangleMesh mesh, boolean[] upper) {
        this(mesh, upper, nearestOnOtherSide(mesh, upper), null);
    }

    private TwoSurfaces(TriangleMesh mesh, boolean[] upper, int[] partner, double[] sourceRim) {
        this.mesh = mesh;
        this.upper = upper;
        this.partner = partner;
        this.sourceRim = sourceRim;
        this.thicknessM = gap(mesh, upper, partner);
        int[] ut = new int[mesh.triangleCount()];
        int n = 0;
        for (int t = 0; t < mesh.triangleCount(); t++) {
            if (upper[mesh.corner(t, 0)] && upper[mesh.corner(t, 1)] && upper[mesh.corner(t, 2)]) {
                ut[n++] = t;
            }
        }
        this.upperTriangles = Arrays.copyOf(ut, n);
    }

    /** Splits a thin closed shell into its upper and lower faces (see the class comment). */
    public static TwoSurfaces split(TriangleMesh shell) {
        double[] b = shell.bounds();
        double cx = 0.5 * (b[0] + b[3]);
        double cy = 0.5 * (b[1] + b[4]);
        double cz = b[2];
        double sense = Math.signum(signedVolume(shell));
        if (sense == 0) {
            sense = 1;
        }
        int nv = shell.vertexCount();
        double[] score = new double[nv];
        double[] n = new double[3];
        for (int t = 0; t < shell.triangleCount(); t++) {
            shell.normal(t, n);
            for (int k = 0; k < 3; k++) {
                int v = shell.corner(t, k);
                double dx = shell.coord(v, 0) - cx;
                double dy = shell.coord(v, 1) - cy;
                double dz = shell.coord(v, 2) - cz;
                double l = Math.sqrt(dx * dx + dy * dy + dz * dz);
                if (l > 0) {
                    score[v] += sense * (n[0] * dx + n[1] * dy + n[2] * dz) / l;
                }
            }
        }
        boolean[] up = new boolean[nv];
        for (int v = 0; v < nv; v++) {
            up[v] = score[v] > 0;
        }
        return new TwoSurfaces(shell, up);
    }

    /**
     * Makes a shell from a single (upper) surface by offsetting a copy of it by
     * {@code thicknessM} towards the abdomen along the vertex normals.
     */
    public static TwoSurfaces offset(TriangleMesh surface, double thicknessM) {
        Check.positive("offset thickness", "m", thicknessM);
        double[] normals = SurfaceGeometry.vertexNormals(surface);
        double[] b = surface.bounds();
        double cx = 0.5 * (b[0] + b[3]);
        double cy = 0.5 * (b[1] + b[4]);
        double cz = b[2];
        int nv = surface.vertexCount();
        double dot = 0;
        for (int v = 0; v < nv; v++) {
            dot += normals[3 * v] * (surface.coord(v, 0) - cx) + normals[3 * v + 1] * (surface.coord(v, 1) - cy)
                    + normals[3 * v + 2] * (surface.coord(v, 2) - cz);
        }
        double sense = dot >= 0 ? 1 : -1; // make the normals point away from the abdomen
        double[] xyz = new double[6 * nv];
        for (int v = 0; v < nv; v++) {
            for (int a = 0; a < 3; a++) {
                xyz[3 * v + a] = surface.coord(v, a);
                xyz[3 * (nv + v) + a] = surface.coord(v, a) - sense * thicknessM * normals[3 * v + a];
            }
        }
        int nt = surface.triangleCount();
        int[] tri = new int[6 * nt];
        for (int t = 0; t < nt; t++) {
            for (int k = 0; k < 3; k++) {
                tri[3 * t + k] = surface.corner(t, k);
            }
            tri[3 * (nt + t)] = nv + surface.corner(t, 0);
            tri[3 * (nt + t) + 1] = nv + surface.corner(t, 2);
            tri[3 * (nt + t) + 2] = nv + surface.corner(t, 1);
        }
        boolean[] up = new boolean[2 * nv];
        Arrays.fill(up, 0, nv, true);
        return new TwoSurfaces(new TriangleMesh(xyz, tri), up);
    }

    /** Two surfaces given by a side per vertex (e.g. kept through a simplification); {@code upper[v]} true on top. */
    public static TwoSurfaces of(TriangleMesh mesh, boolean[] upper) {
        if (upper.length != mesh.vertexCount()) {
            throw new IllegalArgumentException("need one side per vertex: got " + upper.length + " for "
                    + mesh.vertexCount() + " vertices");
        }
        return new TwoSurfaces(mesh, upper.clone());
    }

    public TriangleMesh mesh() {
        return mesh;
    }

    /**
     * A coarser copy: the mesh simplified by vertex clustering in cubes of {@code cellM}
     * ({@link VertexClustering}), the two faces clustered apart (one cluster across a 3 mm shell would fold its
     * faces into one sheet), each vertex keeping its face, and carrying this mesh's free rim ({@link #withRimOf}):
     * the muscle ends where it ends here, not at the holes and folds the clustering opens.
     */
    public TwoSurfaces decimated(double cellM) {
        int[] groups = new int[mesh.vertexCount()];
        for (int v = 0; v < groups.length; v++) {
            groups[v] = upper[v] ? 1 : 0;
        }
        VertexClustering.Result r = VertexClustering.simplify(mesh, groups, cellM);
        boolean[] up = new boolean[r.groups().length];
        for (int v = 0; v < up.length; v++) {
            up[v] = r.groups()[v] == 1;
        }
        return new TwoSurfaces(r.mesh(), up).withRimOf(this);
    }

    /**
     * Per vertex of this mesh: on its free rim, where the sheet of muscle ends. A corner of a triangle that has
     * corners on both faces (where a closed two-surface shell turns over), or an end of an edge with one triangle
     * (an open surface's boundary, the boundary of a hole).
     */
    public boolean[] ownRim() {
        boolean[] rim = org.tensim.io.mesh.MeshCleaner.boundaryVertices(mesh);
        for (int t = 0; t < mesh.triangleCount(); t++) {
            int up = 0;
            for (int k = 0; k < 3; k++) {
                up += upper[mesh.corner(t, k)] ? 1 : 0;
            }
            if (up == 1 || up == 2) {
                for (int k = 0; k < 3; k++) {
                    rim[mesh.corner(t, k)] = true;
                }
            }
        }
        return rim;
    }

    /**
     * The free rim as points (m, 3 per point): the rim of the mesh these surfaces were simplified from when they
     * carry it ({@link #withRimOf}), else the vertices of this mesh's own rim ({@link #ownRim}).
     */
    public double[] rimPoints() {
        if (sourceRim != null) {
            return sourceRim.clone();
        }
        boolean[] rim = ownRim();
        int n = 0;
        for (boolean b : rim) {
            n += b ? 1 : 0;
        }
        double[] xyz = new double[3 * n];
        int k = 0;
        for (int v = 0; v < rim.length; v++) {
            if (rim[v]) {
                for (int a = 0; a < 3; a++) {
                    xyz[3 * k + a] = mesh.coord(v, a);
                }
                k++;
            }
        }
        return xyz;
    }

    /** Whether the rim is a source mesh's ({@link #withRimOf}) rather than this mesh's own. */
    public boolean carriesSourceRim() {
        return sourceRim != null;
    }

    /**
     * These surfaces carrying the free rim of {@code source}, the finer mesh they were simplified from. Why: a
     * simplification opens holes and folds where the source has none (vertex clustering of the BodyParts3D
     * diaphragm at 6 mm cells: 110 boundary loops, 223 non-manifold edges, and faces that meet inside the sheet),
     * and each would count as a free edge where the fibres end ({@code FibreInsertion}); the muscle's ends are
     * where the source's are.
     */
    public TwoSurfaces withRimOf(TwoSurfaces source) {
        return new TwoSurfaces(mesh, upper, partner, source.rimPoints());
    }

    /** Whether vertex v is on the upper (thoracic) surface. */
    public boolean isUpper(int v) {
        return upper[v];
    }

    /** The nearest vertex of the other surface to v (-1 if that surface is empty). */
    public int partner(int v) {
        return partner[v];
    }

    /**
     * The shell's thickness, m: the median over the vertices of the distance to the other surface,
     * to the closest point of its triangles (those with three corners on that side), not to the
     * nearest vertex. Where the two faces were meshed apart (a real mesh) a vertex rarely lies opposite
     * another, and the nearest vertex is farther than the face: on the BodyParts3D diaphragm the
     * paired vertices' median is 3.19 mm and the faces' 2.98 mm. On faces that are offset copies of
     * each other both give the offset to within its curvature's effect.
     */
    public double thicknessM() {
        return thicknessM;
    }

    /** Triangles whose three corners are on the upper surface (what a viewer draws). */
    public int[] upperTriangles() {
        return upperTriangles.clone();
    }

    public int upperCount() {
        return count(upper, true);
    }

    public int lowerCount() {
        return count(upper, false);
    }

    private static int count(boolean[] b, boolean value) {
        int c = 0;
        for (boolean x : b) {
            c += x == value ? 1 : 0;
        }
        return c;
    }

    /**
     * The median gap between the faces (see {@link #thicknessM()}); a side without a whole triangle
     * falls back to the paired vertices' distances.
     */
    private static double gap(TriangleMesh mesh, boolean[] upper, int[] partner) {
        int nv = mesh.vertexCount();
        double[] xyz = mesh.coordinates();
        SurfaceDistance[] face = {face(mesh, xyz, upper, false), face(mesh, xyz, upper, true)};
        double[] d = new double[nv];
        int k = 0;
        for (int v = 0; v < nv; v++) {
            if (partner[v] < 0) {
                continue;
            }
            SurfaceDistance other = face[upper[v] ? 0 : 1];
            d[k++] = other == null ? distance(mesh, v, partner[v])
                    : other.distance(mesh.coord(v, 0), mesh.coord(v, 1), mesh.coord(v, 2));
        }
        if (k == 0) {
            throw new IllegalArgumentException("the mesh has no vertex on one of its two surfaces: upper "
                    + count(upper, true) + ", lower " + count(upper, false) + "; expected a thin closed shell");
        }
        double[] sorted = Arrays.copyOf(d, k);
        Arrays.sort(sorted);
        return sorted[k / 2];
    }

    /** The triangles whose three corners are on the given side, or null when there is none. */
    private static SurfaceDistance face(TriangleMesh mesh, double[] xyz, boolean[] upper, boolean side) {
        int[] t = new int[3 * mesh.triangleCount()];
        int n = 0;
        for (int i = 0; i < mesh.triangleCount(); i++) {
            if (upper[mesh.corner(i, 0)] == side && upper[mesh.corner(i, 1)] == side
                    && upper[mesh.corner(i, 2)] == side) {
                for (int c = 0; c < 3; c++) {
                    t[n++] = mesh.corner(i, c);
                }
            }
        }
        return n == 0 ? null : new SurfaceDistance(xyz, Arrays.copyOf(t, n));
    }

    public static double distance(TriangleMesh m, int a, int b) {
        double dx = m.coord(a, 0) - m.coord(b, 0);
        double dy = m.coord(a, 1) - m.coord(b, 1);
        double dz = m.coord(a, 2) - m.coord(b, 2);
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    public static double signedVolume(TriangleMesh m) {
        double vol = 0;
        for (int t = 0; t < m.triangleCount(); t++) {
            int i = m.corner(t, 0);
            int j = m.corner(t, 1);
            int k = m.corner(t, 2);
            double ax = m.coord(i, 0);
            double ay = m.coord(i, 1);
            double az = m.coord(i, 2);
            double bx = m.coord(j, 0);
            double by = m.coord(j, 1);
            double bz = m.coord(j, 2);
            double cx = m.coord(k, 0);
            double cy = m.coord(k, 1);
            double cz = m.coord(k, 2);
            vol += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
        }
        return vol / 6;
    }

    /** Brute-force nearest vertex on the other side, sorted by z to prune (O(n log n + n k)). */
    private static int[] nearestOnOtherSide(TriangleMesh m, boolean[] upper) {
        int nv = m.vertexCount();
        int[] result = new int[nv];
        Arrays.fill(result, -1);
        for (int side = 0; side < 2; side++) {
            boolean wantUpper = side == 1;
            int[] cand = java.util.stream.IntStream.range(0, nv).filter(v -> upper[v] == wantUpper)
                    .boxed().sorted((p, q) -> Double.compare(m.coord(p, 2), m.coord(q, 2)))
                    .mapToInt(Integer::intValue).toArray();
            if (cand.length == 0) {
                continue;
            }
            double[] cz = new double[cand.length];
            for (int i = 0; i < cand.length; i++) {
                cz[i] = m.coord(cand[i], 2);
            }
            for (int v = 0; v < nv; v++) {
                if (upper[v] == wantUpper) {
                    continue;
                }
                double z = m.coord(v, 2);
                int start = Arrays.binarySearch(cz, z);
                start = start < 0 ? -start - 1 : start;
                double best = Double.POSITIVE_INFINITY;
                int bestIdx = -1;
                for (int dir = -1; dir <= 1; dir += 2) {
                    for (int i = dir < 0 ? start - 1 : start; i >= 0 && i < cand.length; i += dir) {
                        double dz = cz[i] - z;
                        if (dz * dz >= best) {
                            break;
                        }
                        double dx = m.coord(cand[i], 0) - m.coord(v, 0);
                        double dy = m.coord(cand[i], 1) - m.coord(v, 1);
                        double d2 = dx * dx + dy * dy + dz * dz;
                        if (d2 < best) {
                            best = d2;
                            bestIdx = cand[i];
                        }
                    }
                }
                result[v] = bestIdx;
            }
        }
        return result;
    }
}

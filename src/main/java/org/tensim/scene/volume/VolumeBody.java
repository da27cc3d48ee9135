package org.tensim.scene.volume;

import java.util.Locale;
import org.tensim.io.mesh.TetMesh;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.LinearMapping;
import org.tensim.model.Topology;

/**
 * A closed surface filled with a mass-spring volume: a lattice of cubic cells clipped to the surface, with the
 * surface embedded in it, each vertex carried by the eight nodes of its cell with trilinear weights (the pattern of
 * SOFA's {@code SparseGridTopology} with a barycentric mapping, and of ArtiSynth's {@code EmbeddedFem}).
 *
 * <p>What {@link #build} does, in order:
 * <ol>
 * <li>clips a lattice of cell size h to the surface ({@link LatticeClip}): each cell's inside fraction phi by the
 * winding number; a cell is kept when phi &gt; 0 or a surface vertex lies in it, so that every vertex is carried by
 * a cell of its own; a kept cell counts with {@code phi_eff = max(phi, 1 / s^3)}, s the fill samples per axis;</li>
 * <li>adds a node at every corner of a kept cell, of mass {@code sum over its cells rho phi_eff h^3 / 8}, so that
 * the masses sum to rho times the lattice volume {@code sum phi_eff h^3};</li>
 * <li>adds the springs of every kept cell ({@link LatticeMaterial}; none of zero stiffness), scaled by phi_eff, a
 * shared spring summing its cells' shares: stiffness and mass scale alike, so a clipped cell's stable time step is a
 * full cell's;</li>
 * <li>embeds the surface's vertices ({@link #surfaceMapping}).</li>
 * </ol>
 * A surface whose winding number is ambiguous (an open surface) or that encloses nothing is refused with a message
 * naming which; a few boundary edges (small holes) are tolerated and reported.
 *
 * <p>Springs are added, and with the volumetric fit a volume term a cell ({@link org.tensim.model.VolumeElement},
 * with its Gauss-Newton stiffness for the implicit integrators), so a volume runs in every integrator.
 */
public final class VolumeBody {
    private final int firstNode;
    private final int nodeCount;
    private final LinearMapping mapping;
    private final TriangleMesh surface;
    private final VolumeReport report;
    private final double[] originM;
    private final int droppedEdges;

    VolumeBody(int firstNode, int nodeCount, LinearMapping mapping, TriangleMesh surface, VolumeReport report,
            double[] originM, int droppedEdges) {
        this.droppedEdges = droppedEdges;
        this.firstNode = firstNode;
        this.nodeCount = nodeCount;
        this.mapping = mapping;
        this.surface = surface;
        this.report = report;
        this.originM = originM;
    }

    /** As {@link #build(Topology, TriangleMesh, VolumeParameters, String)} with "the surface" in messages. */
    public static VolumeBody build(Topology t, TriangleMesh surface, VolumeParameters p) {
        return build(t, surface, p, "the surface");
    }

    /**
     * Fills {@code surface} (m, triangles counter-clockwise seen from outside; inward winding is filled too) with a
     * lattice volume added to {@code t}: nodes (none fixed) and springs. Nothing is added when the surface is
     * refused.
     *
     * @param name names the surface in messages (e.g. its file)
     * @throws IllegalArgumentException naming the surface when it encloses nothing, when its winding number is
     *                                  ambiguous (open), or when the lattice would be too large
     */
    public static VolumeBody build(Topology t, TriangleMesh surface, VolumeParameters p, String name) {
        return build(t, surface, p, name, 0);
    }

    /**
     * As {@link #build(Topology, TriangleMesh, VolumeParameters, String)} with every node's mass at least
     * {@code minNodeMassKg} (kg, &gt;= 0): a clipped corner node carries as little as {@code rho h^3 / (8 s^3)}, and
     * a stiff coupling on it (a body sliding on another) would alone set the stable step; the floor adds mass
     * there ({@link VolumeReport#massKg} stays rho times the lattice volume; the nodes' sum is the topology's).
     */
    public static VolumeBody build(Topology t, TriangleMesh surface, VolumeParameters p, String name,
            double minNodeMassKg) {
        double h = p.cellSizeM();
        LatticeClip.Result clip = LatticeClip.clip(surface, h, p.fillSamples(), name);
        int boundary = surface.boundaryEdgeCount();
        refuseAmbiguous(clip, boundary, name);
        int nx = clip.nx();
        int ny = clip.ny();
        int nz = clip.nz();
        double floor = 1.0 / (p.fillSamples() * p.fillSamples() * p.fillSamples());
        int cellCount = nx * ny * nz;
        double[] phi = new double[cellCount];
        boolean anyInside = false;
        int kept = 0;
        for (int c = 0; c < cellCount; c++) {
            double f = clip.fill()[c];
            anyInside |= f > 0;
            if (f > 0 || clip.holdsVertex()[c]) {
                phi[c] = Math.max(f, floor);
                kept++;
            }
        }
        if (!anyInside) {
            throw new IllegalArgumentException(String.format(Locale.ROOT, "%s encloses nothing: no point of a"
                    + " lattice of %.3g mm cells over it has a winding number above 1/2 (it has %d boundary edges;"
                    + " an open sheet, or a shell thinner than a cell, is not a volume): expected a closed surface",
                    name, h * 1e3, boundary));
        }
        // Nodes: the corners of kept cells, in lattice order; mass rho phi_eff h^3 / 8 from each cell.
        int px = nx + 1;
        int py = ny + 1;
        double[] pointMass = new double[px * py * (nz + 1)];
        double cellMass = p.densityKgPerM3() * h * h * h;
        for (int k = 0; k < nz; k++) {
            for (int j = 0; j < ny; j++) {
                for (int i = 0; i < nx; i++) {
                    double f = phi[clip.cell(i, j, k)];
                    if (f > 0) {
                        for (int corner = 0; corner < 8; corner++) {
                            pointMass[point(i, j, k, corner, px, py)] += cellMass * f / 8;
                        }
                    }
                }
            }
        }
        int first = t.nodeCount();
        int[] nodeOf = new int[pointMass.length];
        double[] o = clip.origin();
        for (int q = 0; q < pointMass.length; q++) {
            if (pointMass[q] > 0) {
                int i = q % px;
                int j = (q / px) % py;
                int k = q / (px * py);
                nodeOf[q] = t.addNode(o[0] + i * h, o[1] + j * h, o[2] + k * h, Math.max(pointMass[q],
                        minNodeMassKg)).id();
            } else {
                nodeOf[q] = -1;
            }
        }
        int springs = addSprings(t, p, phi, clip, nodeOf, px, py);
        addVolumeTerms(t, p, phi, clip, nodeOf, px, py);
        LinearMapping mapping = embed(t, surface, clip, nodeOf, px, py);
        double volume = 0;
        for (double f : phi) {
            volume += f * h * h * h;
        }
        int nodes = t.nodeCount() - first;
        LatticeMaterial mat = p.material();
        VolumeReport r = new VolumeReport(surface.vertexCount(), surface.triangleCount(), boundary,
                clip.worstPoint() == null ? Double.NaN : clip.maxWindingDeviation(), clip.inward(), h,
                (long) cellCount, kept, clip.crossedCells(), nodes, springs, volume,
                Math.abs(surface.signedVolume()), volume * p.densityKgPerM3(), mat.modelPoisson(), p.poisson(),
                p.fit(), false);
        return new VolumeBody(first, nodes, mapping, surface, r, o.clone(), 0);
    }

    /**
     * The tetrahedral variant: the mesh's own nodes are the volume's nodes (none fixed), of mass {@code rho V_t / 4}
     * from each tet t around them, so that the masses sum to rho times the mesh's volume; its edges are springs from
     * E by {@link TetSprings} (the isotropic fit only: Poisson's ratio 1/4), a spring shared by tets summing their
     * shares, with the damping {@code c = beta k} of {@link VolumeParameters#dampingTimeS}; its boundary surface
     * ({@link TetMesh#boundary}) is the body's surface, each vertex carried by its own node with weight 1. The
     * parameters' cell size and fill samples are the lattice's and are not used. In the report, the cells are the
     * tets, the cell size their mean edge length and the lattice volume the tets' total.
     *
     * @param name names the mesh in messages (e.g. its file)
     * @throws IllegalArgumentException naming the mesh when the parameters ask for the axial fit
     */
    public static VolumeBody buildTets(Topology t, TetMesh mesh, VolumeParameters p, String name) {
        return TetVolume.build(t, mesh, p, name);
    }

    private static void refuseAmbiguous(LatticeClip.Result clip, int boundary, String name) {
        if (clip.maxWindingDeviation() >= LatticeClip.WINDING_TOLERANCE) {
            double[] w = clip.worstPoint();
            throw new IllegalArgumentException(String.format(Locale.ROOT, "%s is open: its winding number is %.3f"
                    + " at (%.4g, %.4g, %.4g) mm, far from it, where a closed surface gives 0 or 1"
                    + " (it has %d boundary edges): expected a closed surface, or holes smaller than a few cells",
                    name, w[3], w[0] * 1e3, w[1] * 1e3, w[2] * 1e3, boundary));
        }
    }

    /** Lattice point index of corner (bits x, y, z) of cell (i, j, k). */
    private static int point(int i, int j, int k, int corner, int px, int py) {
        return ((k + (corner >> 2 & 1)) * py + j + (corner >> 1 & 1)) * px + i + (corner & 1);
    }

    /**
     * The 13 lattice directions of a half-space (the first non-zero of dz, dy, dx positive): every spring of the
     * lattice joins a node to its neighbour along one of them.
     */
    private static final int[][] DIRECTIONS = halfSpace();

    private static int[][] halfSpace() {
        int[][] d = new int[13][];
        int n = 0;
        for (int dz = -1; dz <= 1; dz++) {
            for (int dy = -1; dy <= 1; dy++) {
                for (int dx = -1; dx <= 1; dx++) {
                    boolean positive = dz > 0 || dz == 0 && (dy > 0 || dy == 0 && dx > 0);
                    if (positive) {
                        d[n++] = new int[] {dx, dy, dz};
                    }
                }
            }
        }
        return d;
    }

    private static int direction(int dx, int dy, int dz) {
        for (int i = 0; i < DIRECTIONS.length; i++) {
            if (DIRECTIONS[i][0] == dx && DIRECTIONS[i][1] == dy && DIRECTIONS[i][2] == dz) {
                return i;
            }
        }
        throw new IllegalStateException("not a half-space direction: " + dx + ", " + dy + ", " + dz);
    }

    /**
     * Every kept cell's springs, scaled by its phi_eff; a spring shared by cells sums their shares. The shares are
     * summed in an array of 13 directions a node (no map: a fine lattice has millions of springs), then added node
     * by node, direction by direction.
     */
    private static int addSprings(Topology t, VolumeParameters p, double[] phi, LatticeClip.Result clip,
            int[] nodeOf, int px, int py) {
        LatticeMaterial m = p.material();
        double h = p.cellSizeM();
        double[] share = {0, m.edgeStiffness(h), m.faceDiagonalStiffness(h), m.bodyDiagonalStiffness(h)};
        int first = Integer.MAX_VALUE;
        int last = -1;
        for (int id : nodeOf) {
            if (id >= 0) {
                first = Math.min(first, id);
                last = Math.max(last, id);
            }
        }
        double[] k = new double[13 * (last - first + 1)];
        int[] pairDirection = new int[64];
        boolean[] pairFlip = new boolean[64];
        for (int a = 0; a < 8; a++) {
            for (int b = 0; b < 8; b++) {
                int dx = (b & 1) - (a & 1);
                int dy = (b >> 1 & 1) - (a >> 1 & 1);
                int dz = (b >> 2 & 1) - (a >> 2 & 1);
                boolean positive = dz > 0 || dz == 0 && (dy > 0 || dy == 0 && dx > 0);
                pairFlip[8 * a + b] = !positive;
                pairDirection[8 * a + b] = a == b ? -1 : positive ? direction(dx, dy, dz) : direction(-dx, -dy, -dz);
            }
        }
        for (int kz = 0; kz < clip.nz(); kz++) {
            for (int j = 0; j < clip.ny(); j++) {
                for (int i = 0; i < clip.nx(); i++) {
                    double f = phi[clip.cell(i, j, kz)];
                    if (f == 0) {
                        continue;
                    }
                    for (int a = 0; a < 8; a++) {
                        for (int b = a + 1; b < 8; b++) {
                            double s = share[Integer.bitCount(a ^ b)];
                            if (s == 0) {
                                continue;
                            }
                            int from = pairFlip[8 * a + b] ? b : a;
                            int node = nodeOf[point(i, j, kz, from, px, py)];
                            k[13 * (node - first) + pairDirection[8 * a + b]] += f * s;
                        }
                    }
                }
            }
        }
        int springs = 0;
        for (int q = 0; q < nodeOf.length; q++) {
            if (nodeOf[q] < 0) {
                continue;
            }
            int i = q % px;
            int j = (q / px) % py;
            int kz = q / (px * py);
            for (int d = 0; d < 13; d++) {
                double stiffness = k[13 * (nodeOf[q] - first) + d];
                if (stiffness == 0) {
                    continue;
                }
                int[] o = DIRECTIONS[d];
                int other = nodeOf[((kz + o[2]) * py + j + o[1]) * px + i + o[0]];
                double rest = h * Math.sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]);
                t.addSpring(nodeOf[q], other, stiffness, rest, p.dampingTimeS() * stiffness);
                springs++;
            }
        }
        return springs;
    }

    /**
     * The volumetric fit's volume term ({@link LatticeMaterial#volumetricModulusPa}), one a kept cell, its modulus
     * scaled by phi_eff as the cell's springs are; none for the other fits.
     */
    private static void addVolumeTerms(Topology t, VolumeParameters p, double[] phi, LatticeClip.Result clip,
            int[] nodeOf, int px, int py) {
        double k = p.material().volumetricModulusPa();
        if (!(k > 0)) {
            return;
        }
        int[] corners = new int[8];
        for (int kz = 0; kz < clip.nz(); kz++) {
            for (int j = 0; j < clip.ny(); j++) {
                for (int i = 0; i < clip.nx(); i++) {
                    double f = phi[clip.cell(i, j, kz)];
                    if (f > 0) {
                        for (int c = 0; c < 8; c++) {
                            corners[c] = nodeOf[point(i, j, kz, c, px, py)];
                        }
                        t.addVolumeElement(corners, f * k, p.dampingTimeS());
                    }
                }
            }
        }
    }

    /** Each surface vertex on the 8 nodes of its cell, with the trilinear weights of its place in the cell. */
    private static LinearMapping embed(Topology t, TriangleMesh surface, LatticeClip.Result clip, int[] nodeOf,
            int px, int py) {
        int nv = surface.vertexCount();
        int[] start = new int[nv + 1];
        int[] node = new int[8 * nv];
        double[] weight = new double[8 * nv];
        int[] n = {clip.nx(), clip.ny(), clip.nz()};
        double h = clip.h();
        int[] cell = new int[3];
        double[] f = new double[3];
        for (int v = 0; v < nv; v++) {
            for (int a = 0; a < 3; a++) {
                double x = (surface.coord(v, a) - clip.origin()[a]) / h;
                cell[a] = LatticeClip.cellIndex(surface.coord(v, a), clip.origin()[a], h, n[a]);
                f[a] = x - cell[a];
            }
            for (int corner = 0; corner < 8; corner++) {
                double w = 1;
                for (int a = 0; a < 3; a++) {
                    w *= (corner >> a & 1) == 1 ? f[a] : 1 - f[a];
                }
                node[8 * v + corner] = nodeOf[point(cell[0], cell[1], cell[2], corner, px, py)];
                weight[8 * v + corner] = w;
            }
            start[v + 1] = 8 * (v + 1);
        }
        return new LinearMapping(t.nodeCount(), start, node, weight);
    }

    /** Id of the first node added; the volume's nodes are {@code firstNode() .. firstNode() + nodeCount() - 1}. */
    public int firstNode() {
        return firstNode;
    }

    /** Number of nodes added. */
    public int nodeCount() {
        return nodeCount;
    }

    /**
     * The surface carried by the lattice: point i is surface vertex i, on the topology's node ids. Apply it to the
     * node positions (or velocities) to draw, probe or export the surface; carry forces on the surface's vertices
     * back to the nodes with {@link LinearMapping#addTranspose}.
     */
    public LinearMapping surfaceMapping() {
        return mapping;
    }

    /** The embedded surface (its triangles index the mapping's points). */
    public TriangleMesh surface() {
        return surface;
    }

    /** What the build made and found. */
    public VolumeReport report() {
        return report;
    }

    /**
     * Tet edges (counted once per tet) whose share was dropped because the tet's fit made it negative
     * ({@link TetSprings}); 0 for a lattice.
     */
    public int droppedEdges() {
        return droppedEdges;
    }

    /**
     * The lattice's lowest corner, m (node positions are {@code origin + (i, j, k) h}); a tet mesh's lowest bounding
     * corner.
     */
    public double[] originM() {
        return originM.clone();
    }
}

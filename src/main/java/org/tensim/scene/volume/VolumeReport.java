package org.tensim.scene.volume;

import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;

/**
 * What a volume build made and found. For a tetrahedral body ({@code tetrahedral}) the cells are its tets, the cell
 * size their mean edge length, the lattice volume the tets' total, and there is no winding number or crossed cell.
 *
 * @param surfaceVertices      vertices of the surface, each carried by the lattice
 * @param surfaceTriangles     triangles of the surface
 * @param boundaryEdges        edges of the surface used by one triangle only (holes; tolerated while the winding
 *                             number stays unambiguous)
 * @param maxWindingDeviation  largest distance of |w| from 0 or 1 at cell centres far from the surface (more than
 *                             two cells and a tenth of its bounds' diagonal): near 0 for a closed surface; NaN when
 *                             no cell is that far
 * @param inwardWound          whether the surface's triangles face inwards (w near -1 inside); filled all the same
 * @param cellSizeM            h, m
 * @param latticeCells         cells of the lattice's box, nx ny nz
 * @param cells                cells kept (inside fraction &gt; 0, or holding a surface vertex)
 * @param crossedCells         cells the surface may cross (sampled for their inside fraction)
 * @param nodes                lattice nodes added
 * @param springs              springs added
 * @param latticeVolumeM3      sum over kept cells of their effective fraction times h^3, m^3
 * @param surfaceVolumeM3      the volume the surface encloses (divergence theorem, its absolute value), m^3
 * @param massKg               total mass of the nodes added, kg
 * @param modelPoisson         the lattice's Poisson ratio along its axes ({@link LatticeMaterial#modelPoisson}); for
 *                             tets the target's 1/4 (the assembled network's own differs with the mesh)
 * @param requestedPoisson     the nu asked for
 * @param fit                  the spring fit
 * @param tetrahedral          built from a tetrahedral mesh ({@link VolumeBody#buildTets}) rather than a lattice
 */
public record VolumeReport(int surfaceVertices, int surfaceTriangles, int boundaryEdges, double maxWindingDeviation,
        boolean inwardWound, double cellSizeM, long latticeCells, int cells, int crossedCells, int nodes, int springs,
        double latticeVolumeM3, double surfaceVolumeM3, double massKg, double modelPoisson, double requestedPoisson,
        SpringFit fit, boolean tetrahedral) {

    /** The report as an ordered map with units in its keys (for summary.json). */
    public Map<String, Object> toMap() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("variant", tetrahedral ? "tets" : "lattice");
        m.put("surface_vertices", surfaceVertices);
        m.put("surface_triangles", surfaceTriangles);
        m.put("boundary_edges", boundaryEdges);
        m.put("max_winding_deviation", Double.isFinite(maxWindingDeviation) ? maxWindingDeviation : null);
        m.put("inward_wound", inwardWound);
        m.put("cell_size_m", cellSizeM);
        m.put("lattice_cells", latticeCells);
        m.put("cells", cells);
        m.put("crossed_cells", crossedCells);
        m.put("nodes", nodes);
        m.put("springs", springs);
        m.put("lattice_volume_m3", latticeVolumeM3);
        m.put("surface_volume_m3", surfaceVolumeM3);
        m.put("mass_kg", massKg);
        m.put("spring_fit", fit.key());
        m.put("model_poisson", modelPoisson);
        m.put("requested_poisson", requestedPoisson);
        return m;
    }

    /** One line for a console. */
    public String describe() {
        if (tetrahedral) {
            return String.format(Locale.ROOT, "volume: %d nodes, %d springs, %d tets of mean edge %.3g mm; volume"
                    + " %.4g cm^3 (its boundary encloses %.4g cm^3), mass %.4g kg; boundary %d vertices, %d triangles,"
                    + " %d open edges; springs fitted to the isotropic nu %.3f (asked %.3f; the network's own depends"
                    + " on the mesh, docs/volume.md)", nodes, springs, cells, cellSizeM * 1e3,
                    latticeVolumeM3 * 1e6, surfaceVolumeM3 * 1e6, massKg, surfaceVertices, surfaceTriangles,
                    boundaryEdges, modelPoisson, requestedPoisson);
        }
        return String.format(Locale.ROOT, "volume: %d nodes, %d springs, %d cells of %.3g mm (%d crossed by the"
                + " surface); lattice volume %.4g cm^3 against the surface's %.4g cm^3, mass %.4g kg; surface %d"
                + " vertices, %d triangles, %d boundary edges, winding number %s%s; %s fit: nu %.3f (asked %.3f)",
                nodes, springs, cells, cellSizeM * 1e3, crossedCells, latticeVolumeM3 * 1e6, surfaceVolumeM3 * 1e6,
                massKg, surfaceVertices, surfaceTriangles, boundaryEdges,
                Double.isFinite(maxWindingDeviation) ? String.format(Locale.ROOT, "within %.3f of 0 or 1",
                        maxWindingDeviation) : "not checked (no cell far from the surface)",
                inwardWound ? ", triangles wound inwards" : "", fit.key(), modelPoisson, requestedPoisson);
    }
}

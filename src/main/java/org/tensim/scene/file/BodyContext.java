package org.tensim.scene.file;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.tensim.io.mesh.MeshCleaner;
import org.tensim.io.mesh.MeshExtent;
import org.tensim.io.mesh.MeshFormatException;
import org.tensim.io.mesh.MeshLoader;
import org.tensim.io.mesh.MeshUnits;

/**
 * What a {@link BodyType} reads its body with: the body's name, its keys (already checked against the type's
 * {@link BodyType#keys()}), the file's units and its folder, against which relative file names are resolved.
 */
public final class BodyContext {
    /** Keys of a {@code mesh:} map. */
    public static final java.util.List<String> MESH_KEYS = java.util.List.of("file", "units");

    private final String name;
    private final MapReader keys;
    private final SceneUnits units;
    private final Path folder;
    private EmbeddedSurface surface;
    private org.tensim.model.Topology topology;
    private Object built;
    private final java.util.List<String> report = new java.util.ArrayList<>();

    public BodyContext(String name, MapReader keys, SceneUnits units, Path folder) {
        this.name = name;
        this.keys = keys;
        this.units = units;
        this.folder = folder;
    }

    /** The body's name (its key under {@code bodies:}). */
    public String name() {
        return name;
    }

    /** The body's keys. */
    public MapReader keys() {
        return keys;
    }

    /** The file's units: bare numbers take them, values are returned in SI. */
    public SceneUnits units() {
        return units;
    }

    /** A file named by a scalar, relative to the scene file's folder; refused if it does not exist. */
    public Path file(SceneNode node) {
        return file(node, folder);
    }

    static Path file(SceneNode node, Path folder) {
        if (!node.isScalar()) {
            throw SceneException.at(node, "expected a file name, got " + node.describe());
        }
        Path p = folder.resolve(node.text());
        if (!Files.exists(p)) {
            throw SceneException.absent(node, "no such file: " + p, p);
        }
        if (!Files.isRegularFile(p)) {
            throw SceneException.at(node, "no such file: " + p + " (it is a folder; expected a file)");
        }
        return p;
    }

    /**
     * Reads a {@code mesh: {file: liver.obj, units: mm}} map (units mm or m, required: a mesh's coordinates
     * carry no unit) through {@link MeshLoader}, converted to metres, and refuses a mesh whose largest side is
     * not within [minM, maxM] metres in those units (the message says which units would fit).
     *
     * @param what what the body is, for the message ("organ", "bone")
     */
    public MeshCleaner.Result mesh(SceneNode node, String what, double minM, double maxM) {
        MapReader r = new MapReader(node, MESH_KEYS);
        Path f = file(r.scalar("file"));
        SceneNode u = r.scalar("units");
        MeshUnits mu;
        try {
            mu = MeshUnits.parse(u.text());
        } catch (IllegalArgumentException e) {
            throw SceneException.at(u, u.describe() + ": " + e.getMessage());
        }
        try {
            MeshCleaner.Result res = MeshLoader.load(f, mu);
            MeshExtent.refuseImplausibleSize(res.mesh(), f, mu, what, minM, maxM, "units: ");
            return res;
        } catch (MeshFormatException e) {
            throw SceneException.at(node, e.getMessage());
        } catch (IOException e) {
            throw SceneException.at(node, "cannot read " + f + " (" + e.getMessage() + ")");
        }
    }

    /** A folder named by a scalar, relative to the scene file's folder; refused if it is not a folder. */
    public Path folder(SceneNode node) {
        if (!node.isScalar()) {
            throw SceneException.at(node, "expected a folder name, got " + node.describe());
        }
        Path p = folder.resolve(node.text());
        if (!Files.exists(p)) {
            throw SceneException.absent(node, "no such folder: " + p, p);
        }
        if (!Files.isDirectory(p)) {
            throw SceneException.at(node, "no such folder: " + p + " (it is a file; expected a folder)");
        }
        return p;
    }

    /**
     * Hands over a topology the type's own builder made (the diaphragm's) to be the body's instead of the empty one
     * {@link BodyType#build} was given, with what else that builder made ({@link SceneBody#built()}).
     */
    public void own(org.tensim.model.Topology topology, Object built) {
        this.topology = topology;
        this.built = built;
    }

    /** The topology handed over by {@link #own}, or null. */
    public org.tensim.model.Topology ownTopology() {
        return topology;
    }

    /** What the type built besides its topology ({@link #own}), or null. */
    public Object built() {
        return built;
    }

    /** Records the surface the body carries on its nodes (drawn by the GUI, read by surface probes). */
    public void embed(EmbeddedSurface s) {
        surface = s;
    }

    /** The surface recorded by {@link #embed}, or null. */
    public EmbeddedSurface surface() {
        return surface;
    }

    /** Adds a line to what {@code tensim check} prints about the body (e.g. a volume's build report). */
    public void report(String line) {
        report.add(line);
    }

    /** The lines added by {@link #report}. */
    public java.util.List<String> reportLines() {
        return java.util.List.copyOf(report);
    }
}

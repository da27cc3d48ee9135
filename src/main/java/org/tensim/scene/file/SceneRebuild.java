package org.tensim.scene.file;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;

/**
 * A loaded scene file's regions, conditions and probes applied anew to a body its type rebuilt with the same nodes
 * (a diaphragm the GUI rebuilds when a control that restarts the run moves: the breathing period, the tendon's
 * boundary): what {@link SceneLoader} applied to the body it built, applied again in the same order, so that the
 * rebuilt body carries the file's fixed nodes, held axes, motions, forces, gravity and pressures as {@code tensim
 * run} runs them. Regions are resolved on the rebuilt body (a {@code part: tendon} follows a moved tendon boundary);
 * box, sphere, plane and index regions select the same nodes as before when the nodes have not moved.
 *
 * <p>The file is read once, when this is made (right after the loader read it, with the same {@code --set}
 * overrides): a later edit of the file on disk is not taken in until the file is opened again.
 */
public final class SceneRebuild {
    private final Scene loaded;
    private final SceneNode regions;
    private final SceneNode conditions;
    private final SceneNode probes;
    private final SceneUnits units;
    private final Path folder;

    private SceneRebuild(Scene loaded, SceneNode root, Path folder) {
        this.loaded = loaded;
        this.folder = folder;
        MapReader top = new MapReader(root, SceneLoader.KEYS);
        this.units = SceneUnits.read(top.optional("units"));
        this.regions = top.optional("regions");
        this.conditions = top.optional("conditions");
        this.probes = top.optional("probes");
    }

    /** What {@code loaded} (a scene loaded from its file, with its overrides) applies to a rebuilt body. */
    public static SceneRebuild of(Scene loaded) {
        SceneNode root = SceneTree.read(loaded.file());
        Map<String, SceneParameters.Declared> declared = SceneParameters.declare(root);
        SceneParameters.override(root, declared, loaded.overrides());
        Path parent = loaded.file().toAbsolutePath().getParent();
        return new SceneRebuild(loaded, root, parent == null ? Path.of(".") : parent);
    }

    /** Whether the file has anything to apply beyond what the body's own keys build. */
    public boolean hasExtras() {
        return regions != null || conditions != null || probes != null;
    }

    /**
     * Applies the file's regions and conditions to {@code rebuilt} (its topology changed in place, before any
     * simulation is compiled from it).
     *
     * @param rebuilt the body, named as in the file, rebuilt by its type with the node numbering the file's index
     *                lists and label files name
     * @return the file's probes resolved on the rebuilt body, in file order (empty without a probes block)
     * @throws SceneException naming file, line and key when the rebuilt body no longer fits a region or condition
     *                        (a region that now selects nothing, say)
     */
    public List<SceneProbe> apply(SceneBody rebuilt) {
        if (!loaded.bodies().containsKey(rebuilt.name()) || loaded.bodies().size() != 1) {
            throw new IllegalArgumentException("body '" + rebuilt.name() + "' is not the only body of "
                    + loaded.file() + " (its bodies: " + loaded.bodies().keySet() + ")");
        }
        Map<String, SceneBody> bodies = Map.of(rebuilt.name(), rebuilt);
        Map<String, SceneRegions.Region> r = SceneRegions.read(regions, bodies, units, folder,
                loaded.rigids().keySet());
        List<BodyCoupling> couplings = SceneConditions.apply(conditions, bodies, r, loaded.laws(), units,
                loaded.rigids());
        return SceneProbe.read(probes, bodies, r, loaded.rigids(), couplings);
    }
}

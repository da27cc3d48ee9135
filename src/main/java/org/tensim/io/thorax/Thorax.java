package org.tensim.io.thorax;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.stream.Collectors;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.thorax.ThoraxPart.Group;
import org.tensim.io.thorax.ThoraxPart.Side;

/**
 * A set of thorax surfaces loaded by {@link ThoraxLoader}: the parts in {@code parts.json} order (only the groups
 * asked for), looked up by name, group, side and number. Every mesh is in metres, in the frame {@link #frame()}
 * describes. Immutable.
 */
public final class Thorax {
    private final Path partsJson;
    private final String frame;
    private final MeshUnits units;
    private final List<ThoraxPart> parts;
    private final Map<String, ThoraxPart> byName = new LinkedHashMap<>();

    /**
     * @param partsJson the file the parts were listed in
     * @param frame     the "frame" text of {@code parts.json} (axes and origin), or "" when it gives none
     * @param units     the units the mesh files were written in (the meshes here are converted to metres)
     * @param parts     the parts, names unique
     */
    public Thorax(Path partsJson, String frame, MeshUnits units, List<ThoraxPart> parts) {
        this.partsJson = partsJson;
        this.frame = frame == null ? "" : frame;
        this.units = units;
        this.parts = List.copyOf(parts);
        for (ThoraxPart p : this.parts) {
            if (byName.put(p.name(), p) != null) {
                throw new IllegalArgumentException(partsJson + ": two parts are named '" + p.name() + "'");
            }
        }
    }

    /** The {@code parts.json} the thorax was read from. */
    public Path partsJson() {
        return partsJson;
    }

    /** The frame the coordinates are in, as {@code parts.json} describes it (its units are the files'). */
    public String frame() {
        return frame;
    }

    /** The units of the mesh files (the loaded meshes are in metres whatever this is). */
    public MeshUnits fileUnits() {
        return units;
    }

    /** Every loaded part, in file order. */
    public List<ThoraxPart> parts() {
        return parts;
    }

    /** The part of that name, if loaded. */
    public Optional<ThoraxPart> find(String name) {
        return Optional.ofNullable(byName.get(name));
    }

    /** The part of that name; refused, listing the loaded names, when there is none. */
    public ThoraxPart part(String name) {
        ThoraxPart p = byName.get(name);
        if (p == null) {
            throw new IllegalArgumentException(partsJson + ": no loaded part named '" + name + "'; loaded: "
                    + String.join(", ", byName.keySet()));
        }
        return p;
    }

    /** The parts of a group, in file order (empty when that group was not loaded). */
    public List<ThoraxPart> group(Group g) {
        return parts.stream().filter(p -> p.group() == g).collect(Collectors.toList());
    }

    /** The parts of a group on one side, in file order. */
    public List<ThoraxPart> group(Group g, Side side) {
        return parts.stream().filter(p -> p.group() == g && p.side() == side).collect(Collectors.toList());
    }

    /** Rib {@code number} (1-12) on that side, if loaded. */
    public Optional<ThoraxPart> rib(Side side, int number) {
        return numbered(Group.RIB, side, number);
    }

    /** The costal cartilage of rib {@code number} on that side, if loaded. */
    public Optional<ThoraxPart> cartilage(Side side, int number) {
        return numbered(Group.CARTILAGE, side, number);
    }

    /** The vertebra at {@code level} (e.g. {@code T10}, {@code L1}), if loaded. */
    public Optional<ThoraxPart> vertebra(String level) {
        return parts.stream().filter(p -> p.group() == Group.VERTEBRA && level.equalsIgnoreCase(p.level()))
                .findFirst();
    }

    private Optional<ThoraxPart> numbered(Group g, Side side, int number) {
        return parts.stream().filter(p -> p.group() == g && p.side() == side && p.index() != null
                && p.index() == number).findFirst();
    }

    /** Bounds of the parts of the given groups (all parts when none is given): {min x, y, z, max x, y, z}, m. */
    public double[] bounds(Group... groups) {
        List<Group> want = groups.length == 0 ? List.of(Group.values()) : List.of(groups);
        double[] b = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        List<ThoraxPart> chosen = new ArrayList<>();
        for (ThoraxPart p : parts) {
            if (want.contains(p.group())) {
                chosen.add(p);
            }
        }
        if (chosen.isEmpty()) {
            throw new IllegalArgumentException(partsJson + ": no loaded part in groups " + want);
        }
        for (ThoraxPart p : chosen) {
            double[] m = p.mesh().bounds();
            for (int a = 0; a < 3; a++) {
                b[a] = Math.min(b[a], m[a]);
                b[a + 3] = Math.max(b[a + 3], m[a + 3]);
            }
        }
        return b;
    }

    @Override
    public String toString() {
        return "Thorax[" + parts.size() + " parts from " + partsJson + "]";
    }
}

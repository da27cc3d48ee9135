package org.tensim.io.thorax;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.EnumSet;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.tensim.io.Json;
import org.tensim.io.mesh.MeshCleaner;
import org.tensim.io.mesh.MeshFormatException;
import org.tensim.io.mesh.MeshLoader;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.thorax.ThoraxPart.Group;
import org.tensim.io.thorax.ThoraxPart.Side;

/**
 * Reads a thorax: a folder of surface meshes and the {@code parts.json} that lists them, as in
 * {@code ../shared/meshes/thorax}.
 *
 * <p>{@code parts.json} is an object with an optional {@code "frame"} (text), an optional {@code "units"}
 * ({@code "mm"}, the default, or {@code "m"}: the units of every mesh file) and {@code "parts"}: a list of
 * {@code {"file", "group", "side", "index", "units", "bounds_mm", ...}}. Per part: {@code file} is resolved beside
 * {@code parts.json}; {@code group} is one of {@link Group#parse}'s strings; {@code side} is left, right or absent;
 * {@code index} is the rib number 1-12 for ribs and cartilages (required) and the level ({@code "T10"}) for
 * vertebrae (required), and is ignored for other groups; {@code units}, when given, must equal the thorax's (a part in
 * other units is refused, never rescaled silently); {@code bounds_mm}, when given ({@code [[min x, y, z], [max x, y,
 * z]]}, mm), must agree with the mesh read: a mesh whose bounding-box diagonal differs from it by more than a factor
 * of 2, or whose centre lies more than half that diagonal away, is refused (it is in other units, or another frame).
 * Other keys (source, triangles, ...) are ignored.
 *
 * <p>Every entry's description is checked; the files are read only for the groups asked for. Meshes are cleaned
 * with every component kept: the cartilages come in several pieces, and contact needs all of them.
 */
public final class ThoraxLoader {
    /**
     * The groups {@link #load(Path)} reads: the skeleton the diaphragm is attached to and touches (ribs,
     * cartilages, sternum, vertebrae) and the liver under it; not the lungs, pleura or second diaphragm.
     */
    public static final Set<Group> DEFAULT_GROUPS = Collections.unmodifiableSet(
            EnumSet.of(Group.RIB, Group.CARTILAGE, Group.STERNUM, Group.VERTEBRA, Group.LIVER));

    /** Largest rib number. */
    private static final int RIBS = 12;
    /** Bounding-box disagreement (as a factor of size) beyond which a part is refused. */
    private static final double SIZE_FACTOR = 2;

    private ThoraxLoader() {
    }

    /** Loads {@link #DEFAULT_GROUPS} from {@code dir/parts.json}. */
    public static Thorax load(Path dir) throws IOException {
        return load(dir, DEFAULT_GROUPS);
    }

    /**
     * Loads the parts of the given groups listed in {@code dir/parts.json}.
     *
     * @throws IOException when parts.json or a mesh is missing or malformed, or a part is in other units; the
     *                     message names parts.json, the entry (its position and file) and what was expected
     */
    public static Thorax load(Path dir, Set<Group> groups) throws IOException {
        Path json = dir.resolve("parts.json");
        if (!Files.isRegularFile(json)) {
            throw new IOException(json + ": no such file; expected the thorax's parts list (parts.json) in " + dir);
        }
        JsonNode root;
        try {
            root = Json.mapper().readTree(json.toFile());
        } catch (JsonProcessingException e) {
            throw new IOException(json + ", line " + e.getLocation().getLineNr() + ": not valid JSON ("
                    + e.getOriginalMessage() + ")");
        }
        if (root == null || !root.isObject()) {
            throw new IOException(json + ": expected a JSON object with \"parts\": [...]");
        }
        MeshUnits units = units(root.get("units"), json + ", top-level \"units\"", MeshUnits.MM);
        JsonNode frame = root.get("frame");
        if (frame != null && !frame.isTextual()) {
            throw new IOException(json + ": \"frame\" is " + frame + "; expected a text describing the axes");
        }
        JsonNode list = root.get("parts");
        if (list == null || !list.isArray() || list.size() == 0) {
            throw new IOException(json + ": expected \"parts\": a non-empty list of {\"file\", \"group\", ...}, got "
                    + (list == null ? "none" : list.getNodeType().toString().toLowerCase(Locale.ROOT)));
        }
        List<ThoraxPart> parts = new ArrayList<>();
        Map<String, String> seen = new HashMap<>();
        for (int i = 0; i < list.size(); i++) {
            Entry e = entry(json, i, list.get(i), units);
            String before = seen.put(e.name, e.where);
            if (before != null) {
                throw new IOException(e.where + ": the part name '" + e.name + "' is already used by " + before
                        + "; expected unique file names");
            }
            if (groups.contains(e.group)) {
                parts.add(read(e, dir, units));
            }
        }
        return new Thorax(json, frame == null ? "" : frame.asText(), units, parts);
    }

    /** One entry's description, checked. */
    private static final class Entry {
        String where;
        String file;
        String name;
        Group group;
        Side side;
        Integer index;
        String level;
        double[] boundsMm;
    }

    private static Entry entry(Path json, int i, JsonNode n, MeshUnits units) throws IOException {
        Entry e = new Entry();
        e.where = json + ", parts[" + i + "]";
        if (n == null || !n.isObject()) {
            throw new IOException(e.where + ": expected an object {\"file\", \"group\", ...}, got " + n);
        }
        JsonNode f = n.get("file");
        if (f == null || !f.isTextual() || f.asText().isBlank()) {
            throw new IOException(e.where + ": expected \"file\": the mesh file's name, got " + f);
        }
        e.file = f.asText();
        e.where += " (file '" + e.file + "')";
        String base = Path.of(e.file).getFileName().toString();
        int dot = base.lastIndexOf('.');
        e.name = dot > 0 ? base.substring(0, dot) : base;
        JsonNode g = n.get("group");
        if (g == null || !g.isTextual()) {
            throw new IOException(e.where + ": expected \"group\": one of " + Group.known() + ", got " + g);
        }
        e.group = Group.parse(g.asText(), base);
        if (e.group == null) {
            throw new IOException(e.where + ": unknown group '" + g.asText() + "'; expected one of "
                    + Group.known());
        }
        e.side = side(n.get("side"), e.where);
        MeshUnits own = units(n.get("units"), e.where + ", \"units\"", units);
        if (own != units) {
            throw new IOException(e.where + ": the part is in '" + name(own) + "' but the thorax's units are '"
                    + name(units) + "' (top-level \"units\", mm unless given); expected every part in the same units");
        }
        JsonNode idx = n.get("index");
        if (e.group == Group.RIB || e.group == Group.CARTILAGE) {
            String what = e.group == Group.RIB ? "a rib" : "a costal cartilage";
            if (idx == null || !idx.isIntegralNumber() || idx.asInt() < 1 || idx.asInt() > RIBS) {
                throw new IOException(e.where + ": " + what + " without its number: expected \"index\": the rib"
                        + " number 1-" + RIBS + ", got " + (idx == null ? "none" : idx.toString()));
            }
            if (e.side == Side.NONE) {
                throw new IOException(e.where + ": " + what + " without its side: expected \"side\": \"left\" or"
                        + " \"right\"");
            }
            e.index = idx.asInt();
        } else if (e.group == Group.VERTEBRA) {
            if (idx == null || !idx.isTextual() || !idx.asText().matches("[CTLSctls][0-9]{1,2}")) {
                throw new IOException(e.where + ": a vertebra without its level: expected \"index\": a level such as"
                        + " \"T10\" or \"L1\", got " + (idx == null ? "none" : idx.toString()));
            }
            e.level = idx.asText().toUpperCase(Locale.ROOT);
        }
        e.boundsMm = bounds(n.get("bounds_mm"), e.where);
        return e;
    }

    private static ThoraxPart read(Entry e, Path dir, MeshUnits units) throws IOException {
        Path file = dir.resolve(e.file);
        if (!Files.isRegularFile(file)) {
            throw new IOException(e.where + ": names a missing file " + file + "; expected the mesh beside parts.json");
        }
        MeshCleaner.Result r;
        try {
            r = MeshLoader.load(file, units, MeshCleaner.Options.defaults().keepingAllComponents());
        } catch (MeshFormatException | IllegalArgumentException ex) {
            throw new IOException(e.where + ": " + ex.getMessage(), ex);
        }
        if (e.boundsMm != null) {
            checkBounds(e, r.mesh().bounds(), units);
        }
        return new ThoraxPart(e.name, e.group, e.side, e.index, e.level, file, r.mesh(), r.report());
    }

    /** Refuses a mesh whose size or place disagrees with bounds_mm: a part in other units or another frame. */
    private static void checkBounds(Entry e, double[] boundsM, MeshUnits units) throws IOException {
        double listed = 0;
        double read = 0;
        double offset = 0;
        for (int a = 0; a < 3; a++) {
            listed += sq(e.boundsMm[a + 3] - e.boundsMm[a]);
            read += sq((boundsM[a + 3] - boundsM[a]) * 1e3);
            offset += sq((boundsM[a + 3] + boundsM[a]) * 1e3 / 2 - (e.boundsMm[a + 3] + e.boundsMm[a]) / 2);
        }
        listed = Math.sqrt(listed);
        read = Math.sqrt(read);
        offset = Math.sqrt(offset);
        if (read > SIZE_FACTOR * listed || read < listed / SIZE_FACTOR) {
            throw new IOException(String.format(Locale.ROOT, "%s: the mesh read as '%s' measures %.4g mm across"
                    + " (bounding-box diagonal) but \"bounds_mm\" says %.4g mm (a factor %.3g); expected the same"
                    + " size within a factor %.0f: is the file in other units than the thorax's '%s'?", e.where,
                    name(units), read, listed, read / listed, SIZE_FACTOR, name(units)));
        }
        if (offset > listed / 2) {
            throw new IOException(String.format(Locale.ROOT, "%s: the mesh's centre lies %.4g mm from the centre of"
                    + " \"bounds_mm\", more than half its %.4g mm diagonal; expected the mesh in the thorax's frame",
                    e.where, offset, listed));
        }
    }

    private static MeshUnits units(JsonNode n, String where, MeshUnits dflt) throws IOException {
        if (n == null) {
            return dflt;
        }
        if (n.isTextual()) {
            String s = n.asText().trim().toLowerCase(Locale.ROOT);
            if (s.equals("mm")) {
                return MeshUnits.MM;
            }
            if (s.equals("m")) {
                return MeshUnits.M;
            }
        }
        throw new IOException(where + " is " + n + "; expected \"mm\" or \"m\"");
    }

    private static String name(MeshUnits u) {
        return u == MeshUnits.MM ? "mm" : "m";
    }

    private static Side side(JsonNode n, String where) throws IOException {
        if (n == null || n.isNull()) {
            return Side.NONE;
        }
        if (n.isTextual()) {
            switch (n.asText().trim().toLowerCase(Locale.ROOT)) {
                case "left":
                    return Side.LEFT;
                case "right":
                    return Side.RIGHT;
                case "none":
                case "":
                    return Side.NONE;
                default:
                    break;
            }
        }
        throw new IOException(where + ": \"side\" is " + n + "; expected \"left\", \"right\" or none");
    }

    private static double[] bounds(JsonNode n, String where) throws IOException {
        if (n == null || n.isNull()) {
            return null;
        }
        String expected = "; expected \"bounds_mm\": [[min x, min y, min z], [max x, max y, max z]] in mm";
        if (!n.isArray() || n.size() != 2) {
            throw new IOException(where + ": \"bounds_mm\" is " + n + expected);
        }
        double[] b = new double[6];
        for (int h = 0; h < 2; h++) {
            JsonNode c = n.get(h);
            if (!c.isArray() || c.size() != 3) {
                throw new IOException(where + ": \"bounds_mm\"[" + h + "] is " + c + expected);
            }
            for (int a = 0; a < 3; a++) {
                if (!c.get(a).isNumber()) {
                    throw new IOException(where + ": \"bounds_mm\"[" + h + "][" + a + "] is " + c.get(a)
                            + ", not a number" + expected);
                }
                b[3 * h + a] = c.get(a).asDouble();
            }
        }
        for (int a = 0; a < 3; a++) {
            if (!(b[a] <= b[a + 3])) {
                throw new IOException(where + ": \"bounds_mm\" min[" + a + "] = " + b[a] + " is above max[" + a
                        + "] = " + b[a + 3] + expected);
            }
        }
        return b;
    }

    private static double sq(double x) {
        return x * x;
    }
}

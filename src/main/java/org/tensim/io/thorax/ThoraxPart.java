package org.tensim.io.thorax;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import java.util.stream.Collectors;
import org.tensim.io.mesh.MeshReport;
import org.tensim.io.mesh.TriangleMesh;

/**
 * One surface of the thorax (a bone, a cartilage, an organ), as listed in {@code parts.json} and loaded from its
 * file.
 *
 * @param name   the file name without its extension, e.g. {@code rib-r9}, {@code vertebra-T10}; unique in a thorax
 * @param group  what kind of part it is
 * @param side   the patient's side ({@link Side#NONE} for midline parts and wherever {@code parts.json} gives none)
 * @param index  the rib number 1-12 for ribs and costal cartilages (a cartilage carries its rib's number); null for
 *               every other group
 * @param level  the vertebral level for vertebrae ({@code T10}, {@code L1}: region letter C, T, L or S and a number);
 *               null for every other group. Kept as text rather than folded into {@code index} because T10 and L1
 *               number different regions of the spine.
 * @param file   the mesh file it was read from
 * @param mesh   the surface, cleaned (welded, degenerate triangles dropped, every component kept), coordinates in m
 * @param report what the cleaning found and did (holes, non-manifold edges)
 */
public record ThoraxPart(String name, Group group, Side side, Integer index, String level, Path file,
        TriangleMesh mesh, MeshReport report) {

    /** The kind of part. */
    public enum Group {
        RIB, CARTILAGE, STERNUM, VERTEBRA, LUNG, LIVER, PLEURA, OTHER;

        /**
         * The group named by a {@code parts.json} "group" string: rib, cartilage (or costal-cartilage), sternum,
         * vertebra, lung, liver, pleura, other; and "organ", which the shared thorax uses for every soft organ, is
         * resolved by the file's name ({@code lung-*}, {@code liver*}, {@code pleura*}, else OTHER: the second
         * diaphragm).
         *
         * @return the group, or null when the string names none (the caller reports it with its location)
         */
        static Group parse(String group, String fileName) {
            String g = group.trim().toLowerCase(Locale.ROOT);
            switch (g) {
                case "costal-cartilage":
                case "costal_cartilage":
                    return CARTILAGE;
                case "organ":
                    String f = fileName.toLowerCase(Locale.ROOT);
                    return f.startsWith("lung") ? LUNG : f.startsWith("liver") ? LIVER
                            : f.startsWith("pleura") ? PLEURA : OTHER;
                default:
                    for (Group v : values()) {
                        if (v.name().toLowerCase(Locale.ROOT).equals(g)) {
                            return v;
                        }
                    }
                    return null;
            }
        }

        /** The strings {@link #parse} accepts, for error messages. */
        static String known() {
            return Arrays.stream(values()).map(v -> v.name().toLowerCase(Locale.ROOT))
                    .collect(Collectors.joining(", ")) + ", costal-cartilage, organ (resolved by file name)";
        }
    }

    /** The patient's side: +x is the patient's left in the shared thorax's frame. */
    public enum Side {
        LEFT, RIGHT, NONE
    }

    public ThoraxPart {
        if (name == null || group == null || side == null || file == null || mesh == null) {
            throw new IllegalArgumentException("a thorax part needs a name, group, side, file and mesh; got name "
                    + name + ", group " + group + ", side " + side + ", file " + file);
        }
    }

    @Override
    public String toString() {
        return "ThoraxPart[" + name + ", " + group + ", " + side + (index != null ? ", " + index : "")
                + (level != null ? ", " + level : "") + ", " + mesh.triangleCount() + " triangles]";
    }
}

package org.tensim.scene.diaphragm;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.tensim.io.thorax.Thorax;
import org.tensim.io.thorax.ThoraxLoader;
import org.tensim.io.thorax.ThoraxPart;
import org.tensim.scene.thorax.DistanceGrid;

/**
 * The bones of a thorax folder ({@code parts.json} and its surfaces, {@link ThoraxLoader}) as the
 * scene's {@link Bones}: ribs, costal cartilages, the sternum's parts (the xiphoid apart: the sternal
 * origin), the vertebrae (numbered T10-T12 as 10-12, L1-L3 as 13-15) and the liver. Each bone's signed
 * distance is a {@link DistanceGrid}, made on first use.
 */
final class ThoraxBones {
    private ThoraxBones() {
    }

    static Bones load(Path dir) throws IOException {
        Thorax thorax = ThoraxLoader.load(dir);
        List<Bones.Bone> out = new ArrayList<>();
        for (ThoraxPart p : thorax.parts()) {
            Bones.Side side = switch (p.side()) {
                case LEFT -> Bones.Side.LEFT;
                case RIGHT -> Bones.Side.RIGHT;
                default -> Bones.Side.NONE;
            };
            switch (p.group()) {
                case RIB -> out.add(new Bones.Bone(p.name(), Bones.Kind.RIB, side, p.index(), p.mesh()));
                case CARTILAGE -> out.add(new Bones.Bone(p.name(), Bones.Kind.CARTILAGE, side, p.index(), p.mesh()));
                case STERNUM -> out.add(new Bones.Bone(p.name(), p.name().toLowerCase(Locale.ROOT).contains("xiphoid")
                        ? Bones.Kind.XIPHOID : Bones.Kind.STERNUM, Bones.Side.NONE, 0, p.mesh()));
                case VERTEBRA -> out.add(new Bones.Bone(p.name(), Bones.Kind.VERTEBRA, Bones.Side.NONE,
                        vertebraNumber(p), p.mesh()));
                case LIVER -> out.add(new Bones.Bone(p.name(), Bones.Kind.LIVER, Bones.Side.NONE, 0, p.mesh()));
                default -> {
                    // lungs, pleura, other: not part of the diaphragm's boundary conditions
                }
            }
        }
        if (out.stream().noneMatch(b -> b.kind() == Bones.Kind.RIB)) {
            throw new IOException(thorax.partsJson() + ": no ribs among its parts; a thorax needs ribs 1-12 (group"
                    + " \"rib\" with side and index)");
        }
        return new Bones(out, "thorax " + dir, DistanceGrid::build);
    }

    /** T10-T12 as 10-12, L1-L5 as 13-17. */
    private static int vertebraNumber(ThoraxPart p) {
        String level = p.level() == null ? "" : p.level().toUpperCase(Locale.ROOT);
        try {
            if (level.startsWith("T")) {
                return Integer.parseInt(level.substring(1));
            }
            if (level.startsWith("L")) {
                return 12 + Integer.parseInt(level.substring(1));
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new IllegalArgumentException(p.file() + ": vertebra level '" + p.level() + "' is not T1-T12 or L1-L5");
    }
}

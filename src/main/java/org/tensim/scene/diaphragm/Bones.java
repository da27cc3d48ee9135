package org.tensim.scene.diaphragm;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.SignedDistance;

/**
 * The bones and cartilage around the diaphragm as surfaces (metres, the mesh's frame): what the
 * diaphragm is attached to at its origins and slides on in the zone of apposition. Read from a
 * thorax folder ({@code --thorax}); each bone's signed distance is made once, on first use, and
 * kept, so that rebuilding a scene with other constants does not make it again.
 */
public final class Bones {
    /** What a bone is. */
    public enum Kind { RIB, CARTILAGE, STERNUM, XIPHOID, VERTEBRA, LIVER }

    /** Side of a paired bone. */
    public enum Side { LEFT, RIGHT, NONE }

    /**
     * One bone.
     *
     * @param name  its name (the file's, e.g. {@code rib-r9})
     * @param kind  what it is
     * @param side  left, right, or none (sternum, vertebrae, liver)
     * @param index rib or cartilage number 1-12; vertebra: 10-12 for T10-T12, 13-15 for L1-L3; else 0
     * @param mesh  its surface, metres
     */
    public record Bone(String name, Kind kind, Side side, int index, TriangleMesh mesh) {
        /** Whether the diaphragm arises from this bone (Gray's Anatomy; see {@link #origin}). */
        public boolean origin() {
            return Bones.origin(this);
        }
    }

    private final List<Bone> bones;
    private final String source;
    private final Function<TriangleMesh, SignedDistance> fieldMaker;
    private final SignedDistance[] fields;

    /**
     * @param bones      the bones
     * @param source     where they came from, for summaries
     * @param fieldMaker makes a bone's signed distance from its surface (called once per bone, on first use)
     */
    public Bones(List<Bone> bones, String source, Function<TriangleMesh, SignedDistance> fieldMaker) {
        this.bones = List.copyOf(bones);
        this.source = source;
        this.fieldMaker = fieldMaker;
        this.fields = new SignedDistance[bones.size()];
    }

    public List<Bone> all() {
        return bones;
    }

    public String source() {
        return source;
    }

    /** The bones of a kind, in order. */
    public List<Bone> of(Kind kind) {
        List<Bone> out = new ArrayList<>();
        for (Bone b : bones) {
            if (b.kind() == kind) {
                out.add(b);
            }
        }
        return out;
    }

    /** The bone of a kind, side and number, or null. */
    public Bone find(Kind kind, Side side, int index) {
        for (Bone b : bones) {
            if (b.kind() == kind && b.side() == side && b.index() == index) {
                return b;
            }
        }
        return null;
    }

    /** Bone i's signed distance in its rest frame (made on first use, then kept). */
    public synchronized SignedDistance field(int i) {
        if (fields[i] == null) {
            fields[i] = fieldMaker.apply(bones.get(i).mesh());
        }
        return fields[i];
    }

    /** Index of a bone in {@link #all()}. */
    public int indexOf(Bone b) {
        return bones.indexOf(b);
    }

    /**
     * The diaphragm's origins (Gray's Anatomy, 41st ed.): the xiphoid (sternal part);
     * the inner surfaces of the lower six costal cartilages and ribs, 7-12 (costal part); the bodies of
     * the lumbar vertebrae, right L1-L3 and left L1-L2 (the crura; the arcuate ligaments span from them
     * to rib 12).
     */
    static boolean origin(Bone b) {
        return switch (b.kind()) {
            case XIPHOID -> true;
            case RIB, CARTILAGE -> b.index() >= 7;
            case VERTEBRA -> b.index() >= 13;
            default -> false;
        };
    }
}

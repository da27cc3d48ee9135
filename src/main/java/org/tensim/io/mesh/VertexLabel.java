package org.tensim.io.mesh;

import java.util.Arrays;
import java.util.Locale;
import java.util.stream.Collectors;

/**
 * The tissue a diaphragm mesh's vertex belongs to, as written in a labels file
 * ({@link VertexLabelsFile}). The muscle's origins are split by the structure it
 * arises from, because each is fixed to a different part of the cage.
 */
public enum VertexLabel {
    /** Contractile muscle. */
    MUSCLE,
    /** The central tendon (passive, stiffer). */
    TENDON,
    /** Muscle arising from the back of the xiphoid process. */
    ORIGIN_STERNAL,
    /** Muscle arising from the inner faces of the lower six costal cartilages and ribs. */
    ORIGIN_COSTAL,
    /** Muscle arising from the arcuate ligaments and the crura on the lumbar vertebrae. */
    ORIGIN_LUMBAR;

    private final String fileName = name().toLowerCase(Locale.ROOT).replace('_', '-');

    /** The name in a labels file: lower case, words joined by '-' (e.g. {@code origin-costal}). */
    public String fileName() {
        return fileName;
    }

    /** Whether this is one of the muscle's origins (attached to the cage or spine). */
    public boolean isOrigin() {
        return this == ORIGIN_STERNAL || this == ORIGIN_COSTAL || this == ORIGIN_LUMBAR;
    }

    /** The known file names, comma-separated, in declaration order (for error messages). */
    public static String knownNames() {
        return Arrays.stream(values()).map(VertexLabel::fileName).collect(Collectors.joining(", "));
    }

    /**
     * The label written as {@code name} in a file. Exact match only: a label file is
     * machine-written, and accepting case or '_' variants would let two spellings of one
     * label drift apart.
     *
     * @throws IllegalArgumentException naming {@code name} and listing the known names
     */
    public static VertexLabel parse(String name) {
        for (VertexLabel l : values()) {
            if (l.fileName.equals(name)) {
                return l;
            }
        }
        throw new IllegalArgumentException("unknown vertex label '" + name + "'; expected one of " + knownNames());
    }
}

package org.tensim.io.mesh;

import java.nio.file.Path;

/**
 * A mesh file that cannot be read. The message names the file, where the problem
 * is (a line number for text formats, a byte offset for binary STL) and what was
 * expected there. No partial mesh is ever returned with it.
 */
public final class MeshFormatException extends Exception {
    private final transient Path file;
    private final String location;

    /**
     * @param file     the file being read
     * @param location where, e.g. {@code "line 12"} or {@code "byte 134"}
     * @param problem  what was found and what was expected
     */
    public MeshFormatException(Path file, String location, String problem) {
        super(file + ", " + location + ": " + problem);
        this.file = file;
        this.location = location;
    }

    public Path file() {
        return file;
    }

    /** Where in the file, e.g. {@code "line 12"} or {@code "byte 134"}. */
    public String location() {
        return location;
    }

    static MeshFormatException atLine(Path file, int line, String problem) {
        return new MeshFormatException(file, "line " + line, problem);
    }

    static MeshFormatException atByte(Path file, long offset, String problem) {
        return new MeshFormatException(file, "byte " + offset, problem);
    }
}

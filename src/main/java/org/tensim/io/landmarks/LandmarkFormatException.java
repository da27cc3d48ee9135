package org.tensim.io.landmarks;

import java.nio.file.Path;

/**
 * A landmark file that cannot be read. The message names the file, the line and what was expected there; no
 * partial set is ever returned with it.
 */
public final class LandmarkFormatException extends Exception {
    private final transient Path file;
    private final int line;

    /**
     * @param file    the file being read
     * @param line    its line, from 1 (0 when the problem is the whole file's)
     * @param problem what was found and what was expected
     */
    public LandmarkFormatException(Path file, int line, String problem) {
        super(file.getFileName() + (line > 0 ? ", line " + line : "") + ": " + problem);
        this.file = file;
        this.line = line;
    }

    /** The file that was being read. */
    public Path file() {
        return file;
    }

    /** The line of the problem, from 1; 0 for the whole file. */
    public int line() {
        return line;
    }
}

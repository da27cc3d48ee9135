package org.tensim.scene.file;

/**
 * A scene file that cannot be used. The message reads {@code file:line:column: key.path: what is wrong
 * (what was expected)}, e.g. {@code liver.yaml:12:5: bodies.liver.material.E: "3 kPa/m" is not a pressure
 * (expected a value in Pa, e.g. "2 kPa")}. It is a refusal of the input, never a program error: commands print
 * the message alone and exit with the usage code.
 */
public final class SceneException extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;
    /** The file or folder the scene names that does not exist (null: another refusal). */
    private final transient java.nio.file.Path absent;

    public SceneException(String message) {
        this(message, null);
    }

    private SceneException(String message, java.nio.file.Path absent) {
        super(message);
        this.absent = absent;
    }

    /**
     * A refusal because the file or folder named at {@code node} does not exist: the same message as
     * {@link #at}, and the path, so that a suite can skip a scene whose data is not on this machine (naming it)
     * rather than fail it.
     */
    public static SceneException absent(SceneNode node, String message, java.nio.file.Path path) {
        return new SceneException(node.where() + ": " + node.shownPath() + ": " + message, path);
    }

    /** The named file or folder that does not exist, when that is the refusal. */
    public java.util.Optional<java.nio.file.Path> absentPath() {
        return java.util.Optional.ofNullable(absent);
    }

    /** A refusal of the value at {@code node}: its place and key path, then the message. */
    public static SceneException at(SceneNode node, String message) {
        return new SceneException(node.where() + ": " + node.shownPath() + ": " + message);
    }
}

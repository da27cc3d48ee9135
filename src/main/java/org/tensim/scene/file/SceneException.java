package org.tensim.scene.file;

/**
 * A scene file that cannot be used. The message reads {@code file:line:column: key.path: what is wrong
 * (what was expected)}, e.g. {@code liver.yaml:12:5: bodies.liver.material.E: "3 kPa/m" is not a pressure
 * (expected a value in Pa, e.g. "2 kPa")}. It is a refusal of the input, never a program error: commands print
 * the message alone and exit with the usage code.
 */
public final class SceneException extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;

    public SceneException(String message) {
        super(message);
    }

    /** A refusal of the value at {@code node}: its place and key path, then the message. */
    public static SceneException at(SceneNode node, String message) {
        return new SceneException(node.where() + ": " + node.shownPath() + ": " + message);
    }
}

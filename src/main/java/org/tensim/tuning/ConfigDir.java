package org.tensim.tuning;

import java.nio.file.Path;
import java.util.Map;

/**
 * Where the GUI keeps what it restores at the next start:
 * {@code $XDG_CONFIG_HOME/tensim/} when that variable is set to an absolute path
 * (XDG Base Directory specification), else {@code ~/.config/tensim/}.
 */
public final class ConfigDir {
    private ConfigDir() {
    }

    /** The folder for this user's environment. */
    public static Path resolve() {
        return resolve(System.getenv(), System.getProperty("user.home"));
    }

    /** The folder for the given environment and home folder (testable). */
    public static Path resolve(Map<String, String> env, String home) {
        String xdg = env.get("XDG_CONFIG_HOME");
        // The specification says relative values are invalid and must be ignored.
        if (xdg != null && !xdg.isBlank() && Path.of(xdg).isAbsolute()) {
            return Path.of(xdg, "tensim");
        }
        return Path.of(home, ".config", "tensim");
    }

    /** The last-used settings file of a scene in folder dir. */
    public static Path lastUsed(Path dir, String scene) {
        return dir.resolve("last-" + scene + ".json");
    }
}

package org.tensim.scene.file;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tensim.scene.file.bodies.CubeBody;
import org.tensim.scene.file.bodies.DiaphragmBodyType;
import org.tensim.scene.file.bodies.ShellBodyType;
import org.tensim.scene.file.bodies.VolumeBodyType;

/** The body types scene files may name, by their {@link BodyType#name()}: the built-in ones and any registered. */
public final class BodyTypes {
    private static final Map<String, BodyType> TYPES = new LinkedHashMap<>();

    static {
        register(new CubeBody());
        register(new VolumeBodyType());
        register(new ShellBodyType());
        register(new DiaphragmBodyType());
    }

    private BodyTypes() {
    }

    /** Adds a type (replacing one of the same name). */
    public static synchronized void register(BodyType type) {
        TYPES.put(type.name(), type);
    }

    /** Removes a registered type (a built-in one too); nothing if there is none of that name. */
    public static synchronized void unregister(String name) {
        TYPES.remove(name);
    }

    /** The type of that name, or null. */
    public static synchronized BodyType get(String name) {
        return TYPES.get(name);
    }

    /** Every type's name, built-in first. */
    public static synchronized List<String> names() {
        return new ArrayList<>(TYPES.keySet());
    }
}

package org.tensim.scene.file;

import java.util.Collection;
import java.util.List;

/**
 * Reads the keys of one map of a scene file. The keys it accepts are given up front: any other key is refused at
 * once, with the nearest accepted key as a "did you mean" ({@link DidYouMean}). Required keys that are missing
 * are refused at the map's place; every value read is checked for its kind, and quantities are converted to SI
 * by the file's {@link SceneUnits}.
 */
public final class MapReader {
    private final SceneNode map;

    /** Refuses {@code node} unless it is a map whose keys are all among {@code accepted}. */
    public MapReader(SceneNode node, Collection<String> accepted) {
        if (!node.isMap()) {
            throw SceneException.at(node, "expected a map of keys (" + String.join(", ", accepted) + "), got "
                    + node.describe());
        }
        this.map = node;
        for (String key : node.entries().keySet()) {
            if (!accepted.contains(key)) {
                throw new SceneException(node.keyWhere(key) + ": " + SceneNode.child(node.path(), key)
                        + ": unknown key '" + key + "'" + DidYouMean.suggest(key, accepted) + " (accepted here: "
                        + String.join(", ", accepted) + ")");
            }
        }
    }

    /** The map itself. */
    public SceneNode node() {
        return map;
    }

    public boolean has(String key) {
        SceneNode v = map.get(key);
        return v != null && v.kind() != SceneNode.Kind.NULL;
    }

    /** The value of a key that must be there. */
    public SceneNode required(String key) {
        if (!has(key)) {
            throw new SceneException(map.where() + ": " + SceneNode.child(map.path(), key) + ": missing: the key is"
                    + " required " + (map.path().isEmpty() ? "at the top level" : "in " + map.path()));
        }
        return map.get(key);
    }

    /** The value of a key, or null when it is absent (or null). */
    public SceneNode optional(String key) {
        return has(key) ? map.get(key) : null;
    }

    /** A required scalar. */
    public SceneNode scalar(String key) {
        SceneNode v = required(key);
        if (!v.isScalar()) {
            throw SceneException.at(v, "expected a single value, got " + v.describe());
        }
        return v;
    }

    /** A required quantity, SI. */
    public double quantity(String key, QuantityKind kind, SceneUnits units) {
        return units.si(required(key), kind);
    }

    /** A quantity, SI, or {@code fallback} (SI) when absent. */
    public double quantity(String key, QuantityKind kind, SceneUnits units, double fallback) {
        return has(key) ? units.si(map.get(key), kind) : fallback;
    }

    /** A quantity that must be > 0, SI, or {@code fallback} (NaN: the key is required). */
    public double positive(String key, QuantityKind kind, SceneUnits units, double fallback) {
        if (Double.isNaN(fallback)) {
            required(key);
        }
        double v = quantity(key, kind, units, fallback);
        if (!(v > 0)) {
            throw SceneException.at(has(key) ? map.get(key) : map, key + " must be > 0, got "
                    + (has(key) ? map.get(key).describe() : Double.toString(v)));
        }
        return v;
    }

    /** A quantity that must be >= 0, SI, or {@code fallback} (NaN: the key is required). */
    public double nonNegative(String key, QuantityKind kind, SceneUnits units, double fallback) {
        if (Double.isNaN(fallback)) {
            required(key);
        }
        double v = quantity(key, kind, units, fallback);
        if (!(v >= 0)) {
            throw SceneException.at(map.get(key), key + " must be >= 0, got " + map.get(key).describe());
        }
        return v;
    }

    /** A required string. */
    public String string(String key) {
        SceneNode v = scalar(key);
        return v.text();
    }

    /** A string, or {@code fallback} when absent. */
    public String string(String key, String fallback) {
        return has(key) ? string(key) : fallback;
    }

    /** One of {@code options}, or {@code fallback} when absent. */
    public String choice(String key, List<String> options, String fallback) {
        if (!has(key)) {
            return fallback;
        }
        SceneNode v = scalar(key);
        if (!options.contains(v.text())) {
            throw SceneException.at(v, v.describe() + " is not one of " + String.join(", ", options)
                    + DidYouMean.suggest(v.text(), options));
        }
        return v.text();
    }

    /** A whole number (>= min), or {@code fallback} when absent. */
    public long integer(String key, long min, long fallback) {
        if (!has(key)) {
            return fallback;
        }
        return integer(scalar(key), min);
    }

    /** A scalar node as a whole number >= min. */
    public static long integer(SceneNode v, long min) {
        long n;
        try {
            n = Long.parseLong(v.isScalar() ? v.text().strip() : "x");
        } catch (NumberFormatException e) {
            throw SceneException.at(v, v.describe() + " is not a whole number");
        }
        if (n < min) {
            throw SceneException.at(v, "expected a whole number >= " + min + ", got " + n);
        }
        return n;
    }

    /** A boolean, or {@code fallback} when absent. */
    public boolean bool(String key, boolean fallback) {
        if (!has(key)) {
            return fallback;
        }
        SceneNode v = scalar(key);
        if (v.text().equals("true") || v.text().equals("false")) {
            return Boolean.parseBoolean(v.text());
        }
        throw SceneException.at(v, v.describe() + " is not true or false");
    }

    /** A required list. */
    public SceneNode list(String key) {
        SceneNode v = required(key);
        if (!v.isList()) {
            throw SceneException.at(v, "expected a list [ ... ], got " + v.describe());
        }
        return v;
    }

    /** A required 3-vector of the kind, SI: {@code [x, y, z]}, each component a value of the kind. */
    public double[] vector(String key, QuantityKind kind, SceneUnits units) {
        return vector(required(key), kind, units);
    }

    /** A node as a 3-vector of the kind, SI. */
    public static double[] vector(SceneNode v, QuantityKind kind, SceneUnits units) {
        if (!v.isList() || v.items().size() != 3) {
            throw SceneException.at(v, "expected a vector of three values [x, y, z], got " + v.describe()
                    + (v.isList() ? " of " + v.items().size() : ""));
        }
        double[] out = new double[3];
        for (int i = 0; i < 3; i++) {
            out[i] = units.si(v.items().get(i), kind);
        }
        return out;
    }
}

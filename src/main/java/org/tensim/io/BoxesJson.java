package org.tensim.io;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Map.Entry;

/**
 * Reads named axis-aligned boxes from JSON, as in BodyParts3D's
 * {@code rib-sternum-bounds-mm.json}: {@code {"name": {"min": [x, y, z], "max": [x, y, z]}, ...}}.
 * Keys starting with '_' (comments) are skipped. Coordinates are converted to metres.
 */
public final class BoxesJson {
    private BoxesJson() {
    }

    /**
     * @param metresPerUnit file unit in metres (0.001 for millimetres)
     * @return {min x, min y, min z, max x, max y, max z} in metres, by name, in file order
     * @throws IOException when the file is missing or not of that form (the message names the file and the entry)
     */
    public static Map<String, double[]> read(Path file, double metresPerUnit) throws IOException {
        if (!Files.isRegularFile(file)) {
            throw new IOException(file + ": no such file; expected the rib and sternum boxes (JSON)");
        }
        JsonNode root;
        try {
            root = Json.mapper().readTree(file.toFile());
        } catch (JsonProcessingException e) {
            throw new IOException(file + ", line " + e.getLocation().getLineNr() + ": not valid JSON ("
                    + e.getOriginalMessage() + ")");
        }
        if (root == null || !root.isObject()) {
            throw new IOException(file + ": expected a JSON object of named boxes");
        }
        Map<String, double[]> out = new LinkedHashMap<>();
        for (Iterator<Entry<String, JsonNode>> it = root.fields(); it.hasNext();) {
            Entry<String, JsonNode> e = it.next();
            if (e.getKey().startsWith("_")) {
                continue;
            }
            double[] box = new double[6];
            for (int half = 0; half < 2; half++) {
                String key = half == 0 ? "min" : "max";
                JsonNode a = e.getValue().get(key);
                if (a == null || !a.isArray() || a.size() != 3) {
                    throw new IOException(file + ", entry '" + e.getKey() + "': expected \"" + key
                            + "\": [x, y, z]");
                }
                for (int k = 0; k < 3; k++) {
                    if (!a.get(k).isNumber()) {
                        throw new IOException(file + ", entry '" + e.getKey() + "', " + key + "[" + k + "]: '"
                                + a.get(k) + "' is not a number");
                    }
                    box[3 * half + k] = a.get(k).asDouble() * metresPerUnit;
                }
            }
            for (int k = 0; k < 3; k++) {
                if (box[k] > box[k + 3]) {
                    throw new IOException(file + ", entry '" + e.getKey() + "': min[" + k + "] = " + box[k]
                            + " m is above max[" + k + "] = " + box[k + 3] + " m");
                }
            }
            out.put(e.getKey(), box);
        }
        return out;
    }
}

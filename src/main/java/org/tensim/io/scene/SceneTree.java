package org.tensim.io.scene;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.dataformat.yaml.YAMLFactory;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Reads a scene file (YAML, or JSON for a {@code .json} file) into a {@link SceneNode} tree with each value's
 * line and column. The tree is built from Jackson's parser tokens, so that the place of every token survives
 * (Jackson's own tree drops it). Syntax errors are reported at the place Jackson gives; duplicate keys are refused.
 */
public final class SceneTree {
    private SceneTree() {
    }

    /** The file's top-level map. */
    public static SceneNode read(Path file) {
        String name = file.getFileName() == null ? file.toString() : file.getFileName().toString();
        byte[] bytes;
        try {
            bytes = Files.readAllBytes(file);
        } catch (NoSuchFileException e) {
            throw new SceneException(file + ": no such scene file");
        } catch (IOException e) {
            throw new SceneException(file + ": cannot read the scene file (" + e.getMessage() + ")");
        }
        boolean json = name.toLowerCase(Locale.ROOT).endsWith(".json");
        JsonFactory factory = json ? new JsonFactory() : new YAMLFactory();
        try (JsonParser p = factory.createParser(bytes)) {
            JsonToken t = p.nextToken();
            if (t == null) {
                throw new SceneException(name + ":1:1: (top level): the file is empty; expected a map with"
                        + " 'version: 1' and 'bodies:'");
            }
            SceneNode root = value(p, name, "");
            if (p.nextToken() != null) {
                throw new SceneException(where(name, p.currentTokenLocation()) + ": (top level): text after the"
                        + " end of the top-level value");
            }
            if (!root.isMap()) {
                throw SceneException.at(root, "expected a map of keys (version:, bodies:, ...) at the top"
                        + " level, got " + root.describe());
            }
            return root;
        } catch (JsonProcessingException e) {
            JsonLocation loc = e.getLocation();
            String at = loc == null ? name : where(name, loc);
            throw new SceneException(at + ": syntax error: " + firstLine(e.getOriginalMessage()));
        } catch (IOException e) {
            throw new SceneException(file + ": cannot read the scene file (" + e.getMessage() + ")");
        }
    }

    private static SceneNode value(JsonParser p, String file, String path) throws IOException {
        JsonToken t = p.currentToken();
        String at = where(file, p.currentTokenLocation());
        switch (t) {
            case START_OBJECT: {
                SceneNode m = SceneNode.map(at, path);
                while (p.nextToken() == JsonToken.FIELD_NAME) {
                    String key = p.currentName();
                    String keyAt = where(file, p.currentTokenLocation());
                    String childPath = SceneNode.child(path, key);
                    if (m.get(key) != null) {
                        throw new SceneException(keyAt + ": " + childPath + ": the key is given twice (first at "
                                + m.get(key).where() + ")");
                    }
                    p.nextToken();
                    m.put(key, value(p, file, childPath));
                }
                return m;
            }
            case START_ARRAY: {
                SceneNode l = SceneNode.list(at, path);
                int i = 0;
                while (p.nextToken() != JsonToken.END_ARRAY) {
                    l.add(value(p, file, path + "[" + i++ + "]"));
                }
                return l;
            }
            case VALUE_NUMBER_INT:
            case VALUE_NUMBER_FLOAT:
                return SceneNode.scalar(SceneNode.Token.NUMBER, p.getText(), at, path);
            case VALUE_TRUE:
            case VALUE_FALSE:
                return SceneNode.scalar(SceneNode.Token.BOOLEAN, p.getText(), at, path);
            case VALUE_NULL:
                return SceneNode.scalar(SceneNode.Token.NONE, null, at, path);
            default:
                return SceneNode.scalar(SceneNode.Token.STRING, p.getText(), at, path);
        }
    }

    static String where(String file, JsonLocation loc) {
        return file + ":" + loc.getLineNr() + ":" + loc.getColumnNr();
    }

    private static String firstLine(String message) {
        if (message == null) {
            return "unreadable text";
        }
        String m = message.strip();
        int nl = m.indexOf('\n');
        String first = nl < 0 ? m : m.substring(0, nl).strip();
        // Jackson adds the source description and a location of its own; the caller gives the place.
        int src = first.indexOf(" at [Source");
        return src < 0 ? first : first.substring(0, src);
    }
}

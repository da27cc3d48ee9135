package org.tensim.scene.file;

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
    /** The key path being read, for a syntax error's message. */
    private String reading = "";

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
        return read(name, bytes);
    }

    /** A scene's top-level map from its bytes; {@code name} (a .json name is read as JSON) is named in messages. */
    public static SceneNode read(String name, byte[] bytes) {
        boolean json = name.toLowerCase(Locale.ROOT).endsWith(".json");
        JsonFactory factory = json ? new JsonFactory() : new YAMLFactory();
        SceneTree tree = new SceneTree();
        try (JsonParser p = factory.createParser(bytes)) {
            JsonToken t = p.nextToken();
            if (t == null) {
                throw new SceneException(name + ":1:1: (top level): the file is empty; expected a map with"
                        + " 'version: 1' and 'bodies:'");
            }
            SceneNode root = tree.value(p, name, "");
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
            throw new SceneException(at + ": " + (tree.reading.isEmpty() ? "(top level)" : tree.reading)
                    + ": syntax error: " + firstLine(e.getOriginalMessage()));
        } catch (IOException e) {
            throw new SceneException(name + ": cannot read the scene file (" + e.getMessage() + ")");
        }
    }

    private SceneNode value(JsonParser p, String file, String path) throws IOException {
        reading = path;
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
                                + m.keyWhere(key) + ")");
                    }
                    reading = childPath;
                    p.nextToken();
                    m.put(key, value(p, file, childPath), keyAt);
                    reading = path;
                }
                return m;
            }
            case START_ARRAY: {
                SceneNode l = SceneNode.list(at, path);
                int i = 0;
                while (p.nextToken() != JsonToken.END_ARRAY) {
                    l.add(value(p, file, path + "[" + i++ + "]"));
                    reading = path;
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

    /**
     * The parser's message on one line: snakeyaml's "while parsing ... / expected ..., but got ..." lines, without
     * its quoted source lines, carets and "in 'reader'" places (the caller gives the place).
     */
    private static String firstLine(String message) {
        if (message == null) {
            return "unreadable text";
        }
        StringBuilder b = new StringBuilder();
        for (String line : message.strip().split("\n")) {
            String l = line.strip();
            if (l.isEmpty() || l.startsWith("in 'reader'") || l.startsWith("^") || line.startsWith("    ")) {
                continue;
            }
            int src = l.indexOf(" at [Source");
            b.append(b.length() == 0 ? "" : ": ").append(src < 0 ? l : l.substring(0, src));
        }
        return b.length() == 0 ? "unreadable text" : b.toString();
    }
}

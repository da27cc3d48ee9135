package org.tensim.app.scenetest;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.dataformat.yaml.YAMLFactory;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.stream.Stream;

/**
 * The scene files under a folder, searched recursively: the {@code .yaml}, {@code .yml} and {@code .json} files
 * whose top level has {@code bodies:} or {@code version:} and no {@code scene:} (a sweep's or a calibration's
 * spec names its scene by {@code scene:}; other YAML and JSON files have neither key). A file that cannot be read
 * as YAML or JSON at all is kept too, so that a scene with a syntax error is a failed test, not a missing one.
 * Folders whose name starts with a dot are not searched.
 */
public final class SceneFileFinder {
    /** A scene file found: its path, its path relative to the folder searched, and its run folder's name. */
    public record Found(Path file, String relative, String runName) {
    }

    private SceneFileFinder() {
    }

    /** The scene files under {@code dir}, in the order of their relative paths. */
    public static List<Found> find(Path dir) throws IOException {
        List<Path> files;
        try (Stream<Path> s = Files.walk(dir)) {
            files = s.filter(Files::isRegularFile).filter(p -> !hidden(dir, p)).filter(SceneFileFinder::named)
                    .sorted().toList();
        }
        List<Path> scenes = new ArrayList<>();
        for (Path p : files) {
            if (isScene(p)) {
                scenes.add(p);
            }
        }
        // Runs go to a folder named as the file without its extension, unless two files would share it.
        Map<String, Integer> stems = new HashMap<>();
        for (Path p : scenes) {
            stems.merge(stem(dir, p), 1, Integer::sum);
        }
        List<Found> out = new ArrayList<>();
        for (Path p : scenes) {
            String rel = relative(dir, p);
            String st = stem(dir, p);
            out.add(new Found(p, rel, stems.get(st) > 1 ? rel : st));
        }
        return out;
    }

    /**
     * Whether the file is a scene file by its top-level keys, or unreadable as YAML/JSON (see the class). An empty
     * file, or one whose top level is not a map, is not a scene file.
     */
    static boolean isScene(Path file) throws IOException {
        boolean json = file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".json");
        ObjectMapper mapper = new ObjectMapper(json ? new JsonFactory() : new YAMLFactory());
        JsonNode top;
        try {
            top = mapper.readTree(file.toFile());
        } catch (JsonProcessingException e) {
            return true;
        }
        return top != null && top.isObject() && !top.has("scene") && (top.has("bodies") || top.has("version"));
    }

    private static boolean named(Path p) {
        String n = p.getFileName().toString().toLowerCase(Locale.ROOT);
        return n.endsWith(".yaml") || n.endsWith(".yml") || n.endsWith(".json");
    }

    private static boolean hidden(Path dir, Path p) {
        for (Path part : dir.relativize(p)) {
            if (part.toString().startsWith(".")) {
                return true;
            }
        }
        return false;
    }

    private static String relative(Path dir, Path p) {
        return dir.relativize(p).toString().replace('\\', '/');
    }

    private static String stem(Path dir, Path p) {
        return relative(dir, p).replaceFirst("\\.(?i:json|yaml|yml)$", "");
    }
}

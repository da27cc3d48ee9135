package org.tensim.io;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Map;

/** JSON output through Jackson: one-line summaries and files written atomically. */
public final class Json {
    private static final ObjectMapper MAPPER = new ObjectMapper();
    private static final ObjectMapper PRETTY = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private Json() {
    }

    public static ObjectMapper mapper() {
        return MAPPER;
    }

    /** The value as one line of JSON. */
    public static String line(Object value) {
        try {
            return MAPPER.writeValueAsString(value);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("cannot write JSON: " + e.getMessage(), e);
        }
    }

    /** Writes the value, indented, to a temporary file then renames it onto {@code path} (mode 0644). */
    public static void write(Path path, Object value) throws IOException {
        byte[] bytes = PRETTY.writeValueAsBytes(value);
        OutputFiles.writeAtomically(path, out -> out.write(bytes));
    }

    /** Reads a JSON object file into a map. */
    @SuppressWarnings("unchecked")
    public static Map<String, Object> readMap(Path path) throws IOException {
        return MAPPER.readValue(path.toFile(), Map.class);
    }
}

package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;

/** docs/scene.schema.json and the loader accept the same keys, block by block, and the schema has no other block. */
class SceneSchemaTest {
    /** The loader's keys of each of the schema's definitions. */
    static Map<String, List<String>> loaderBlocks() {
        Map<String, List<String>> m = new LinkedHashMap<>();
        m.put("scene", SceneLoader.KEYS);
        m.put("units", SceneUnits.blockKeys());
        m.put("run", RunSettings.KEYS);
        TimeLaws.KEYS.forEach((t, k) -> m.put("law_" + t, k));
        for (String t : BodyTypes.names()) {
            List<String> k = new ArrayList<>(List.of("type"));
            k.addAll(BodyTypes.get(t).keys());
            m.put("body_" + t, k);
        }
        m.put("body_" + RigidBodies.TYPE, RigidBodies.KEYS);
        RigidBodies.MOTION_KEYS.forEach((t, k) -> m.put("rigid_motion_" + t, k));
        m.put("mesh", BodyContext.MESH_KEYS);
        m.put("region", SceneRegions.KEYS);
        SceneRegions.KIND_KEYS.forEach((kind, k) -> m.put("region_" + kind, k));
        SceneConditions.KEYS.forEach((t, k) -> m.put("condition_" + t, k));
        m.put("zone", SceneZones.KEYS);
        m.put("probe", SceneProbe.KEYS);
        m.put("expect", ExpectBlock.KEYS);
        m.put("parameter", SceneParameters.KEYS);
        return m;
    }

    @Test
    void schemaAndLoaderAcceptTheSameKeys() throws IOException {
        JsonNode defs = new ObjectMapper().readTree(Path.of("docs/scene.schema.json").toFile()).get("$defs");
        assertNotNull(defs, "the schema has $defs");
        Map<String, List<String>> loader = loaderBlocks();
        TreeSet<String> withProperties = new TreeSet<>();
        defs.fields().forEachRemaining(e -> {
            if (e.getValue().has("properties")) {
                withProperties.add(e.getKey());
            }
        });
        assertEquals(new TreeSet<>(loader.keySet()), withProperties, "the schema's blocks are the loader's");
        for (Map.Entry<String, List<String>> e : loader.entrySet()) {
            TreeSet<String> schemaKeys = new TreeSet<>();
            defs.get(e.getKey()).get("properties").fieldNames().forEachRemaining(schemaKeys::add);
            assertEquals(new TreeSet<>(e.getValue()), schemaKeys, "keys of " + e.getKey());
            assertEquals(false, defs.get(e.getKey()).get("additionalProperties").asBoolean(true),
                    e.getKey() + " refuses other keys, as the loader does");
        }
        // Every body type and law type is one of the schema's choices.
        assertEquals(BodyTypes.names().size() + 1, defs.get("body").get("oneOf").size(), "the types and rigid");
        assertEquals(RigidBodies.MOTIONS.size(), defs.get("rigid_motion").get("oneOf").size());
        assertEquals(TimeLaws.TYPES.size(), defs.get("law").get("oneOf").size());
        assertEquals(SceneConditions.TYPES.size(), defs.get("condition").get("oneOf").size());
    }
}

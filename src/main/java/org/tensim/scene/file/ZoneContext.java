package org.tensim.scene.file;

/**
 * What a {@link BodyType} applies a zone with: the zone's map (for messages), its model, its {@code material:}
 * values (checked against the type's {@link BodyType#zoneMaterialKeys()}; null when absent), the body's own keys
 * and the file's units.
 */
public record ZoneContext(SceneNode node, String model, MapReader material, MapReader bodyKeys, SceneUnits units) {
}

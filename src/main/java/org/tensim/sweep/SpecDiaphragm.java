package org.tensim.sweep;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.tensim.tuning.DiaphragmOptions;
import org.tensim.tuning.TunableScenes;

/**
 * A spec's diaphragm, as the command line's options ({@link DiaphragmOptions}): its {@code "diaphragm"} object, by the
 * options' names, and the shorter keys {@code "mesh"}, {@code "boxes"} and {@code "muscleLoad"}; checked as a whole,
 * files included, before any run.
 */
final class SpecDiaphragm {
    private SpecDiaphragm() {
    }

    /** The options of the spec's diaphragm, e.g. {@code ["--rings", "8", "--muscle-load", "pressure"]}. */
    static List<String> args(SpecReader r, JsonNode root, String scene) throws SpecReader.SpecException {
        // The diaphragm's options: the "diaphragm" object, by the command line's names, and the older keys
        // "mesh", "boxes" and "muscleLoad", which say the same as --mesh/--rings, --boxes and --muscle-load.
        List<String> args = new ArrayList<>();
        JsonNode mesh = root.get("mesh");
        if (mesh != null) {
            onlyDiaphragm(r, scene, "mesh", mesh);
            if (!mesh.isObject()) {
                throw r.fail("mesh", mesh, "an object {\"rings\": N} or {\"file\": \"x.obj\", \"units\": \"mm\"}");
            }
            r.allowOnly(mesh, "mesh.", Set.of("rings", "file", "units", "thicknessMm"));
            if (mesh.has("file") && mesh.has("rings")) {
                throw r.fail("mesh.rings", mesh.get("rings"), "either rings (generated dome) or file, not both");
            }
            if (mesh.has("file")) {
                args.addAll(List.of("--mesh", r.existing("mesh.file", r.text(mesh, "file", null)).toString()));
            }
            if (mesh.has("units")) {
                args.addAll(List.of("--units", r.text(mesh, "units", null)));
            }
            if (mesh.has("thicknessMm")) {
                args.addAll(List.of("--thickness", Double.toString(r.number(mesh, "mesh.thicknessMm", 0))));
            }
            if (mesh.has("rings")) {
                JsonNode rings = mesh.get("rings");
                if (!rings.isIntegralNumber()) {
                    throw r.fail("mesh.rings", rings, "a whole number of rings per face, 4 or more");
                }
                args.addAll(List.of("--rings", rings.asText()));
            }
        }
        if (root.has("boxes")) {
            onlyDiaphragm(r, scene, "boxes", root.get("boxes"));
            args.addAll(List.of("--boxes", r.existing("boxes", r.text(root, "boxes", null)).toString()));
        }
        if (root.has("muscleLoad")) {
            onlyDiaphragm(r, scene, "muscleLoad", root.get("muscleLoad"));
            String load = r.text(root, "muscleLoad", null);
            try {
                org.tensim.scene.diaphragm.BoundaryConditions.parse(
                        org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad.class, load);
            } catch (IllegalArgumentException e) {
                throw r.fail("muscleLoad", root.get("muscleLoad"), e.getMessage());
            }
            args.addAll(List.of("--muscle-load", load));
        }
        if (root.has("diaphragm")) {
            onlyDiaphragm(r, scene, "diaphragm", root.get("diaphragm"));
            try {
                args.addAll(DiaphragmOptions.fromJson(root.get("diaphragm"), "diaphragm", r.base));
            } catch (IllegalArgumentException e) {
                throw new SpecReader.SpecException(r.where + ": " + e.getMessage());
            }
        }
        if (scene.equals("diaphragm")) {
            try {
                DiaphragmOptions o = DiaphragmOptions.parse(args);
                org.tensim.scene.diaphragm.DiaphragmSpec d = o.spec(null, TunableScenes.defaultRings());
                for (Path f : new Path[] {d.mesh().file(), d.cage().boxes(), d.mesh().labels()}) {
                    if (f != null && !Files.isRegularFile(f)) {
                        throw new IllegalArgumentException("no such file " + f);
                    }
                }
                if (d.cage().thorax() != null && !Files.isDirectory(d.cage().thorax())) {
                    throw new IllegalArgumentException("--thorax " + d.cage().thorax() + ": no such folder");
                }
            } catch (IllegalArgumentException e) {
                throw new SpecReader.SpecException(r.where + ": the diaphragm's options (fields mesh, boxes, muscleLoad and"
                        + " diaphragm): " + e.getMessage());
            }
        }
        return args;
    }

    private static void onlyDiaphragm(SpecReader r, String scene, String field, JsonNode value)
            throws SpecReader.SpecException {
        if (!scene.equals("diaphragm")) {
            throw r.fail(field, value, "absent: scene '" + scene + "' is built in and has no diaphragm");
        }
    }
}

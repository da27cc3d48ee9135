package org.tensim.tuning;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import org.tensim.scene.diaphragm.BoundaryConditions;




/**
 * The last-used parameters of a built-in scene, restored when the window opens ({@code tensim gui}; a scene file
 * runs with its own values and restores nothing): a file that cannot be used is moved aside with a note.
 */
public final class LastUsedParameters {
    private LastUsedParameters() {
    }

    /**
     * Restores last-used parameters; returns a note for the status bar when they could not be used. With
     * {@code keepLoad} (a muscle load named on the command line) parameters
     * tuned with another muscle load are left alone, with a note: they would replace the load asked for.
     */
    public static String restore(Tuning tuning, Path file, boolean keepLoad) {
        if (!Files.exists(file)) {
            return null;
        }
        try {
            Settings s = readLastUsed(file, tuning);
            if (keepLoad && s.muscleLoad() != null && !s.muscleLoad().equals(tuning.muscleLoad())) {
                return "Last-used parameters not restored: they were tuned with muscle load "
                        + BoundaryConditions.name(s.muscleLoad()) + ", and --muscle-load "
                        + BoundaryConditions.name(tuning.muscleLoad()) + " was given (" + file + ")";
            }
            tuning.apply(s, file.toString());
            return null;
        } catch (PresetFile.PresetException | IllegalArgumentException e) {
            // Keep the file for the user to inspect, out of the way of the next save.
            Path bad = file.resolveSibling(file.getFileName() + ".bad");
            try {
                Files.move(file, bad, StandardCopyOption.REPLACE_EXISTING);
            } catch (java.io.IOException io) {
                bad = file;
            }
            return "Last-used parameters not restored (kept as " + bad + "): " + e.getMessage();
        }
    }

    /**
     * Reads last-used parameters for this window. The tendon boundary's control belongs to how the scene was opened
     * (the tendon rule, or none with a label file), which may change from one start to the next (tune the plane, save
     * the labels, reopen with them): a tendon control this window does not have is left out rather than making the
     * whole file unusable. Anything else wrong is refused as {@link PresetFile#read} refuses it.
     */
    public static Settings readLastUsed(Path file, Tuning tuning) throws PresetFile.PresetException {
        try {
            return PresetFile.read(file, tuning);
        } catch (PresetFile.PresetException first) {
            com.fasterxml.jackson.databind.node.ObjectNode root;
            try {
                com.fasterxml.jackson.databind.JsonNode n = org.tensim.io.Json.mapper().readTree(Files.readAllBytes(file));
                if (!(n instanceof com.fasterxml.jackson.databind.node.ObjectNode o)
                        || !(o.get("parameters") instanceof com.fasterxml.jackson.databind.node.ObjectNode params)) {
                    throw first;
                }
                boolean dropped = false;
                for (String key : java.util.List.of(org.tensim.scene.tunable.DiaphragmViewScene.TENDON_PLANE,
                        org.tensim.scene.tunable.DiaphragmViewScene.TENDON_SHARE)) {
                    if (params.has(key) && !tuning.keys().contains(key)) {
                        params.remove(key);
                        dropped = true;
                    }
                }
                if (!dropped) {
                    throw first;
                }
                root = o;
            } catch (java.io.IOException e) {
                throw first;
            }
            Path tmp = file.resolveSibling(file.getFileName() + ".tendon.tmp");
            try {
                Files.write(tmp, org.tensim.io.Json.mapper().writeValueAsBytes(root));
                return PresetFile.read(tmp, tuning);
            } catch (java.io.IOException e) {
                throw first;
            } catch (PresetFile.PresetException e) {
                throw new PresetFile.PresetException(e.getMessage().replace(tmp.toString(), file.toString()), e);
            } finally {
                try {
                    Files.deleteIfExists(tmp);
                } catch (java.io.IOException ignored) {
                    // a left-over temporary file is harmless
                }
            }
        }
    }

}

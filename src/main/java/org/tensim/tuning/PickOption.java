package org.tensim.tuning;

import java.nio.file.Path;
import org.tensim.experiment.diaphragm.ResolutionPick;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import picocli.CommandLine.Option;

/**
 * {@code --pick FILE}: the mechanics at the resolution a resolution study picked, the paper's 43-ring mesh carried by
 * them (a picocli mixin of {@code diaphragm} and {@code gui}). Without it, the default scene takes the pick shipped
 * with the project ({@link ResolutionPick#shipped}, a measured study with its date, command and load); a pick is used
 * only on the scene it was measured on ({@link ResolutionPick#requireMatches}). The run's summary, the window's
 * status bar and {@code --run-for}'s line name the pick, its error and its source. The rings are the coarsest within
 * {@link ResolutionPick#DEFAULT_TOLERANCE} in the study's table ({@link ResolutionPick#within}).
 */
public final class PickOption {
    @Option(names = "--pick", paramLabel = "FILE",
            description = "Run the mechanics at the rings a resolution study picked (the coarsest within 5 %% of 43"
                    + " rings in its table), read from its"
                    + " resolution-pick.json (e.g. out/diaphragm-resolution/resolution-pick.json), the 43-ring mesh"
                    + " carried by them; not with --rings or --mesh; refused when the study's scene is not this one"
                    + " (default: the pick shipped with the project, measured on the default scene).")
    Path file;

    /** The file given, or null. */
    public Path file() {
        return file;
    }

    /**
     * The pick the scene's mechanics run at: {@code --pick}'s, or the shipped one when the scene is the default
     * double dome; null for the full model ({@code --rings}, {@code --mesh}, a label file, the paper's model).
     *
     * @param note receives, when not null, why the full model runs although no resolution was asked for (the shipped
     *             pick does not match the scene)
     * @throws IllegalArgumentException with {@code --rings} or {@code --mesh} given too (a usage error)
     * @throws IllegalStateException    when the file is missing, not a pick, or measured on another scene
     */
    public ResolutionPick choose(DiaphragmOptions options, DiaphragmSpec spec,
            java.util.function.Consumer<String> note) {
        if (file != null && options.rings != null) {
            throw new IllegalArgumentException("--pick " + file + " gives the rings of the mechanics: leave out"
                    + " --rings " + options.rings + " or --pick");
        }
        if (file != null && options.mesh != null) {
            throw new IllegalArgumentException("--pick " + file + " is a resolution of the generated double dome, not"
                    + " of --mesh " + options.mesh + ": leave out one of them");
        }
        if (file != null) {
            ResolutionPick p = ResolutionPick.read(file).within(ResolutionPick.DEFAULT_TOLERANCE);
            p.requireMatches(spec);
            return p;
        }
        if (options.rings != null || options.mesh != null || options.paperModel()) {
            return null; // a resolution or a model was asked for: it runs as asked, unmapped
        }
        ResolutionPick p = ResolutionPick.shipped().within(ResolutionPick.DEFAULT_TOLERANCE);
        try {
            p.requireMatches(spec);
        } catch (IllegalStateException e) {
            if (note != null) {
                note.accept("full model, unmapped: " + e.getMessage().replaceFirst(";.*", ""));
            }
            return null;
        }
        return p.rings() >= ResolutionPick.REFERENCE_RINGS ? null : p;
    }
}

package org.tensim.tuning;

import java.nio.file.Path;
import org.tensim.experiment.diaphragm.ResolutionPick;
import picocli.CommandLine.Option;

/**
 * {@code --pick FILE}: the generated double dome at the resolution a resolution study picked, read from the
 * {@code resolution-pick.json} the study wrote (a picocli mixin of {@code diaphragm} and {@code gui}). Nothing reads a
 * pick unless this option names it; the run's summary and the GUI's title then name the file.
 */
public final class PickOption {
    @Option(names = "--pick", paramLabel = "FILE",
            description = "Open the generated double dome at the rings a resolution study picked, read from its"
                    + " resolution-pick.json (e.g. out/diaphragm-resolution/resolution-pick.json); not with --rings"
                    + " or --mesh; the summary and the window's title name the file (default: no pick).")
    Path file;

    /** The file given, or null. */
    public Path file() {
        return file;
    }

    /**
     * Reads the pick and gives its rings to the options, as {@code --rings} would.
     *
     * @return the pick, or null when {@code --pick} is left out (the options are then unchanged)
     * @throws IllegalArgumentException with {@code --rings} or {@code --mesh} given too (a usage error)
     * @throws IllegalStateException    when the file is missing or not a pick ({@link ResolutionPick#read})
     */
    public ResolutionPick apply(DiaphragmOptions options) {
        if (file == null) {
            return null;
        }
        if (options.rings != null) {
            throw new IllegalArgumentException("--pick " + file + " gives the rings of the generated double dome:"
                    + " leave out --rings " + options.rings + " or --pick");
        }
        if (options.mesh != null) {
            throw new IllegalArgumentException("--pick " + file + " is a resolution of the generated double dome, not"
                    + " of --mesh " + options.mesh + ": leave out one of them");
        }
        ResolutionPick p = ResolutionPick.read(file);
        options.rings = p.rings();
        return p;
    }
}

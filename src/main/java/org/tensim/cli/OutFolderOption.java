package org.tensim.cli;

import java.nio.file.Path;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;

/**
 * {@code --out DIR}, the output folder of a run, and {@code --overwrite} (a picocli mixin). Each command gives its
 * default to the constructor, a folder no other command uses by default; a default ending in {@value #SPEC_NAME}
 * stands for the name of the command's spec file. A folder that holds another command's results or files no tensim
 * run wrote is refused unless {@code --overwrite} is given ({@link org.tensim.io.FolderClaim}).
 */
public final class OutFolderOption {
    /** The last part of a default folder that the spec file's name replaces. */
    public static final String SPEC_NAME = "SPEC-NAME";

    @Option(names = "--out", paramLabel = "DIR", description = "Output folder (default: ${DEFAULT-VALUE}).")
    Path out;

    @Option(names = "--overwrite", description = "Use --out even when it holds another command's results or files"
            + " that no tensim run wrote (their outputs of the same names are replaced); without it such a folder is"
            + " refused and left as it is.")
    boolean overwrite;

    /** The option with this default folder. */
    public OutFolderOption(Path defaultFolder) {
        out = defaultFolder;
    }

    /** Whether {@code --overwrite} was given. */
    public boolean overwrite() {
        return overwrite;
    }

    /** The folder given, or the default; refused (a usage error) if empty or an existing file. */
    public Path folder(CommandSpec spec) {
        return OptionChecks.outFolder(spec, out);
    }

    /**
     * The folder given, or the default with its last part {@value #SPEC_NAME} replaced by the spec file's name
     * without {@code .json}, {@code .yaml} or {@code .yml} (out/sweep/NAME for a spec NAME.json); refused as
     * {@link #folder(CommandSpec)}.
     */
    public Path folder(CommandSpec spec, Path specFile) {
        var parsed = spec.commandLine() == null ? null : spec.commandLine().getParseResult();
        boolean given = parsed != null && parsed.hasMatchedOption("--out");
        if (!given && out != null && out.getFileName() != null && out.getFileName().toString().equals(SPEC_NAME)) {
            String n = specFile.getFileName().toString();
            out = out.resolveSibling(n.replaceFirst("\\.(json|yaml|yml)$", ""));
        }
        return folder(spec);
    }
}

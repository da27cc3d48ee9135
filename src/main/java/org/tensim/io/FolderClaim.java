package org.tensim.io;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.stream.Stream;

/**
 * Whose results an output folder holds, so that a run never replaces another command's or another program's
 * files. A folder belongs to a command when
 * <ul>
 * <li>its {@value RunFolder#SUMMARY} names that command (whatever the status: a failed or interrupted run of the
 * same command is its own), or</li>
 * <li>without a summary (a run killed or still running), the first line of its manifest
 * {@value RunFolder#MANIFEST} names that command ({@value #HEADER} then the command), or</li>
 * <li>with neither, every entry in it is one of the command's own output names (or a left-over temporary file),
 * an empty folder included.</li>
 * </ul>
 * Anything else (another command's summary, a manifest of another or an unknown command, files that no tensim run
 * wrote) is refused unless the user asks to {@code --overwrite}.
 */
public final class FolderClaim {
    /** The manifest's first line starts with this, followed by the command that wrote it. */
    public static final String HEADER = "#command ";

    private FolderClaim() {
    }

    /**
     * Refuses {@code dir} for a run of {@code command} when the folder holds what another command or no tensim run
     * wrote; nothing is read beyond the summary, the manifest and the folder's listing, and nothing is changed.
     * A folder that does not exist yet, or {@code overwrite}, passes.
     *
     * @param ownNames the names (relative to dir) the command writes
     * @throws IllegalArgumentException naming the folder, what it holds and the two ways to proceed
     */
    public static void check(Path dir, String command, Collection<String> ownNames, boolean overwrite)
            throws IOException {
        if (overwrite || !Files.isDirectory(dir)) {
            return;
        }
        String held = foreign(dir, command, ownNames);
        if (held != null) {
            throw new IllegalArgumentException("--out " + dir + " holds " + held + ", and this run of `tensim "
                    + command + "` would replace them; nothing was changed. Give another folder with --out DIR, or"
                    + " pass --overwrite to use this one anyway");
        }
    }

    /** What in {@code dir} is not {@code command}'s own (a phrase for the message), or null when the folder is its. */
    static String foreign(Path dir, String command, Collection<String> ownNames) throws IOException {
        Path summary = dir.resolve(RunFolder.SUMMARY);
        if (Files.exists(summary, LinkOption.NOFOLLOW_LINKS)) {
            String by = summaryCommand(summary);
            if (command.equals(by)) {
                return null;
            }
            return by == null ? "a " + RunFolder.SUMMARY + " that names no tensim command"
                    : "the results of `tensim " + by + "` (its " + RunFolder.SUMMARY + ")";
        }
        Path manifest = dir.resolve(RunFolder.MANIFEST);
        if (Files.exists(manifest, LinkOption.NOFOLLOW_LINKS)) {
            String by = manifestCommand(manifest);
            if (command.equals(by)) {
                return null;
            }
            return "the outputs of an unfinished run of " + (by == null ? "an unknown command" : "`tensim " + by + "`")
                    + " (listed in " + RunFolder.MANIFEST + ", no " + RunFolder.SUMMARY + ")";
        }
        List<String> strangers = new ArrayList<>();
        try (Stream<Path> s = Files.list(dir)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                String n = p.getFileName().toString();
                if (!ownNames.contains(n) && !(n.startsWith(".") && n.endsWith(".tmp"))) {
                    strangers.add(n);
                }
            }
        }
        if (strangers.isEmpty()) {
            return null;
        }
        strangers.sort(null);
        String names = String.join(", ", strangers.subList(0, Math.min(3, strangers.size())))
                + (strangers.size() > 3 ? " and " + (strangers.size() - 3) + " more" : "");
        return "files that no tensim run wrote (" + names + ")";
    }

    /** The {@code "command"} of a summary, or null when it has none or cannot be read as one. */
    static String summaryCommand(Path summary) {
        try {
            Object c = Json.readMap(summary).get("command");
            return c instanceof String s ? s : null;
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }

    /** The command named on a manifest's first line, or null (a manifest written before the header existed). */
    static String manifestCommand(Path manifest) throws IOException {
        try (Stream<String> lines = Files.lines(manifest, StandardCharsets.UTF_8)) {
            String first = lines.findFirst().orElse("");
            return first.startsWith(HEADER) ? first.substring(HEADER.length()).trim() : null;
        } catch (java.io.UncheckedIOException e) {
            return null; // not text: not a manifest this program wrote
        }
    }
}

package org.tensim.io;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Where a figure came from, for every summary: the time (UTC), the project's commit, the cores and the
 * load average, so that a number quoted in the docs can be traced to the run that measured it.
 */
public final class Provenance {
    private Provenance() {
    }

    /** {@code finished_utc}, {@code commit}, {@code cores}, {@code load_average_1min}. */
    public static Map<String, Object> fields() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("finished_utc", Instant.now().truncatedTo(ChronoUnit.SECONDS).toString());
        m.put("commit", commit(ProjectFolder.home()));
        m.put("cores", Runtime.getRuntime().availableProcessors());
        double load = ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage();
        m.put("load_average_1min", load < 0 ? null : Math.round(load * 100) / 100.0);
        return m;
    }

    /**
     * The commit checked out in {@code project}, read from {@code .git} without running git; edits not yet
     * committed are not detected. "unknown" outside a clone.
     */
    static String commit(Path project) {
        try {
            Path git = project.resolve(".git");
            if (Files.isRegularFile(git)) { // a worktree: "gitdir: PATH"
                String line = Files.readString(git).trim();
                if (line.startsWith("gitdir:")) {
                    git = project.resolve(line.substring(7).trim());
                }
            }
            String head = Files.readString(git.resolve("HEAD")).trim();
            if (!head.startsWith("ref:")) {
                return head;
            }
            String ref = head.substring(4).trim();
            Path common = Files.isRegularFile(git.resolve("commondir"))
                    ? git.resolve(Files.readString(git.resolve("commondir")).trim()) : git;
            for (Path dir : new Path[] {git, common}) {
                Path loose = dir.resolve(ref);
                if (Files.isRegularFile(loose)) {
                    return Files.readString(loose).trim();
                }
                Path packed = dir.resolve("packed-refs");
                if (Files.isRegularFile(packed)) {
                    for (String l : Files.readAllLines(packed)) {
                        if (l.endsWith(" " + ref)) {
                            return l.substring(0, l.indexOf(' '));
                        }
                    }
                }
            }
            return "unknown";
        } catch (IOException | RuntimeException e) {
            return "unknown";
        }
    }
}

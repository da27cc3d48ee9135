package org.tensim.io;

import java.io.IOException;
import java.io.InputStream;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Properties;

/**
 * Where a figure came from, for every summary: the time (UTC), the commit of the code that ran, the cores
 * and the load average, so that a number quoted in the docs can be traced to the run that measured it.
 *
 * <p>The commit is the one the build was made from ({@code build-stamp.properties}, written by the build's
 * {@code buildStamp} task), so that an installed copy run from a folder that has since moved on still names
 * its own code; {@code commit_uncommitted_changes} says whether tracked files differed from that commit when
 * it was built. Without a stamp (classes compiled by other means) it is the commit checked out in the
 * project folder, read from its {@code .git}.
 */
public final class Provenance {
    private Provenance() {
    }

    /** The build's stamp, on the class path beside this class. */
    static final String STAMP = "build-stamp.properties";

    /**
     * {@code finished_utc}, {@code commit}, {@code commit_uncommitted_changes} (when the build could tell),
     * {@code cores}, {@code load_average_1min}.
     */
    public static Map<String, Object> fields() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("finished_utc", Instant.now().truncatedTo(ChronoUnit.SECONDS).toString());
        Properties stamp = stamp(Provenance.class.getResourceAsStream(STAMP));
        String built = stamp.getProperty("commit", "unknown");
        m.put("commit", "unknown".equals(built) ? commit(ProjectFolder.home()) : built);
        String dirty = stamp.getProperty("uncommitted_changes", "unknown");
        if (!"unknown".equals(built) && !"unknown".equals(dirty)) {
            m.put("commit_uncommitted_changes", Boolean.parseBoolean(dirty));
        }
        m.put("cores", Runtime.getRuntime().availableProcessors());
        double load = ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage();
        m.put("load_average_1min", load < 0 ? null : Math.round(load * 100) / 100.0);
        return m;
    }

    /**
     * The code that runs, as a key for results kept between runs (a study's reference samples): the build's commit,
     * with {@code +changes} when tracked files differed from it at build time; "unknown" when it cannot be told.
     */
    public static String codeVersion() {
        Map<String, Object> f = fields();
        return f.get("commit") + (Boolean.TRUE.equals(f.get("commit_uncommitted_changes")) ? "+changes" : "");
    }

    /** The stamp's properties; empty when there is none or it cannot be read. */
    static Properties stamp(InputStream in) {
        Properties p = new Properties();
        if (in == null) {
            return p;
        }
        try (InputStream s = in) {
            p.load(s);
        } catch (IOException | IllegalArgumentException e) {
            p.clear();
        }
        return p;
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

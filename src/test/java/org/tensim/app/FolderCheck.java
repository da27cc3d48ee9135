package org.tensim.app;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;
import org.tensim.io.Json;
import org.tensim.io.RunFolder;
import org.tensim.io.RunStatus;

/**
 * What a run's folder must be after the run ended in any way: either a summary
 * whose status agrees with the exit code, or (killed with SIGKILL) no summary; every
 * CSV ending on a whole row with as many cells as its header; no file that the run
 * did not list (nothing stale). Returns the problems found, empty when the folder is
 * sound.
 */
final class FolderCheck {
    private FolderCheck() {
    }

    static List<String> problems(Path dir, int exitCode, String signal) throws IOException {
        List<String> p = new ArrayList<>();
        Path summary = dir.resolve(RunFolder.SUMMARY);
        Set<String> listed = new HashSet<>();
        if (Files.exists(summary)) {
            Map<String, Object> s = Json.readMap(summary);
            String status = String.valueOf(s.get("status"));
            RunStatus st;
            try {
                st = RunStatus.valueOf(status.toUpperCase(java.util.Locale.ROOT));
            } catch (IllegalArgumentException e) {
                p.add("unknown status '" + status + "'");
                return p;
            }
            if (st.exitCode() != exitCode) {
                p.add("status " + status + " but exit code " + exitCode);
            }
            if (("INT".equals(signal) || "TERM".equals(signal)) && st == RunStatus.OK && exitCode != 0) {
                p.add("interrupted run says ok");
            }
            @SuppressWarnings("unchecked")
            List<String> files = (List<String>) s.get("files");
            if (files == null) {
                p.add("the summary lists no files (not written by a run folder)");
            } else {
                listed.addAll(files);
            }
        } else if (!"KILL".equals(signal) && exitCode != 137) {
            p.add("no summary, but the run was not killed with SIGKILL (exit " + exitCode + ")");
        }
        Path manifest = dir.resolve(RunFolder.MANIFEST);
        if (Files.exists(manifest)) {
            listed.addAll(Files.readAllLines(manifest));
        }
        try (Stream<Path> s = Files.list(dir)) {
            for (Path f : (Iterable<Path>) s::iterator) {
                String name = f.getFileName().toString();
                boolean tmp = name.startsWith(".") && name.endsWith(".tmp");
                if (!listed.contains(name) && !name.equals(RunFolder.SUMMARY) && !name.equals(RunFolder.MANIFEST)
                        && !(tmp && "KILL".equals(signal))) {
                    p.add("unlisted (stale or stray) file " + name);
                }
                if (name.endsWith(".csv") && Files.isRegularFile(f)) {
                    p.addAll(csvProblems(f));
                }
            }
        }
        return p;
    }

    /** A CSV ends on a whole row: a final line break, and every row as many cells as the header. */
    static List<String> csvProblems(Path csv) throws IOException {
        List<String> p = new ArrayList<>();
        String text = Files.readString(csv);
        if (text.isEmpty()) {
            return p; // created, nothing written yet (killed at once)
        }
        if (!text.endsWith("\n")) {
            p.add(csv.getFileName() + " ends mid-row: '" + text.substring(Math.max(0, text.length() - 40)) + "'");
        }
        String[] lines = text.split("\n");
        int cells = lines[0].split(",", -1).length;
        for (int i = 1; i < lines.length; i++) {
            if (lines[i].split(",", -1).length != cells) {
                p.add(csv.getFileName() + " row " + i + " has the wrong number of cells: " + lines[i]);
            }
        }
        return p;
    }
}

package org.tensim.io;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;

/**
 * One run's output folder ({@code --out}). Every command writes through one, so that
 * the folder holds this run's outputs only and says how the run ended:
 * <ol>
 * <li>{@link #open} refuses a folder that holds another command's results or files no tensim run wrote
 * ({@link FolderClaim}), unless asked to overwrite; nothing is removed then.</li>
 * <li>In a folder it may use, {@link #open} removes the previous run's {@code summary.json} first, then every
 * file and folder the previous run listed in its manifest ({@value #MANIFEST}, one
 * relative path a line after a first line naming the command, written as files are
 * created, so a killed run's list is there too), the names the command declares as its own (for folders written before
 * manifests existed), and left-over temporary files. Nothing else in the folder is
 * touched.</li>
 * <li>{@link #file} and {@link #csv} name each output and add it to the manifest before
 * it is created.</li>
 * <li>{@link #finish} writes {@code summary.json}: {@code "status"} (ok, diverged,
 * failed, interrupted), {@code "command"}, the command's own fields and {@code "files"}
 * (the manifest). {@link #run} writes {@code "failed"} with the error when the command
 * throws; {@link RunSignals} writes {@code "interrupted"} on SIGINT/SIGTERM. A folder
 * without a summary is a run that was killed (SIGKILL, power cut) or still runs.</li>
 * </ol>
 * docs/outputs.md lists what each command writes.
 */
public final class RunFolder {
    /** The summary file, written last (atomically). */
    public static final String SUMMARY = "summary.json";
    /** The manifest: the outputs of the run that wrote it, one relative path a line. */
    public static final String MANIFEST = ".tensim-files";

    /** A command's work inside its run folder; it ends by calling {@link RunFolder#finish}. */
    @FunctionalInterface
    public interface Body {
        void run(RunFolder run) throws Exception;
    }

    private static final java.util.concurrent.atomic.AtomicLong OPENED = new java.util.concurrent.atomic.AtomicLong();
    private final Path dir;
    private final String command;
    private final Set<String> files = new LinkedHashSet<>();
    private final List<CsvWriter> csvs = new ArrayList<>();
    private final long startNanos = System.nanoTime();
    private RunStatus status;
    private Map<String, Object> summary;

    private RunFolder(Path dir, String command) {
        this.dir = dir;
        this.command = command;
    }

    /**
     * Opens {@code dir} for a run of {@code command}, runs {@code body} and returns the
     * exit code of the status it finished with. An exception from the body is written
     * as {@code "status": "failed"} with its message, then rethrown.
     *
     * @param ownNames names (relative to dir) this command writes, removed before the run
     */
    public static int run(Path dir, String command, List<String> ownNames, Body body) throws Exception {
        return run(dir, command, ownNames, false, body);
    }

    /**
     * As {@link #run(Path, String, List, Body)}; with {@code overwrite} a folder holding another command's results
     * or files no tensim run wrote is used all the same ({@code --overwrite}).
     */
    public static int run(Path dir, String command, List<String> ownNames, boolean overwrite, Body body)
            throws Exception {
        RunFolder run = open(dir, command, ownNames, overwrite);
        try {
            body.run(run);
        } catch (Exception | Error e) {
            Map<String, Object> s = new LinkedHashMap<>();
            s.put("error", e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage());
            run.finish(RunSignals.stopRequested() ? RunStatus.INTERRUPTED : RunStatus.FAILED, s);
            throw e;
        } finally {
            RunSignals.deactivate(run);
        }
        if (run.status == null) {
            run.finish(RunStatus.FAILED, Map.of("error", "the command ended without a status"));
        }
        return run.status.exitCode();
    }

    /**
     * Checks and prepares the folder (see the class comment); the run is then the active one.
     *
     * @throws IllegalArgumentException when the folder holds another command's results or files no tensim run
     *                                  wrote ({@link FolderClaim#check}); nothing is changed then
     */
    public static RunFolder open(Path dir, String command, List<String> ownNames) throws IOException {
        return open(dir, command, ownNames, false);
    }

    /** As {@link #open(Path, String, List)}; with {@code overwrite} any folder is used ({@code --overwrite}). */
    public static RunFolder open(Path dir, String command, List<String> ownNames, boolean overwrite)
            throws IOException {
        if (dir == null || dir.toString().isBlank()) {
            throw new IllegalArgumentException("--out must name a folder, got an empty path");
        }
        FolderClaim.check(dir, command, ownNames, overwrite);
        OutputFiles.createFolder(dir);
        if (!Files.isWritable(dir)) {
            throw new IOException("cannot write into " + dir + ": permission denied");
        }
        OPENED.incrementAndGet();
        RunFolder run = new RunFolder(dir, command);
        run.clearPrevious(ownNames);
        RunSignals.activate(run);
        return run;
    }

    /** Run folders opened so far in this JVM (tells a refusal of options from a failed run). */
    public static long opened() {
        return OPENED.get();
    }

    private void clearPrevious(List<String> ownNames) throws IOException {
        remove(SUMMARY); // first: a run stopped during the clean-up must not leave the old status
        Set<String> old = new LinkedHashSet<>();
        Path manifest = dir.resolve(MANIFEST);
        if (Files.isRegularFile(manifest, LinkOption.NOFOLLOW_LINKS)) {
            old.addAll(Files.readAllLines(manifest, StandardCharsets.UTF_8));
        }
        old.addAll(ownNames);
        for (String name : old) {
            if (!name.isBlank() && !name.startsWith(FolderClaim.HEADER)) {
                remove(name);
            }
        }
        try (Stream<Path> s = Files.list(dir)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                String n = p.getFileName().toString();
                if (n.startsWith(".") && n.endsWith(".tmp")) {
                    Files.deleteIfExists(p); // a temporary file of a killed run (OutputFiles.writeAtomically)
                }
            }
        }
        remove(MANIFEST);
        // Written at once, so that even a run killed before its first output is known as this command's.
        Files.writeString(dir.resolve(MANIFEST), FolderClaim.HEADER + command + "\n", StandardCharsets.UTF_8,
                java.nio.file.StandardOpenOption.CREATE_NEW, LinkOption.NOFOLLOW_LINKS);
    }

    /** Deletes dir/name (a folder with what is in it); links are removed, never followed. */
    private void remove(String name) throws IOException {
        Path p = inside(name);
        if (!Files.exists(p, LinkOption.NOFOLLOW_LINKS)) {
            return;
        }
        try {
            if (Files.isDirectory(p, LinkOption.NOFOLLOW_LINKS)) {
                Files.walkFileTree(p, new SimpleFileVisitor<>() {
                    @Override
                    public FileVisitResult visitFile(Path f, BasicFileAttributes a) throws IOException {
                        Files.delete(f);
                        return FileVisitResult.CONTINUE;
                    }

                    @Override
                    public FileVisitResult postVisitDirectory(Path d, IOException e) throws IOException {
                        Files.delete(d);
                        return FileVisitResult.CONTINUE;
                    }
                });
            } else {
                Files.delete(p);
            }
        } catch (IOException e) {
            throw OutputFiles.describe("remove the previous run's", p, e);
        }
    }

    /** dir/name, refusing names that leave the folder. */
    private Path inside(String name) {
        Path p = dir.resolve(name).normalize();
        if (!p.startsWith(dir.normalize()) || p.equals(dir.normalize())) {
            throw new IllegalArgumentException("output name '" + name + "' is outside the run folder " + dir);
        }
        return p;
    }

    public Path dir() {
        return dir;
    }

    public String command() {
        return command;
    }

    /**
     * The path of output {@code name} (relative; a folder such as "vtk" counts as one
     * output), added to the manifest before anything is written there.
     */
    public synchronized Path file(String name) throws IOException {
        Path p = inside(name);
        if (files.add(name)) {
            Files.writeString(dir.resolve(MANIFEST), name + "\n", StandardCharsets.UTF_8,
                    java.nio.file.StandardOpenOption.CREATE, java.nio.file.StandardOpenOption.APPEND,
                    java.nio.file.LinkOption.NOFOLLOW_LINKS);
        }
        return p;
    }

    /** A CSV output {@code name}, closed (whole rows) by {@link RunSignals} on SIGINT/SIGTERM. */
    public CsvWriter csv(String name, List<String> header, int flushEvery) throws IOException {
        CsvWriter w = new CsvWriter(file(name), header, flushEvery);
        synchronized (this) {
            csvs.add(w);
        }
        return w;
    }

    /** The outputs named so far, in order. */
    public synchronized List<String> files() {
        return List.copyOf(files);
    }

    /** The status written, or null while the run goes on. */
    public synchronized RunStatus status() {
        return status;
    }

    /** The summary written by {@link #finish} (status first), or null before. */
    public synchronized Map<String, Object> summary() {
        return summary;
    }

    /**
     * Writes {@code summary.json}: status, command, the given fields, wall time and the
     * files. Only the first call writes (a signal's "interrupted" is not overwritten by
     * the run's own end, nor the reverse). Returns the summary as written.
     */
    public synchronized Map<String, Object> finish(RunStatus s, Map<String, Object> fields) throws IOException {
        if (status != null) {
            return summary;
        }
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("status", s.word());
        m.put("command", command);
        m.putAll(fields);
        m.putIfAbsent("run_wall_s", Math.round((System.nanoTime() - startNanos) / 1e6) / 1e3);
        Provenance.fields().forEach(m::putIfAbsent);
        m.put("files", new ArrayList<>(files));
        IOException closing = null;
        for (CsvWriter w : csvs) {
            try {
                w.close();
            } catch (IOException e) {
                closing = closing == null ? e : closing;
            }
        }
        status = s;
        summary = m;
        Json.write(dir.resolve(SUMMARY), m);
        RunSignals.deactivate(this);
        if (closing != null) {
            throw closing;
        }
        return m;
    }

    /** Called by {@link RunSignals}: marks an unfinished run interrupted; returns the status the run has. */
    synchronized RunStatus interruptIfUnfinished() {
        if (status == null) {
            try {
                finish(RunStatus.INTERRUPTED, Map.of("error", "interrupted by SIGINT or SIGTERM"));
            } catch (IOException | RuntimeException e) {
                System.err.println("tensim: could not write the interrupted status to " + dir + ": " + e.getMessage());
                status = RunStatus.INTERRUPTED;
            }
        }
        return status;
    }
}

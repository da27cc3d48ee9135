package org.tensim.io;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.channels.Channels;
import java.nio.channels.FileChannel;
import java.nio.file.AccessDeniedException;
import java.nio.file.DirectoryNotEmptyException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Locale;
import java.util.Set;

/**
 * How every output file is created: never through a symbolic link already at its
 * path (the link is refused, its target never written), with mode 0644 (rw-r--r--,
 * like any other tool's output, also for files first written to a temporary file
 * and renamed into place), and with file-system errors turned into messages that
 * say what failed.
 */
public final class OutputFiles {
    /** rw-r--r--. */
    public static final Set<PosixFilePermission> MODE_0644 = PosixFilePermissions.fromString("rw-r--r--");

    /** Temporary files being written now: removed by {@link RunSignals} when a signal ends the JVM. */
    private static final Set<Path> IN_FLIGHT = java.util.concurrent.ConcurrentHashMap.newKeySet();

    private OutputFiles() {
    }

    /** Deletes the temporary files of writes still in progress (at a signal; SIGKILL leaves them). */
    static void deleteInFlight() {
        for (Path p : IN_FLIGHT) {
            try {
                Files.deleteIfExists(p);
            } catch (IOException e) {
                // the JVM is ending: nothing more to do about it
            }
        }
    }

    /** Writes to an output stream; the stream is closed by the caller of the callback. */
    @FunctionalInterface
    public interface Content {
        void write(OutputStream out) throws IOException;
    }

    /**
     * Creates {@code file} (replacing a regular file of that name), mode 0644, and
     * returns its channel. Refuses a symbolic link or a folder at that path.
     */
    public static FileChannel create(Path file) throws IOException {
        Path abs = file.toAbsolutePath();
        createFolder(abs.getParent());
        refuseLink(abs);
        if (Files.isDirectory(abs, LinkOption.NOFOLLOW_LINKS)) {
            throw new IOException("cannot write " + file + ": a folder of that name is in the way");
        }
        Files.deleteIfExists(abs);
        try {
            // CREATE_NEW with NOFOLLOW_LINKS: a link made between the check and here is not followed either.
            FileChannel ch = FileChannel.open(abs, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE,
                    LinkOption.NOFOLLOW_LINKS);
            setMode(abs);
            return ch;
        } catch (IOException e) {
            throw describe("create", file, e);
        }
    }

    /**
     * Writes {@code file} whole: into a temporary file beside it, mode 0644, then
     * renamed over the target (a rename replaces a link at the target, never its
     * target), so that the file is either the old one or the complete new one.
     */
    public static void writeAtomically(Path file, Content content) throws IOException {
        Path abs = file.toAbsolutePath();
        createFolder(abs.getParent());
        refuseLink(abs);
        RunSignals.install();
        Path tmp;
        try {
            tmp = Files.createTempFile(abs.getParent(), "." + abs.getFileName(), ".tmp");
        } catch (IOException e) {
            throw describe("create a temporary file in", abs.getParent(), e);
        }
        IN_FLIGHT.add(tmp);
        try {
            try (OutputStream out = Channels.newOutputStream(FileChannel.open(tmp, StandardOpenOption.WRITE,
                    StandardOpenOption.TRUNCATE_EXISTING))) {
                content.write(out);
            }
            setMode(tmp);
            Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } catch (IOException e) {
            throw describe("write", file, e);
        } finally {
            Files.deleteIfExists(tmp);
            IN_FLIGHT.remove(tmp);
        }
    }

    /** Creates a folder and its parents, with a message saying what is in the way when that fails. */
    public static void createFolder(Path dir) throws IOException {
        if (dir == null) {
            return;
        }
        for (Path p = dir.toAbsolutePath(); p != null; p = p.getParent()) {
            if (Files.exists(p) && !Files.isDirectory(p)) {
                throw new IOException("cannot use " + dir + " as a folder: " + (p.equals(dir.toAbsolutePath())
                        ? "it" : p.toString()) + " exists and is a file");
            }
        }
        try {
            Files.createDirectories(dir);
        } catch (IOException e) {
            throw describe("create the folder", dir, e);
        }
    }

    private static void refuseLink(Path abs) throws IOException {
        if (Files.isSymbolicLink(abs)) {
            throw new IOException("refusing to write " + abs + ": it is a symbolic link (to "
                    + Files.readSymbolicLink(abs) + "); remove it or choose another --out");
        }
    }

    private static void setMode(Path p) throws IOException {
        try {
            Files.setPosixFilePermissions(p, MODE_0644);
        } catch (UnsupportedOperationException e) {
            // not a POSIX file system (Windows): its default permissions stand
        }
    }

    /**
     * An exception whose message says what could not be done to which path and why:
     * "cannot create out/x/cube.csv: permission denied".
     */
    public static IOException describe(String action, Path path, IOException e) {
        if (e.getMessage() != null && e.getMessage().startsWith("cannot ")) {
            return e; // already described
        }
        IOException d = new IOException("cannot " + action + " " + path + ": " + reason(e), e);
        return d;
    }

    /** Why a file-system operation failed, in words (permission denied, disk full, ...). */
    public static String reason(IOException e) {
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof NoSuchFileException) {
            return "no such file or folder (" + e.getMessage() + ")";
        }
        if (e instanceof FileAlreadyExistsException) {
            return "something of that name already exists (" + e.getMessage() + ")";
        }
        if (e instanceof NotDirectoryException) {
            return "a part of the path is a file, not a folder (" + e.getMessage() + ")";
        }
        if (e instanceof DirectoryNotEmptyException) {
            return "the folder is not empty (" + e.getMessage() + ")";
        }
        String m = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
        if (e instanceof FileSystemException fse && fse.getReason() != null) {
            m = fse.getReason();
        }
        String lower = m.toLowerCase(Locale.ROOT);
        if (lower.contains("no space left")) {
            return "the disk is full (no space left on device)";
        }
        if (lower.contains("read-only file system")) {
            return "the file system is read-only";
        }
        if (lower.contains("too many levels of symbolic links")) {
            return "it is a symbolic link (not followed)";
        }
        if (lower.contains("not a directory")) {
            return "a part of the path is a file, not a folder";
        }
        return m;
    }
}

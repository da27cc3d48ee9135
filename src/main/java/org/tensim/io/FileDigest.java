package org.tensim.io;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.stream.Stream;

/**
 * A SHA-256 digest of files' contents, for naming what was computed from them (a study's kept reference): a file
 * edited in place gives another digest, whatever its name and size.
 */
public final class FileDigest {
    private FileDigest() {
    }

    /**
     * The digest of the given files and of every regular file below the given folders (in name order), each file's
     * path relative to its root and its bytes; a path that does not exist counts as its name alone.
     *
     * @return 64 hexadecimal digits
     */
    public static String of(List<Path> roots) throws IOException {
        MessageDigest md;
        try {
            md = MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is missing from this JVM", e);
        }
        byte[] buffer = new byte[1 << 16];
        for (Path root : roots) {
            List<Path> files = new ArrayList<>();
            if (Files.isDirectory(root)) {
                try (Stream<Path> walk = Files.walk(root)) {
                    walk.filter(Files::isRegularFile).sorted().forEach(files::add);
                }
            } else {
                files.add(root);
            }
            for (Path f : files) {
                md.update((root.relativize(f).toString() + "\n" + root.getFileName() + "\n").getBytes(
                        java.nio.charset.StandardCharsets.UTF_8));
                if (!Files.isRegularFile(f)) {
                    continue;
                }
                try (InputStream in = Files.newInputStream(f)) {
                    int n;
                    while ((n = in.read(buffer)) > 0) {
                        md.update(buffer, 0, n);
                    }
                }
            }
        }
        return HexFormat.of().formatHex(md.digest());
    }
}

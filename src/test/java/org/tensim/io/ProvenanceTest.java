package org.tensim.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.Properties;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Which commit a summary names: the build's stamp first, else the folder's checkout. */
class ProvenanceTest {
    private static final String A = "0123456789abcdef0123456789abcdef01234567";
    private static final String B = "fedcba9876543210fedcba9876543210fedcba98";

    @Test
    void theBuildsStampNamesTheCommitThatRuns() {
        Properties stamp = Provenance.stamp(Provenance.class.getResourceAsStream(Provenance.STAMP));
        String built = stamp.getProperty("commit");
        assertTrue(built != null && (built.equals("unknown") || built.matches("[0-9a-f]{40}")),
                "the build writes build-stamp.properties with a 40-digit commit or 'unknown', got " + built);
        Map<String, Object> f = Provenance.fields();
        if (!built.equals("unknown")) {
            assertEquals(built, f.get("commit"), "the summary names the build's commit, not the folder's");
            assertTrue(f.get("commit_uncommitted_changes") instanceof Boolean, f.toString());
        }
    }

    @Test
    void theCodesVersionIsTheCommitAndWhetherItWasChanged() {
        Map<String, Object> f = Provenance.fields();
        String v = Provenance.codeVersion();
        assertEquals(f.get("commit") + (Boolean.TRUE.equals(f.get("commit_uncommitted_changes")) ? "+changes" : ""), v,
                "a kept result is keyed by the code that made it");
        assertEquals(v, Provenance.codeVersion(), "the same within a run");
    }

    @Test
    void aStampIsReadAndABrokenOneIsIgnored() {
        Properties p = Provenance.stamp(new ByteArrayInputStream(
                ("commit=" + A + "\nuncommitted_changes=true\n").getBytes(StandardCharsets.ISO_8859_1)));
        assertEquals(A, p.getProperty("commit"));
        assertEquals("true", p.getProperty("uncommitted_changes"));
        assertTrue(Provenance.stamp(null).isEmpty());
        // A malformed \\u escape makes Properties.load throw: no half-read stamp.
        assertTrue(Provenance.stamp(new ByteArrayInputStream("commit=\\u12".getBytes(StandardCharsets.ISO_8859_1)))
                .isEmpty());
    }

    @Test
    void theFoldersCheckoutIsReadFromItsGitDirectory(@TempDir Path dir) throws IOException {
        Path git = Files.createDirectories(dir.resolve("clone/.git/refs/heads"));
        Files.writeString(git.getParent().getParent().resolve("HEAD"), "ref: refs/heads/main\n");
        Files.writeString(git.resolve("main"), A + "\n");
        assertEquals(A, Provenance.commit(dir.resolve("clone")), "a loose ref");

        Files.delete(git.resolve("main"));
        Files.writeString(dir.resolve("clone/.git/packed-refs"), "# pack-refs with: peeled\n" + B + " refs/heads/main\n");
        assertEquals(B, Provenance.commit(dir.resolve("clone")), "a packed ref");

        Files.writeString(dir.resolve("clone/.git/HEAD"), A + "\n");
        assertEquals(A, Provenance.commit(dir.resolve("clone")), "a detached head");

        assertEquals("unknown", Provenance.commit(dir.resolve("nowhere")));
        assertFalse(Provenance.commit(dir.resolve("clone")).isEmpty());
    }
}

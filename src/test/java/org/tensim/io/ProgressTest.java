package org.tensim.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** Progress without a terminal: one line per 10 % with simulated time, real-time factor and ETA, or nothing. */
class ProgressTest {
    @Test
    void oneLinePerTenPercentWithTimeFactorAndEta() {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        try (Progress p = Progress.lines("run", 2.0, new PrintStream(b, true, StandardCharsets.UTF_8), 0)) {
            for (int i = 0; i <= 20_000; i++) {
                p.update(i * 1e-4);
            }
        }
        String[] lines = b.toString(StandardCharsets.UTF_8).split("\n");
        assertEquals(10, lines.length, String.join("\n", lines));
        assertTrue(lines[0].matches("run: 10 %, t = 0\\.2\\d\\d of 2\\.000 s, \\S+ x real time, ETA \\d+ s"),
                lines[0]);
        assertTrue(lines[9].startsWith("run: 100 %"), lines[9]);
    }

    @Test
    void shortRunsPrintNothing() {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        try (Progress p = Progress.lines("run", 1.0, new PrintStream(b, true, StandardCharsets.UTF_8), 3600)) {
            for (int i = 0; i <= 1000; i++) {
                p.update(i * 1e-3);
            }
        }
        assertEquals(0, b.size());
    }
}

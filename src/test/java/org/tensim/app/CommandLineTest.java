package org.tensim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

class CommandLineTest {
    static String[] run(String... args) {
        CommandLine cl = Main.commandLine();
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        cl.setOut(new PrintWriter(out));
        cl.setErr(new PrintWriter(err));
        int code = cl.execute(args);
        return new String[] {String.valueOf(code), out.toString(), err.toString()};
    }

    @Test
    void helpExplainsEveryCubeOptionWithUnitsAndDefaults() {
        String[] r = run("cube", "--help");
        assertEquals("0", r[0]);
        for (String s : new String[] {"--out", "--dt", "(default: 0.001)", "--force", "(default: 400.0)",
            "--frequency", "Hz", "--stiffness", "N/m"}) {
            assertTrue(r[1].contains(s), "cube --help mentions " + s + ":\n" + r[1]);
        }
    }

    @Test
    void badValuesGetOneClearMessage() {
        String[] r = run("cube", "--dt", "-1", "--out", "build/tmp/never");
        assertEquals("2", r[0], "a refused option is a usage error");
        assertTrue(r[2].contains("--dt -1.0") && r[2].contains("> 0 s"), r[2]);
        assertTrue(!r[2].contains("\tat "), "no stack trace: " + r[2]);
        String[] b = run("bench", "--n", "1");
        assertEquals("2", b[0]);
        assertTrue(b[2].contains("--n 1"), b[2]);
    }

    @Test
    void unknownOptionsAreRefused() {
        String[] r = run("cube", "--nonsense");
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("--nonsense"), r[2]);
    }
}

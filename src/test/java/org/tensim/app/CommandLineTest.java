package org.tensim.app;

import org.tensim.testsupport.Commands;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

class CommandLineTest {
    static String[] run(String... args) {
        return Commands.run(args);
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
        assertTrue(b[2].contains("--size 1"), b[2]);
    }

    /** bench --compare takes two names of the catalogue, on the diaphragm; anything else is refused at once. */
    @Test
    void benchCompareIsRefusedWithoutTwoKnownIntegratorsOnTheDiaphragm() {
        String[] one = run("bench", "--scene", "diaphragm", "--compare", "bdf2");
        assertEquals("2", one[0]);
        assertTrue(one[2].contains("--compare takes two"), one[2]);
        String[] lattice = run("bench", "--compare", "bdf2,bdf2-newton2");
        assertEquals("2", lattice[0]);
        assertTrue(lattice[2].contains("with --scene diaphragm"), lattice[2]);
        String[] unknown = run("bench", "--scene", "diaphragm", "--compare", "bdf2,bdf3");
        assertTrue(!"0".equals(unknown[0]), "refused");
        assertTrue(unknown[2].contains("unknown integrator 'bdf3'"), unknown[2]);
    }

    @Test
    void everyCommandsHelpIsFormattedWithoutAWarning() {
        PrintStream saved = System.err;
        ByteArrayOutputStream warnings = new ByteArrayOutputStream();
        List<String> names = new ArrayList<>();
        try {
            System.setErr(new PrintStream(warnings, true, StandardCharsets.UTF_8));
            Deque<CommandLine> todo = new ArrayDeque<>(List.of(Main.commandLine()));
            while (!todo.isEmpty()) {
                CommandLine c = todo.pop();
                names.add(c.getCommandSpec().qualifiedName());
                String usage = c.getUsageMessage(CommandLine.Help.Ansi.OFF);
                assertFalse(usage.contains("%n"), c.getCommandSpec().qualifiedName() + ": unformatted help\n" + usage);
                todo.addAll(c.getSubcommands().values());
            }
        } finally {
            System.setErr(saved);
        }
        String w = warnings.toString(StandardCharsets.UTF_8);
        assertFalse(w.contains("picocli WARN"), "a help text picocli cannot format (a lone '%' must be '%%'):\n" + w);
        assertTrue(names.size() > 10, "walked the whole command tree: " + names);
    }

    @Test
    void unknownOptionsAreRefused() {
        String[] r = run("cube", "--nonsense");
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("--nonsense"), r[2]);
    }
}

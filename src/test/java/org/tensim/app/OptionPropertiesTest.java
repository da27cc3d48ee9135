package org.tensim.app;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tensim.RandomCases;
import org.tensim.cli.TimeStepOption;
import picocli.CommandLine;
import picocli.CommandLine.Model.OptionSpec;

/**
 * Property-based tests ({@link RandomCases}) of the option parsing of every command: any numeric
 * option given a value that is not a usable number (text, empty, NaN, infinities,
 * 1e400, an integer beyond int) is refused with exit code 2 (usage) or 1 and one
 * short message that names the option or the value: never a stack trace, an internal
 * error or a run that starts. The commands and options are read from the command
 * line's own model, so a new option is covered without changing this test.
 */
class OptionPropertiesTest {
    /** Values no numeric option may take. */
    static final List<String> BAD = List.of("abc", "", "NaN", "nan", "Infinity", "-Infinity", "1e400", "-1e400",
            "1..2", "0x", "--", "1,,2", "\u00e9");
    /** Beyond long, or not whole: no whole-number option may take them. */
    static final List<String> BAD_LONGS = List.of("99999999999999999999", "1.5", "1e3");
    /** Beyond int as well: no int option may take them (a long option, such as a seed, may). */
    static final List<String> BAD_INTS = List.of("2147483648", "-2147483649");
    /** The GUI opens a window for any value its options accept: only values no parser accepts. */
    static final List<String> BAD_FOR_ANY_PARSER = List.of("abc", "", "1..2", "0x", "1,,2", "\u00e9");

    record Case(String command, String option, String value) {
    }

    static List<String[]> numericOptions() {
        List<String[]> pairs = new ArrayList<>();
        CommandLine cl = Main.commandLine();
        for (var e : cl.getSubcommands().entrySet()) {
            for (OptionSpec o : e.getValue().getCommandSpec().options()) {
                Class<?> t = o.type();
                Class<?> item = o.auxiliaryTypes().length > 0 ? o.auxiliaryTypes()[0] : t;
                boolean numeric = isNumber(t) || ((List.class.isAssignableFrom(t) || t.isArray()) && isNumber(
                        t.isArray() ? t.getComponentType() : item));
                if (numeric && !o.usageHelp() && !o.versionHelp()) {
                    boolean isLong = t == long.class || t == Long.class || item == Long.class;
                    boolean isInt = t == int.class || t == Integer.class || item == Integer.class || t == int[].class;
                    pairs.add(new String[] {e.getKey(), o.longestName(), isInt ? "int" : isLong ? "long" : "double"});
                }
            }
        }
        assertTrue(pairs.size() >= 30, "every command's numeric options are found: " + pairs.size());
        return pairs;
    }

    private static boolean isNumber(Class<?> c) {
        return c == int.class || c == double.class || c == long.class || c == Integer.class || c == Double.class
                || c == Long.class || c == TimeStepOption.Step.class;
    }

    @Test
    void everyNumericOptionRefusesValuesThatAreNotUsableNumbers() throws Exception {
        List<String[]> options = numericOptions();
        RandomCases.check("numeric options", 250, r -> {
            String[] p = options.get(r.nextInt(options.size()));
            List<String> values = new ArrayList<>(p[0].equals("gui") ? BAD_FOR_ANY_PARSER : BAD);
            if (p[2].equals("int") || p[2].equals("long")) {
                values.addAll(BAD_LONGS);
            }
            if (p[2].equals("int")) {
                values.addAll(BAD_INTS);
            }
            refused(new Case(p[0], p[1], values.get(r.nextInt(values.size()))));
        });
    }

    private static void refused(Case c) throws Exception {
        Path out = Files.createTempDirectory("tensim-opt").resolve("never");
        CommandLine cl = Main.commandLine();
        StringWriter o = new StringWriter();
        StringWriter e = new StringWriter();
        cl.setOut(new PrintWriter(o));
        cl.setErr(new PrintWriter(e));
        List<String> args = new ArrayList<>(List.of(c.command(), c.option() + "=" + c.value()));
        if (!c.command().equals("diaphragm-mesh") && !c.command().equals("gui")) {
            args.add("--out=" + out);
        }
        int code = cl.execute(args.toArray(new String[0]));
        String err = e.toString();
        assertTrue(code == 2 || code == 1, c + ": exit " + code + "\n" + err + o);
        String first = err.strip().split("\n")[0];
        assertTrue(first.contains(c.option()) || (!c.value().isEmpty() && first.contains(c.value()))
                || first.contains("'" + c.value() + "'"), c + ": the message names the option or the value: " + err);
        assertFalse(err.contains("\tat ") || err.contains("internal error"), c + ": " + err);
        assertFalse(Files.exists(out), c + ": refused before any output");
    }
}

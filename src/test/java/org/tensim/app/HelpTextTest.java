package org.tensim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tensim.cli.HelpLayout;
import picocli.CommandLine;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;

/**
 * Every command's help is made of whole sentences: each summary in its parent's command list is the whole first
 * paragraph of its description and ends with a full stop; each paragraph of a description and of an option's text
 * ends a sentence; and the help wrapped at 80 columns has exactly the words of the help at 400, so that no line
 * breaks inside a word or a value.
 */
class HelpTextTest {
    private static final int NARROW = 80;
    private static final int WIDE = 400;

    /** Why a paragraph is not whole sentences, or null: it must end with . ! ? or :, with its brackets closed. */
    static String notWhole(String paragraph) {
        String p = paragraph.strip();
        if (p.isEmpty()) {
            return null; // a blank element is the space between paragraphs
        }
        char last = p.charAt(p.length() - 1);
        if (".!?:".indexOf(last) < 0) {
            return "ends mid-sentence ('" + last + "')";
        }
        int round = 0;
        int square = 0;
        for (char c : p.toCharArray()) {
            round += c == '(' ? 1 : c == ')' ? -1 : 0;
            square += c == '[' ? 1 : c == ']' ? -1 : 0;
            if (round < 0 || square < 0) {
                return "closes a bracket it did not open";
            }
        }
        return round != 0 || square != 0 ? "leaves a bracket open" : null;
    }

    /** The words of a text, in order (whitespace of any kind, line breaks included, separates them). */
    static List<String> words(String text) {
        return Arrays.stream(text.strip().split("\\s+")).filter(w -> !w.isEmpty()).toList();
    }

    /**
     * The summary that a command list shows for {@code name}: the text of its row and of the rows that continue
     * it (indented past the names), joined with single spaces; null if the list has no such command.
     */
    static String summaryIn(String usage, String name) {
        List<String> lines = usage.lines().toList();
        int at = lines.indexOf("Commands:");
        if (at < 0) {
            return null;
        }
        for (int i = at + 1; i < lines.size(); i++) {
            String l = lines.get(i);
            if (l.startsWith("  " + name + " ")) {
                int column = l.length() - l.substring(2 + name.length()).stripLeading().length();
                StringBuilder s = new StringBuilder(l.substring(column).strip());
                for (int j = i + 1; j < lines.size() && lines.get(j).length() > column
                        && lines.get(j).substring(0, column).isBlank(); j++) {
                    s.append(' ').append(lines.get(j).strip());
                }
                return s.toString();
            }
        }
        return null;
    }

    /** Every problem of one command's help against these rules (empty: none). */
    static List<String> problems(CommandLine cmd) {
        List<String> found = new ArrayList<>();
        CommandSpec spec = cmd.getCommandSpec();
        String who = spec.qualifiedName();
        List<String[]> texts = new ArrayList<>();
        texts.add(new String[] {"description", null});
        for (String d : spec.usageMessage().description()) {
            texts.add(new String[] {"description", String.format(d)});
        }
        for (String d : spec.usageMessage().header()) {
            texts.add(new String[] {"header", String.format(d)});
        }
        for (String d : spec.usageMessage().footer()) {
            texts.add(new String[] {"footer", String.format(d)});
        }
        for (OptionSpec o : spec.options()) {
            if (!o.hidden()) {
                for (String d : o.description()) {
                    texts.add(new String[] {o.names()[0], d});
                }
            }
        }
        for (String[] t : texts) {
            String why = t[1] == null ? null : notWhole(t[1]);
            if (why != null) {
                found.add(who + " " + t[0] + ": " + why + ": \"" + t[1] + "\"");
            }
        }
        if (spec.usageMessage().description().length == 0 || notWhole(spec.usageMessage().description()[0]) != null
                || !String.format(spec.usageMessage().description()[0]).strip().endsWith(".")) {
            found.add(who + ": the first paragraph of the description, its summary, must be a sentence ending in '.'");
        }
        String narrow = usage(cmd, NARROW);
        String wide = usage(cmd, WIDE);
        if (!words(narrow).equals(words(wide))) {
            found.add(who + ": the words at " + NARROW + " columns differ from those at " + WIDE + " (a line breaks"
                    + " inside a word or value): " + difference(words(narrow), words(wide)));
        }
        for (String w : words(narrow)) {
            String name = w.replaceAll("^[\\[(]+", "").replaceAll("[=,.)\\]].*$", "");
            if (HelpLayout.FORMER_NAMES.containsKey(name)) {
                found.add(who + ": the help shows the former name " + name + " (" + HelpLayout.FORMER_NAMES.get(name)
                        + " replaced it)");
            }
        }
        for (CommandLine sub : cmd.getSubcommands().values()) {
            String full = String.join(" ", words(String.format(sub.getCommandSpec().usageMessage().description()[0])));
            for (String u : List.of(narrow, wide)) {
                String shown = summaryIn(u, sub.getCommandName());
                if (!full.equals(shown)) {
                    found.add(who + ": the command list shows " + sub.getCommandName() + " as \"" + shown
                            + "\", not its whole summary \"" + full + "\"");
                }
            }
        }
        return found;
    }

    private static String usage(CommandLine cmd, int width) {
        cmd.setUsageHelpWidth(width);
        return cmd.getUsageMessage(CommandLine.Help.Ansi.OFF);
    }

    private static String difference(List<String> a, List<String> b) {
        int i = 0;
        while (i < a.size() && i < b.size() && a.get(i).equals(b.get(i))) {
            i++;
        }
        return "'" + (i < a.size() ? a.get(i) : "(end)") + "' against '" + (i < b.size() ? b.get(i) : "(end)") + "'";
    }

    private static void walk(CommandLine cmd, List<CommandLine> all) {
        all.add(cmd);
        cmd.getSubcommands().values().forEach(s -> walk(s, all));
    }

    @Test
    void everyCommandsHelpIsWholeSentencesAndKeepsEveryWordOnOneLine() {
        List<CommandLine> all = new ArrayList<>();
        walk(Main.commandLine(), all);
        List<String> names = all.stream().map(c -> c.getCommandSpec().qualifiedName()).toList();
        assertTrue(names.contains("tensim diaphragm resolution-study") && names.contains("tensim gui"), "" + names);
        List<String> found = new ArrayList<>();
        for (CommandLine c : all) {
            found.addAll(problems(c));
        }
        assertEquals(List.of(), found, String.join("\n", found));
    }

    @Test
    void theChecksRefuseFragments() {
        assertEquals("ends mid-sentence ('e')",
                notWhole("The paper's cube experiment: a mass-spring and a tensegrity cube"));
        assertTrue(notWhole("(10 x 10 x 10 m, bottom fixed), identical but for the six rigid links, under") != null);
        assertTrue(notWhole("central tendon as tensegrity (docs/diaphragm.md.") != null, "an open bracket");
        assertTrue(notWhole("simulated time, s (default: 0.5)") != null);
        assertEquals(null, notWhole("Simulated time, s (default: 0.5)."));
        assertEquals(null, notWhole("Its studies are subcommands:"));
        assertEquals(null, notWhole(""));
        assertFalse(words("restored from ~/.\nconfig/tensim/").equals(words("restored from ~/.config/tensim/")));
        assertEquals(words("a  b\n   c"), List.of("a", "b", "c"));
        String list = "Usage: x\nCommands:\n  cube   The paper's cube, a mass-spring and a\n"
                + "           tensegrity cube.\n"
                + "  gui    Interactive.\n";
        assertEquals("The paper's cube, a mass-spring and a tensegrity cube.", summaryIn(list, "cube"));
        assertEquals("Interactive.", summaryIn(list, "gui"));
        assertEquals(null, summaryIn(list, "bench"));
        String cut = "Commands:\n  cube   The paper's cube, a mass-spring and a\n  gui    Interactive.\n";
        assertEquals("The paper's cube, a mass-spring and a", summaryIn(cut, "cube"), "a summary cut short");
    }

    /** A command written as picocli's fragments: every check finds it out. */
    @CommandLine.Command(name = "bad", subcommands = BadSub.class,
            description = {"Restores the last-used parameters from $XDG_CONFIG_HOME/tensim/ or from the",
                "folder ~/.config/tensim/ of the user, as settings.json, presets.json, window.json, labels.json,"
                    + " charts.json, probes.json, colours.json, brushes.json, meshes.json and more.json."})
    static final class Bad {
        @CommandLine.Option(names = "--boxes", description = "rib and sternum boxes, mm (default: none)")
        String boxes;
    }

    @CommandLine.Command(name = "sub", description = {"The paper's diaphragm: muscle as mass-spring, central",
        "tendon as tensegrity."})
    static final class BadSub {
    }

    @Test
    void aCommandOfFragmentsFailsEveryCheck() {
        List<CommandLine> cmds = new ArrayList<>();
        walk(new CommandLine(new Bad()), cmds);
        List<String> found = new ArrayList<>();
        cmds.forEach(c -> found.addAll(problems(c)));
        String all = String.join("\n", found);
        assertTrue(all.contains("bad description: ends mid-sentence"), all);
        assertTrue(all.contains("bad --boxes: ends mid-sentence"), all);
        assertTrue(all.contains("sub: the first paragraph of the description, its summary, must be"), all);
        assertTrue(all.contains("bad: the words at 80 columns differ"),
                "picocli's own wrapping splits a value: " + all);
        // The project's layout keeps every word whole; the fragments are still fragments.
        String ours = String.join("\n", problems(HelpLayout.install(new CommandLine(new Bad()))));
        assertFalse(ours.contains("the words at 80 columns differ"), ours);
        assertTrue(ours.contains("bad --boxes: ends mid-sentence"), ours);
    }

    /** The launcher's `test` is named in the root help once, in a sentence of its own, not as a command. */
    @Test
    void theRootHelpNamesTheLaunchersTestOnce() {
        String root = usage(Main.commandLine(), NARROW);
        assertEquals(null, summaryIn(root, "test"), root);
        assertEquals(1, root.split("test suite", -1).length - 1, root);
        assertTrue(root.contains("./tensim test --help"), root);
    }
}

package org.tensim.cli;

import java.util.IllegalFormatException;
import java.util.Map;
import picocli.CommandLine;
import picocli.CommandLine.Help.Ansi.Text;
import picocli.CommandLine.Help.Column;
import picocli.CommandLine.Help.TextTable;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Model.PositionalParamSpec;

/**
 * The usage help of every command (a picocli help factory, {@link #install}): picocli's layout with two changes.
 * Text is wrapped at spaces only, so that no word or value ({@code ~/.config}, {@code mm.json}, {@code 0..3}) is
 * split across two lines: picocli wraps where {@link java.text.BreakIterator} allows, which includes after a
 * '.', a '/' or a ','. Paragraphs (the elements of a description) are set apart by a blank line. And an
 * option's former names ({@link #FORMER_NAMES}), still accepted so that scripts keep working, are left out of
 * the help.
 */
public final class HelpLayout extends CommandLine.Help {
    /** Former option names, still accepted, each to the name that replaced it (the one the help shows). */
    public static final Map<String, String> FORMER_NAMES = Map.of("--duration", "--seconds", "--integrators",
            "--integrator", "--resolution", "--rings", "--n", "--size", "--muscle-force", "--muscle-action");

    /** Synopsis lines wrap under the command name unless it takes more than this share of the width. */
    private static final double SYNOPSIS_INDENT_SHARE = 0.9;

    HelpLayout(CommandSpec spec, ColorScheme scheme) {
        super(spec, scheme);
    }

    /** Makes this the help of a command line and of all its subcommands, as they are now; returns it. */
    public static CommandLine install(CommandLine cl) {
        cl.setHelpFactory(HelpLayout::new);
        return cl;
    }

    private int width() {
        return commandSpec().usageMessage().width();
    }

    @Override
    public String description(Object... params) {
        return paragraphs(commandSpec().usageMessage().description(), params);
    }

    @Override
    public String header(Object... params) {
        return paragraphs(commandSpec().usageMessage().header(), params);
    }

    @Override
    public String footer(Object... params) {
        return paragraphs(commandSpec().usageMessage().footer(), params);
    }

    @Override
    public String customSynopsis(Object... params) {
        return paragraphs(commandSpec().usageMessage().customSynopsis(), params);
    }

    /**
     * Each element a paragraph over the whole width, as picocli's own join does, with a blank line between two
     * paragraphs.
     */
    private String paragraphs(String[] values, Object... params) {
        StringBuilder sb = new StringBuilder();
        if (values != null) {
            TextTable t = new SpaceWrapped(colorScheme(), new Column(width(), 0, Column.Overflow.WRAP));
            t.indentWrappedLines = 0;
            String previous = "";
            for (String v : values) {
                String text = format(v, params);
                if (!previous.isBlank() && !text.isBlank()) {
                    t.addRowValues("");
                }
                t.addRowValues(text);
                previous = text;
            }
            t.toString(sb);
        }
        return sb.toString();
    }

    private static String format(String text, Object... params) {
        try {
            return text == null ? "" : String.format(text, params);
        } catch (IllegalFormatException e) {
            return text;
        }
    }

    @Override
    protected String insertSynopsisCommandName(int headingLength, Text details) {
        CommandLine.Model.UsageMessageSpec u = commandSpec().usageMessage();
        String name = commandSpec().qualifiedName();
        int indent = headingLength + name.length() + 1;
        if (indent > u.synopsisAutoIndentThreshold() * width()) {
            indent = u.synopsisIndent() < 0 ? headingLength : u.synopsisIndent();
            indent = Math.min(indent, (int) (SYNOPSIS_INDENT_SHARE * width()));
        }
        for (String former : FORMER_NAMES.keySet()) {
            details = renamed(details, former, FORMER_NAMES.get(former));
        }
        TextTable t = new SpaceWrapped(colorScheme(), new Column(width(), 0, Column.Overflow.WRAP));
        t.indentWrappedLines = indent;
        // The heading ("Usage: ") is printed before: padding stands for it on the first line, then is cut off.
        t.addRowValues(colorScheme().text("X".repeat(headingLength)).concat(colorScheme().commandText(name))
                .concat(details));
        return t.toString().substring(headingLength);
    }

    @Override
    public String commandList(Map<String, CommandLine.Help> subcommands) {
        if (subcommands.isEmpty()) {
            return "";
        }
        int nameLength = Math.min(subcommands.keySet().stream().mapToInt(String::length).max().orElse(0),
                width() / 2);
        TextTable t = new SpaceWrapped(colorScheme(), new Column(nameLength + 2, 2, Column.Overflow.SPAN),
                new Column(width() - (nameLength + 2), 2, Column.Overflow.WRAP));
        for (CommandLine.Help help : subcommands.values()) {
            CommandLine.Model.UsageMessageSpec usage = help.commandSpec().usageMessage();
            String[] header = usage.header().length > 0 ? usage.header() : usage.description();
            Text[] lines = colorScheme().text(format(header.length > 0 ? header[0] : "")).splitLines();
            for (int i = 0; i < lines.length; i++) {
                t.addRowValues(i == 0 ? help.commandNamesText(", ") : colorScheme().text(""), lines[i]);
            }
        }
        return t.toString();
    }

    @Override
    public Layout createDefaultLayout(java.util.List<OptionSpec> options,
            java.util.List<PositionalParamSpec> positionals, ColorScheme scheme) {
        TextTable made = TextTable.forDefaultColumns(scheme, calcLongOptionColumnWidth(options, positionals, scheme),
                width());
        Column[] columns = made.columns();
        for (int i = 0; i < columns.length; i++) {
            columns[i] = new Column(columns[i].width, columns[i].indent, columns[i].overflow);
        }
        TextTable t = new SpaceWrapped(scheme, columns);
        t.indentWrappedLines = made.indentWrappedLines;
        return new Layout(scheme, t, createDefaultOptionRenderer(), createDefaultParameterRenderer());
    }

    @Override
    public IOptionRenderer createDefaultOptionRenderer() {
        IOptionRenderer picocli = super.createDefaultOptionRenderer();
        return (option, labels, scheme) -> {
            Text[][] rows = picocli.render(option, labels, scheme);
            for (String name : option.names()) {
                if (FORMER_NAMES.containsKey(name) && rows.length > 0) {
                    for (int c = 0; c < rows[0].length; c++) {
                        rows[0][c] = withoutName(rows[0][c], name);
                    }
                }
            }
            return rows;
        };
    }

    /**
     * The synopsis with a former name, which picocli shows when it is the shortest, replaced by the name that
     * replaced it, where the command has an option of both names.
     */
    private Text renamed(Text synopsis, String former, String name) {
        OptionSpec o = commandSpec().findOption(former);
        if (o == null || !java.util.Arrays.asList(o.names()).contains(name)) {
            return synopsis;
        }
        String p = synopsis.plainString();
        for (int i = p.indexOf(former); i >= 0; i = p.indexOf(former, i + 1)) {
            int end = i + former.length();
            if (i > 0 && p.charAt(i - 1) == '[' && end < p.length() && (p.charAt(end) == '=' || p.charAt(end) == ']')) {
                return renamed(synopsis.substring(0, i).concat(colorScheme().optionText(name))
                        .concat(synopsis.substring(end, p.length())), former, name);
            }
        }
        return synopsis;
    }

    /** The text with {@code name} taken out of its list of names ("--a, --b=X"), or as it was. */
    static Text withoutName(Text t, String name) {
        String p = t.plainString();
        for (int i = p.indexOf(name); i >= 0; i = p.indexOf(name, i + 1)) {
            int end = i + name.length();
            boolean whole = (i == 0 || p.charAt(i - 1) == ' ') && (end == p.length()
                    || !(Character.isLetterOrDigit(p.charAt(end)) || p.charAt(end) == '-'));
            if (!whole) {
                continue;
            }
            if (p.startsWith(", ", end)) {
                return t.substring(0, i).concat(t.substring(end + 2, p.length()));
            }
            if (i >= 2 && p.startsWith(", ", i - 2)) {
                return t.substring(0, i - 2).concat(t.substring(end, p.length()));
            }
        }
        return t;
    }

    /** A table whose wrapped columns break lines at spaces only. */
    static final class SpaceWrapped extends TextTable {
        SpaceWrapped(ColorScheme scheme, Column... columns) {
            super(scheme, columns);
        }

        @Override
        public Cell putValue(int row, int col, Text value) {
            Column column = columns()[col];
            if (value == null || column.overflow != Column.Overflow.WRAP) {
                return super.putValue(row, col, value);
            }
            String plain = value.plainString();
            int first = column.indent;
            int indent = first;
            int start = 0;
            try {
                while (true) {
                    int end = lineEnd(plain, start, column.width - indent);
                    // Each line fits (but for a word longer than the column), so picocli writes it whole.
                    column.indent = indent;
                    Cell cell = super.putValue(row, col, value.substring(start, end));
                    start = end;
                    while (start < plain.length() && plain.charAt(start) == ' ') {
                        start++;
                    }
                    if (start >= plain.length()) {
                        return cell;
                    }
                    addEmptyRow();
                    row = rowCount() - 1;
                    indent = first + indentWrappedLines;
                }
            } finally {
                column.indent = first;
            }
        }

        /** Where the line from {@code start} ends: at the last space that lets it fit in {@code room} characters. */
        static int lineEnd(String s, int start, int room) {
            int n = s.length();
            if (n - start <= Math.max(room, 1)) {
                return n;
            }
            for (int i = start + Math.max(room, 1); i > start; i--) {
                if (s.charAt(i) == ' ') {
                    int end = i;
                    while (end > start && s.charAt(end - 1) == ' ') {
                        end--;
                    }
                    if (end > start) {
                        return end;
                    }
                }
            }
            int space = s.indexOf(' ', start);
            return space < 0 ? n : space; // a word longer than the column: picocli then cuts it
        }
    }
}

package org.tensim.testsupport;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import org.tensim.app.Main;
import picocli.CommandLine;

/** Runs a {@code tensim} command line in the test's JVM, as the launcher would, and keeps what it printed. */
public final class Commands {
    private Commands() {
    }

    /**
     * Runs the command with its output and error streams captured: {exit code, standard output, standard error}
     * (picocli's writers, which the commands print to).
     */
    public static String[] run(String... args) {
        CommandLine cl = Main.commandLine();
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        cl.setOut(new PrintWriter(out));
        cl.setErr(new PrintWriter(err));
        int code = cl.execute(args);
        return new String[] {String.valueOf(code), out.toString(), err.toString()};
    }

    /**
     * As {@link #run}, for the commands that print their figures to {@code System.out} (the studies): that stream
     * is captured for the run and restored after it.
     */
    public static String[] runCapturingSystemOut(String... args) {
        CommandLine cl = Main.commandLine();
        StringWriter err = new StringWriter();
        cl.setErr(new PrintWriter(err));
        PrintStream old = System.out;
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        int code;
        try {
            System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
            code = cl.execute(args);
        } finally {
            System.setOut(old);
        }
        return new String[] {Integer.toString(code), out.toString(StandardCharsets.UTF_8), err.toString()};
    }
}

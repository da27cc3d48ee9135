package org.tensim.app;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * The real program as a separate process: the launcher's java command (same class
 * path, -Dtensim.home, JVM options) with its own working folder, environment,
 * standard output and error, signals and exit code. Used by the process-level tests.
 */
final class RunProcess {
    /** The project folder (Gradle runs the tests there). */
    static final Path HOME = Path.of(System.getProperty("user.dir")).toAbsolutePath();

    final Process process;
    final Path stdout;
    final Path stderr;

    private RunProcess(Process p, Path stdout, Path stderr) {
        this.process = p;
        this.stdout = stdout;
        this.stderr = stderr;
    }

    /** Starts {@code tensim args...} in {@code cwd}; {@code env} entries with a null value are removed. */
    static RunProcess start(Path cwd, Map<String, String> env, String... args) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xss8m", "-XX:+UseParallelGC", "-XX:TieredStopAtLevel=1", "-Dtensim.home=" + HOME, "-cp",
                System.getProperty("tensim.classpath", System.getProperty("java.class.path")),
                "org.tensim.app.Main"));
        cmd.addAll(List.of(args));
        ProcessBuilder b = new ProcessBuilder(cmd).directory(cwd.toFile());
        env.forEach((k, v) -> {
            if (v == null) {
                b.environment().remove(k);
            } else {
                b.environment().put(k, v);
            }
        });
        Path out = Files.createTempFile(cwd, "stdout", ".txt");
        Path err = Files.createTempFile(cwd, "stderr", ".txt");
        b.redirectOutput(out.toFile()).redirectError(err.toFile());
        return new RunProcess(b.start(), out, err);
    }

    /** Runs to the end (at most {@code timeoutS}) and returns the exit code. */
    int waitFor(double timeoutS) throws Exception {
        if (!process.waitFor((long) (timeoutS * 1000), TimeUnit.MILLISECONDS)) {
            process.destroyForcibly().waitFor();
            throw new AssertionError("the process ran longer than " + timeoutS + " s");
        }
        return process.exitValue();
    }

    /**
     * Sends a signal by name (INT, TERM, KILL) with kill(1) and returns the one sent: a
     * process started with SIGINT ignored (a background job of a non-interactive shell, as
     * the test runner may be) keeps ignoring it, as any program does, so TERM is sent instead.
     */
    String signal(String name) throws Exception {
        String sent = name.equals("INT") && ignores(2) ? "TERM" : name;
        new ProcessBuilder("kill", "-" + sent, Long.toString(process.pid())).inheritIO().start().waitFor();
        return sent;
    }

    /** Whether the process ignores signal number {@code sig} (SigIgn in /proc/PID/status). */
    private boolean ignores(int sig) throws IOException {
        Path status = Path.of("/proc", Long.toString(process.pid()), "status");
        if (!Files.exists(status)) {
            return false;
        }
        for (String line : Files.readAllLines(status)) {
            if (line.startsWith("SigIgn:")) {
                long mask = Long.parseUnsignedLong(line.substring(7).trim(), 16);
                return (mask & (1L << (sig - 1))) != 0;
            }
        }
        return false;
    }

    String out() throws IOException {
        return Files.readString(stdout);
    }

    String err() throws IOException {
        return Files.readString(stderr);
    }
}

package org.tensim.tutorial;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * docs/examples/library/HangingBlock.java, the program docs/tutorials/library.md points at, compiled with javax.tools
 * against the built jar (build/libs/tensim-VERSION.jar, {@code -Dtensim.libraryJar}, which ./tensim test builds and
 * sets) and the dependency jars of the test's class path, none of the project's class folders, then run in its own
 * JVM. Its printed figures are checked as physics: the hanging block rests at the static stretch (m1 + m2) g / k,
 * its rigid link keeps its length, and the cantilever's scene file, run at 4 cells across with the file's total load
 * (10 uN), deflects within the 4-cell lattice's error of Euler-Bernoulli's F L^3 / (3 E I) = 2 mm.
 */
class LibraryExampleTest {
    private static final Path PROGRAM = Path.of("docs/examples/library/HangingBlock.java");

    @Test
    void theExampleProgramCompilesAgainstTheJarAndPrintsThePhysics(@TempDir Path dir) throws Exception {
        String jar = System.getProperty("tensim.libraryJar");
        Assumptions.assumeTrue(jar != null && Files.isRegularFile(Path.of(jar)),
                "the built jar (tensim.libraryJar, set by ./tensim test) is absent: " + jar);
        String testPath = System.getProperty("tensim.classpath", System.getProperty("java.class.path"));
        List<String> cp = new ArrayList<>(List.of(jar));
        for (String e : testPath.split(File.pathSeparator)) {
            if (e.endsWith(".jar")) {
                cp.add(e);
            }
        }
        String classPath = String.join(File.pathSeparator, cp);
        assertTrue(cp.stream().skip(1).noneMatch(e -> Path.of(e).getFileName().toString().startsWith("tensim")), "only the jar carries tensim: " + cp);

        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        boolean compiled;
        try (StandardJavaFileManager files = javac.getStandardFileManager(diagnostics, null, StandardCharsets.UTF_8)) {
            compiled = javac.getTask(null, files, diagnostics, List.of("-d", dir.toString(), "-cp", classPath,
                    "--release", "17"), null, files.getJavaFileObjects(PROGRAM.toFile())).call();
        }
        assertTrue(compiled, "HangingBlock.java compiles against the jar: " + diagnostics.getDiagnostics());

        Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                dir + File.pathSeparator + classPath, "HangingBlock", "docs/examples/cantilever.yaml",
                "bodies.beam.cell=5", "conditions[1].magnitude=4e-7 N").redirectErrorStream(true).start();
        String out;
        try (var in = p.getInputStream()) {
            out = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        assertTrue(p.waitFor(300, TimeUnit.SECONDS), "the program ended");
        System.out.print(out);
        assertEquals(0, p.exitValue(), out);

        // Part 1: the spring carries both 1 kg nodes: (m1 + m2) g / k = 2 * 9.81 / 50 m; the paper's loop leaves a
        // first-order offset along a loaded link (docs/solvers.md), 0.1 % at the program's 0.5 ms step.
        Matcher block = find(out, "hanging block: stretch (\\S+) m, \\(m1 \\+ m2\\) g / k (\\S+) m .*length error (\\S+) m");
        double stretch = Double.parseDouble(block.group(1));
        assertEquals(2 * 9.81 / 50, Double.parseDouble(block.group(2)), 1e-6);
        assertEquals(2 * 9.81 / 50, stretch, 0.005 * 2 * 9.81 / 50, "the static stretch");
        assertTrue(Double.parseDouble(block.group(3)) < 1e-9 * 0.1, "the rigid link keeps its 0.1 m");

        // Part 2: 25 tip nodes of 0.4 uN, 10 uN in all, as the file's 9 of 1.111 uN; E = 1 kPa, L = 200 mm, D = 20 mm.
        find(out, "scene docs/examples/cantilever.yaml: 1025 nodes, 120 steps");
        Matcher tip = find(out, "probe tip: mean displacement (\\S+) (\\S+) (\\S+) m over 25 nodes");
        double eulerBernoulli = 10e-6 * Math.pow(0.2, 3) / (3 * 1e3 * Math.pow(0.02, 4) / 12);
        double error = -Double.parseDouble(tip.group(2)) / eulerBernoulli - 1;
        // the 4-cell lattice is stiff by about 5 % (docs/volume.md: -5.60 % under a uniform traction)
        assertTrue(error > -0.08 && error < -0.03, "the 4-cell cantilever against Euler-Bernoulli: " + error);
        assertTrue(Math.abs(Double.parseDouble(tip.group(3))) < 1e-6 * eulerBernoulli, "no sideways tip motion");
    }

    private static Matcher find(String out, String regex) {
        Matcher m = Pattern.compile(regex).matcher(out);
        assertTrue(m.find(), "printed: " + regex + "\n" + out.lines().collect(Collectors.joining("\n")));
        return m;
    }
}

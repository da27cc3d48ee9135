package org.tensim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.tensim.io.ProjectFolder;

/**
 * The packages depend one way. Layers, lowest first; a package may use its own layer and those below it,
 * never one above:
 * <pre>
 *   model  &lt;-  solver  &lt;-  scene, io  &lt;-  experiment, analysis, tuning, sweep, calibration  &lt;-  view, cli  &lt;-  bench  &lt;-  app
 * </pre>
 * Within a layer two packages must not use each other both ways. {@code model} and {@code solver} use no
 * Java3D, Swing or AWT; below {@code view} nothing uses Java3D or Swing. A use is an import line or a fully
 * qualified name in code (comments and string literals are left out), in {@code src/main/java}. And
 * {@code app/gui} holds only classes that draw.
 */
class LayersTest {
    /** The layers, lowest first: top-level packages under org.tensim. */
    static final List<Set<String>> LAYERS = List.of(
            Set.of("model"),
            Set.of("solver"),
            Set.of("scene", "io"),
            Set.of("experiment", "analysis", "tuning", "sweep", "calibration"),
            Set.of("view", "cli"),
            Set.of("bench"),
            Set.of("app"));

    /** Packages that draw on a screen: allowed from {@code view} up only. */
    static final List<String> SCREEN = List.of("org.jogamp.", "javax.media.j3d.", "javax.swing.");
    /** Packages {@code model} and {@code solver} must not use besides {@link #SCREEN}. */
    static final List<String> CORE_FORBIDDEN = List.of("java.awt.");

    private static final Pattern OWN = Pattern.compile("\\borg\\.tensim\\.([a-z][a-z0-9_]*)\\.[A-Za-z]");
    private static final Pattern ANY_QUALIFIED = Pattern.compile(
            "\\b(org\\.jogamp\\.|javax\\.media\\.j3d\\.|javax\\.swing\\.|java\\.awt\\.)");

    @Test
    void packagesDependOnlyOnTheirOwnLayerAndLowerOnes() throws IOException {
        List<String> violations = violations(ProjectFolder.resolve("src", "main", "java"));
        assertTrue(violations.isEmpty(), "layer violations (file:line: use; rule):\n  "
                + String.join("\n  ", violations));
    }

    /**
     * {@code app/gui} holds the Swing window only: every class there uses Swing, AWT or Java3D. A class that
     * uses none is headless and belongs below the application (in {@code tuning}, where sweeps and calibration
     * can use it).
     */
    @Test
    void appGuiHoldsOnlyClassesThatDraw() throws IOException {
        Path gui = ProjectFolder.resolve("src", "main", "java", "org", "tensim", "app", "gui");
        List<String> headless = new ArrayList<>();
        try (Stream<Path> s = Files.list(gui)) {
            for (Path f : s.filter(p -> p.toString().endsWith(".java")).sorted().toList()) {
                if (!ANY_QUALIFIED.matcher(codeOnly(Files.readString(f))).find()) {
                    headless.add(f.getFileName().toString());
                }
            }
        }
        assertTrue(headless.isEmpty(), "headless classes in app/gui (move them to org.tensim.tuning): " + headless);
    }

    /** The check must be able to fail: a solver that imports the app, a model that draws, a cycle. */
    @Test
    void findsAnUpwardImportAQualifiedUseAndACycle(@org.junit.jupiter.api.io.TempDir Path root) throws IOException {
        write(root, "solver/Bad.java", "package org.tensim.solver;\n\nimport org.tensim.app.Main;\n\nclass Bad {}\n");
        write(root, "model/Drawn.java", "package org.tensim.model;\n\n/** org.tensim.app.Main in a comment is no use. */\n"
                + "class Drawn {\n    String s = \"org.tensim.view.SceneView\";\n"
                + "    javax.swing.JFrame f;\n    Object o = new org.tensim.view.SceneView();\n}\n");
        write(root, "sweep/A.java", "package org.tensim.sweep;\nimport org.tensim.calibration.B;\nclass A {}\n");
        write(root, "calibration/B.java", "package org.tensim.calibration;\nimport org.tensim.sweep.A;\nclass B {}\n");
        write(root, "scene/Fine.java", "package org.tensim.scene;\nimport org.tensim.io.Json;\nimport org.tensim.solver.Integrator;\n"
                + "class Fine {}\n");
        List<String> v = violations(root);
        String all = String.join("\n", v);
        assertTrue(all.contains("solver/Bad.java:3: org.tensim.app.Main; solver may not use app"), all);
        assertTrue(all.contains("model/Drawn.java:6: javax.swing.JFrame"), all);
        assertTrue(all.contains("model/Drawn.java:7: org.tensim.view.SceneView; model may not use view"), all);
        assertTrue(all.contains("calibration and sweep use each other"), all);
        assertEquals(4, v.size(), all);
    }

    private static void write(Path root, String file, String text) throws IOException {
        Path p = root.resolve("org/tensim").resolve(file);
        Files.createDirectories(p.getParent());
        Files.writeString(p, text);
    }

    /** Every violation under a source root, one line each, naming the file, the line and the use. */
    static List<String> violations(Path sourceRoot) throws IOException {
        List<String> out = new ArrayList<>();
        Map<String, Set<String>> uses = new TreeMap<>();
        Path base = sourceRoot.resolve("org/tensim");
        List<Path> files;
        try (Stream<Path> s = Files.walk(base)) {
            files = s.filter(p -> p.toString().endsWith(".java")).sorted().toList();
        }
        assertTrue(files.size() > 0, "no sources under " + base);
        for (Path f : files) {
            String rel = base.relativize(f).toString().replace('\\', '/');
            if (!rel.contains("/")) {
                out.add(rel + ": directly in org.tensim; put it in a layer's package");
                continue;
            }
            String pkg = rel.substring(0, rel.indexOf('/'));
            int layer = layerOf(pkg);
            if (layer < 0) {
                out.add(rel + ": package " + pkg + " is in no layer; add it to LayersTest.LAYERS");
                continue;
            }
            String[] lines = codeOnly(Files.readString(f)).split("\n", -1);
            for (int i = 0; i < lines.length; i++) {
                String line = lines[i];
                if (line.startsWith("package ")) {
                    continue;
                }
                Matcher m = OWN.matcher(line);
                while (m.find()) {
                    String target = m.group(1);
                    String use = name(line, m.start());
                    int tl = layerOf(target);
                    if (tl > layer) {
                        out.add(rel + ":" + (i + 1) + ": " + use + "; " + pkg + " may not use " + target
                                + " (a higher layer)");
                    } else if (tl < 0) {
                        out.add(rel + ":" + (i + 1) + ": " + use + "; package " + target + " is in no layer");
                    } else if (!target.equals(pkg)) {
                        uses.computeIfAbsent(pkg, k -> new TreeSet<>()).add(target);
                    }
                }
                Matcher q = ANY_QUALIFIED.matcher(line);
                while (q.find()) {
                    String use = name(line, q.start());
                    boolean screen = SCREEN.stream().anyMatch(use::startsWith);
                    if (screen && layer < layerOf("view")) {
                        out.add(rel + ":" + (i + 1) + ": " + use + "; " + pkg + " is below view: no Java3D or Swing");
                    } else if (!screen && layer <= layerOf("solver")) {
                        out.add(rel + ":" + (i + 1) + ": " + use + "; " + pkg + " uses no AWT");
                    }
                }
            }
        }
        for (Map.Entry<String, Set<String>> e : uses.entrySet()) {
            for (String t : e.getValue()) {
                if (e.getKey().compareTo(t) < 0 && uses.getOrDefault(t, Set.of()).contains(e.getKey())) {
                    out.add(e.getKey() + " and " + t + " use each other: one of them must not");
                }
            }
        }
        return out;
    }

    private static int layerOf(String pkg) {
        for (int i = 0; i < LAYERS.size(); i++) {
            if (LAYERS.get(i).contains(pkg)) {
                return i;
            }
        }
        return -1;
    }

    /** The qualified name that starts at {@code from}: letters, digits, dots, underscores and {@code *}. */
    private static String name(String line, int from) {
        int end = from;
        while (end < line.length() && (Character.isJavaIdentifierPart(line.charAt(end)) || line.charAt(end) == '.'
                || line.charAt(end) == '*')) {
            end++;
        }
        String n = line.substring(from, end);
        return n.endsWith(".") ? n.substring(0, n.length() - 1) : n;
    }

    /**
     * The source with comments and string and character literals blanked (line breaks kept, so line numbers
     * stay right): only code is checked.
     */
    static String codeOnly(String src) {
        StringBuilder b = new StringBuilder(src.length());
        int i = 0;
        int n = src.length();
        while (i < n) {
            char c = src.charAt(i);
            if (c == '/' && i + 1 < n && src.charAt(i + 1) == '/') {
                while (i < n && src.charAt(i) != '\n') {
                    i++;
                }
            } else if (c == '/' && i + 1 < n && src.charAt(i + 1) == '*') {
                int end = src.indexOf("*/", i + 2);
                end = end < 0 ? n : end + 2;
                blank(src, i, end, b);
                i = end;
            } else if (src.startsWith("\"\"\"", i)) {
                int end = src.indexOf("\"\"\"", i + 3);
                end = end < 0 ? n : end + 3;
                blank(src, i, end, b);
                i = end;
            } else if (c == '"' || c == '\'') {
                int j = i + 1;
                while (j < n && src.charAt(j) != c && src.charAt(j) != '\n') {
                    j += src.charAt(j) == '\\' ? 2 : 1;
                }
                j = Math.min(n, j + 1);
                blank(src, i, j, b);
                i = j;
            } else {
                b.append(c);
                i++;
            }
        }
        return b.toString();
    }

    private static void blank(String src, int from, int to, StringBuilder b) {
        for (int k = from; k < to; k++) {
            b.append(src.charAt(k) == '\n' ? '\n' : ' ');
        }
    }
}

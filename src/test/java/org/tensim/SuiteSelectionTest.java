package org.tensim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.annotation.Annotation;
import java.lang.reflect.Modifier;
import java.net.URISyntaxException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.RepeatedTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.api.TestTemplate;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.platform.commons.support.AnnotationSupport;
import org.junit.platform.commons.support.HierarchyTraversalMode;
import org.junit.platform.commons.support.ReflectionSupport;
import org.junit.platform.engine.discovery.ClassNameFilter;

/**
 * Every compiled test class that holds a test is selected by the class-name pattern the suite's launcher is
 * given, so that no test class is silently left out of {@code ./tensim test} (the launcher does not report
 * classes it does not select, not even as skipped). The pattern is the one build.gradle hands the launcher
 * ({@code -Dtensim.test.classPattern}); run some other way, the launcher's own default.
 */
class SuiteSelectionTest {
    /** The Jupiter annotations that make a method a test (composed annotations are found through them). */
    static final List<Class<? extends Annotation>> TEST_ANNOTATIONS = List.of(Test.class, ParameterizedTest.class,
            RepeatedTest.class, TestFactory.class, TestTemplate.class);

    /** The class-name pattern of the suite's run. */
    static Pattern suitePattern() {
        String p = System.getProperty("tensim.test.classPattern");
        return Pattern.compile(p != null ? p : ClassNameFilter.STANDARD_INCLUDE_PATTERN);
    }

    /**
     * Whether the launcher would find tests in this class when it is selected: a concrete class (abstract
     * classes and interfaces run through their subclasses) with a test method of its own, inherited from a
     * superclass or an interface, or in a {@code @Nested} class within it.
     */
    static boolean hasTests(Class<?> c) {
        if (c.isInterface() || Modifier.isAbstract(c.getModifiers()) || c.isAnonymousClass() || c.isLocalClass()) {
            return false;
        }
        return !ReflectionSupport.findMethods(c, m -> TEST_ANNOTATIONS.stream()
                .anyMatch(a -> AnnotationSupport.isAnnotated(m, a)), HierarchyTraversalMode.TOP_DOWN).isEmpty();
    }

    /**
     * The name the launcher's class-name filter sees for a class: its own binary name, except that an inner
     * (non-static, i.e. {@code @Nested}) class is reached only through the class that encloses it.
     */
    static String selectionName(Class<?> c) {
        Class<?> s = c;
        while (s.getEnclosingClass() != null && !Modifier.isStatic(s.getModifiers())) {
            s = s.getEnclosingClass();
        }
        return s.getName();
    }

    /** The names of every class with tests under a folder of compiled classes, mapped to their selection name. */
    static Map<String, String> testClasses(Path classesDir, ClassLoader loader) throws IOException {
        java.util.TreeMap<String, String> found = new java.util.TreeMap<>();
        List<Path> files;
        try (Stream<Path> walk = Files.walk(classesDir)) {
            files = walk.filter(f -> f.toString().endsWith(".class") && !f.endsWith("module-info.class")).toList();
        }
        for (Path f : files) {
            String rel = classesDir.relativize(f).toString();
            String name = rel.substring(0, rel.length() - ".class".length()).replace(f.getFileSystem()
                    .getSeparator(), ".");
            Class<?> c;
            try {
                c = Class.forName(name, false, loader);
            } catch (ClassNotFoundException | LinkageError e) {
                throw new AssertionError("compiled class " + name + " in " + classesDir + " does not load: " + e, e);
            }
            if (hasTests(c)) {
                found.put(name, selectionName(c));
            }
        }
        return found;
    }

    /** The classes with tests (sorted) that the pattern leaves out, each with the name the filter sees. */
    static List<String> unselected(Map<String, String> testClasses, Pattern pattern) {
        List<String> out = new ArrayList<>();
        testClasses.forEach((name, seen) -> {
            if (!pattern.matcher(seen).matches()) {
                out.add(name.equals(seen) ? name : name + " (seen as " + seen + ")");
            }
        });
        return out;
    }

    private static Path location(Class<?> c) throws URISyntaxException {
        return Path.of(c.getProtectionDomain().getCodeSource().getLocation().toURI());
    }

    @Test
    void everyTestClassOfTheSuiteIsSelected() throws Exception {
        Path dir = location(SuiteSelectionTest.class);
        assertTrue(Files.isDirectory(dir), "the test classes are a folder: " + dir);
        Map<String, String> classes = testClasses(dir, SuiteSelectionTest.class.getClassLoader());
        // The scan must see the suite, not an empty or foreign folder.
        assertTrue(classes.size() >= 100, "test classes found in " + dir + ": " + classes.size());
        assertTrue(classes.containsKey(SuiteSelectionTest.class.getName()), "the scan finds this class");
        assertTrue(classes.containsKey("org.tensim.app.OptionPropertiesTest"), "the scan finds the option properties");
        assertEquals(List.of(), unselected(classes, suitePattern()),
                "test classes the launcher's pattern " + suitePattern() + " does not select (rename them)");
    }

    @Test
    void theSuitesPatternIsTheLaunchersDefault() {
        // Changing it in build.gradle is allowed, but then docs/outputs.md's naming rule must change with it.
        assertEquals(ClassNameFilter.STANDARD_INCLUDE_PATTERN, suitePattern().pattern());
    }

    /** Fixture sources: class name to source text, in package {@code fx}. */
    static final Map<String, String> FIXTURES = Map.ofEntries(
            Map.entry("Misnamed", "public class Misnamed { @Test void t() { } }"),
            Map.entry("GoodTest", "public class GoodTest { @Test void t() { } }"),
            Map.entry("TestsFirst", "public class TestsFirst { @Test void t() { } }"),
            Map.entry("Helper", "public class Helper { void t() { } }"),
            Map.entry("BaseChecks", "public abstract class BaseChecks { @Test void t() { } }"),
            Map.entry("Child", "public class Child extends BaseChecks { }"),
            Map.entry("ChildTest", "public class ChildTest extends BaseChecks { }"),
            Map.entry("Contract", "public interface Contract { @Test default void t() { } }"),
            Map.entry("Impl", "public class Impl implements Contract { }"),
            Map.entry("Outer", "public class Outer { @Nested class InnerTest { @Test void t() { } } }"),
            Map.entry("OuterTest", "public class OuterTest { @Nested class Inner { @Test void t() { } } }"),
            Map.entry("Holder", "public class Holder { static class Checks {"
                    + " @ParameterizedTest @ValueSource(ints = 1) void t(int i) { } } }"),
            Map.entry("Repeated", "public class Repeated { @RepeatedTest(2) void t() { } }"),
            Map.entry("Factory", "public class Factory { @TestFactory java.util.List<DynamicTest> t() {"
                    + " return java.util.List.of(); } }"));

    @Test
    void misnamedFixturesAreReported(@TempDir Path tmp) throws Exception {
        Path src = Files.createDirectories(tmp.resolve("src/fx"));
        Path out = Files.createDirectories(tmp.resolve("classes"));
        List<String> args = new ArrayList<>(List.of("-proc:none", "-d", out.toString(), "-cp",
                location(Test.class) + java.io.File.pathSeparator + location(ParameterizedTest.class)));
        for (var e : FIXTURES.entrySet()) {
            Path f = src.resolve(e.getKey() + ".java");
            Files.writeString(f, "package fx;\nimport org.junit.jupiter.api.*;\nimport org.junit.jupiter.params.*;\n"
                    + "import org.junit.jupiter.params.provider.*;\n" + e.getValue() + "\n");
            args.add(f.toString());
        }
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        assertNotNull(javac, "the tests run on a JDK");
        assertEquals(0, javac.run(null, null, null, args.toArray(String[]::new)), "the fixtures compile");
        try (URLClassLoader loader = new URLClassLoader(new URL[] {out.toUri().toURL()},
                SuiteSelectionTest.class.getClassLoader())) {
            Map<String, String> classes = testClasses(out, loader);
            assertEquals(new TreeSet<>(List.of("fx.Misnamed", "fx.GoodTest", "fx.TestsFirst", "fx.Child",
                    "fx.ChildTest", "fx.Impl", "fx.Outer$InnerTest", "fx.OuterTest$Inner", "fx.Holder$Checks",
                    "fx.Repeated", "fx.Factory")), classes.keySet(), "the classes holding tests");
            assertEquals(List.of("fx.Child", "fx.Factory", "fx.Holder$Checks", "fx.Impl", "fx.Misnamed",
                    "fx.Outer$InnerTest (seen as fx.Outer)", "fx.Repeated"),
                    unselected(classes, Pattern.compile(ClassNameFilter.STANDARD_INCLUDE_PATTERN)));
        }
    }
}

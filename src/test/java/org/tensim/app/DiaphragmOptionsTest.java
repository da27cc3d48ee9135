package org.tensim.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.app.gui.GuiCommand;
import org.tensim.io.Json;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.sweep.RunSetup;
import org.tensim.sweep.SpecReader;
import org.tensim.tuning.DiaphragmOptions;
import org.tensim.tuning.TunableScenes;
import picocli.CommandLine;

/**
 * The diaphragm has one option set: {@code tensim diaphragm}, {@code tensim gui} and the {@code "diaphragm"} object of
 * sweep and calibration specs take the same options by the same names, and the same values give the same
 * {@link DiaphragmSpec}.
 */
class DiaphragmOptionsTest {
    /** One non-default value per option; every option of the set must be here, and each must change the spec. */
    private static Map<String, Object> values(Path dir) throws Exception {
        Path mesh = Files.writeString(dir.resolve("d.obj"), "v 0 0 0\n");
        Path boxes = Files.writeString(dir.resolve("boxes.json"), "{}");
        Path labels = Files.writeString(dir.resolve("d.labels"), "tensim-labels 1\n");
        Path thorax = Files.createDirectories(dir.resolve("thorax"));
        Map<String, Object> v = new LinkedHashMap<>();
        v.put("mesh", mesh);
        v.put("units", "m");
        v.put("thickness", 3.0);
        v.put("rings", 12);
        v.put("thorax", thorax);
        v.put("cage", "surfaces");
        v.put("labels", labels);
        v.put("tendon-rule", "plane");
        v.put("contact", false);
        v.put("contact-stiffness", 7e7);
        v.put("liver-support", 2e4);
        v.put("abdominal-support", 1e5);
        v.put("abdominal-pressure", 300.0);
        v.put("apposition-pressure", 150.0);
        v.put("model", "default");
        v.put("rib-amplitude", 0.5);
        v.put("muscle-action", 2000.0);
        v.put("period", 5.0);
        v.put("ie-ratio", 1.5);
        v.put("expiratory-pause", 0.1);
        v.put("attach-threshold", 15.0);
        v.put("attachment", "paper-threshold");
        v.put("band-stiffness", 3e7);
        v.put("band-all-segments", true);
        v.put("muscle-load", "pressure");
        v.put("weld-tolerance", 0.01);
        v.put("min-piece-fraction", 0.02);
        v.put("tendon-normal", List.of(0.0, 0.1, 1.0));
        v.put("tendon-point", List.of(1.0, 2.0, 30.0));
        v.put("tendon-fraction", 0.2);
        v.put("tissue-model", "springs");
        v.put("action-line", List.of("10,20,40", "-10,20,40"));
        v.put("boxes", boxes); // with a thorax: refused together, checked apart below
        return v;
    }

    /** The command-line form of one option. */
    private static List<String> args(String name, Object value) {
        List<String> a = new ArrayList<>();
        if (value instanceof Boolean b) {
            a.add(b ? "--" + name : "--no-" + name);
        } else if (value instanceof List<?> l && !l.isEmpty() && l.get(0) instanceof Number) {
            a.add("--" + name);
            a.add(l.stream().map(String::valueOf).collect(Collectors.joining(",")));
        } else if (value instanceof List<?> l) {
            for (Object x : l) {
                a.add("--" + name);
                a.add(String.valueOf(x));
            }
        } else {
            a.add("--" + name);
            a.add(String.valueOf(value));
        }
        return a;
    }

    private static Set<String> optionNames(Object command) {
        return new CommandLine(command).getCommandSpec().options().stream()
                .flatMap(o -> java.util.Arrays.stream(o.names())).collect(Collectors.toCollection(TreeSet::new));
    }

    @Test
    void theCommandLineAndTheGuiHaveEveryOptionOfTheSet(@TempDir Path dir) throws Exception {
        Set<String> set = new TreeSet<>(DiaphragmOptions.names());
        assertEquals(new TreeSet<>(values(dir).keySet()), set, "the table above names every option of the set");
        Set<String> cli = optionNames(new DiaphragmCommand());
        Set<String> gui = optionNames(new GuiCommand());
        for (String n : set) {
            assertTrue(cli.contains("--" + n), "tensim diaphragm has --" + n);
            assertTrue(gui.contains("--" + n), "tensim gui has --" + n);
        }
    }

    @Test
    void eachOptionChangesTheSpecAndEveryWayInGivesTheSameSpec(@TempDir Path dir) throws Exception {
        Map<String, Object> v = values(dir);
        DiaphragmSpec defaults = DiaphragmOptions.parse(List.of()).spec(null, TunableScenes.defaultRings());
        // Options that mean something only beside another: units of a mesh file, action lines of a pressure load.
        Map<String, String> companion = Map.of("units", "mesh", "action-line", "muscle-load");
        for (Map.Entry<String, Object> e : v.entrySet()) {
            if (e.getKey().equals("model")) {
                continue; // "default" is the default; the paper's model is checked below
            }
            Map<String, Object> json = new LinkedHashMap<>();
            List<String> without = new ArrayList<>();
            String c = companion.get(e.getKey());
            if (c != null) {
                without.addAll(args(c, v.get(c)));
                json.put(c, v.get(c) instanceof Path p ? dir.relativize(p).toString() : v.get(c));
            }
            List<String> with = new ArrayList<>(without);
            with.addAll(args(e.getKey(), e.getValue()));
            json.put(e.getKey(), e.getValue() instanceof Path p ? dir.relativize(p).toString() : e.getValue());
            DiaphragmSpec cli = viaCommandLine(with);
            assertNotEquals(without.isEmpty() ? defaults : viaCommandLine(without), cli,
                    "--" + e.getKey() + " changes the spec");
            assertEquals(cli, viaGui(with), "the GUI reads --" + e.getKey() + " as the command line does");
            assertEquals(cli, viaSpecFile(dir, json), "a spec's \"diaphragm\": {\"" + e.getKey() + "\": ..} reads"
                    + " as --" + e.getKey());
        }
        // All of them together (boxes and thorax exclude each other).
        List<String> all = new ArrayList<>();
        Map<String, Object> json = new LinkedHashMap<>();
        for (Map.Entry<String, Object> e : v.entrySet()) {
            if (!e.getKey().equals("boxes")) {
                all.addAll(args(e.getKey(), e.getValue()));
                json.put(e.getKey(), e.getValue() instanceof Path p ? dir.relativize(p).toString() : e.getValue());
            }
        }
        DiaphragmSpec cli = viaCommandLine(all);
        assertEquals(cli, viaGui(all));
        assertEquals(cli, viaSpecFile(dir, json));
        assertEquals(v.get("thorax"), cli.cage().thorax());
        assertEquals(12, cli.mesh().rings());
    }

    @Test
    void theAbdominalSupportIsTheTissuesAndANegativeOneIsRefusedByName(@TempDir Path dir) throws Exception {
        DiaphragmSpec stiffer = viaCommandLine(List.of("--abdominal-support", "1e5"));
        assertEquals(1e5, stiffer.tissue().abdominalSupportPaPerM(), 0);
        assertEquals(stiffer, viaSpecFile(dir, Map.of("abdominal-support", 1e5)));
        assertEquals(0, viaCommandLine(List.of("--abdominal-support", "0")).tissue().abdominalSupportPaPerM(), 0,
                "0 turns it off");
        assertEquals(org.tensim.scene.diaphragm.DiaphragmParameters.DEFAULT_ABDOMINAL_SUPPORT_PA_PER_M,
                viaCommandLine(List.of()).tissue().abdominalSupportPaPerM(), 0);
        IllegalArgumentException bad = assertThrows(IllegalArgumentException.class,
                () -> viaCommandLine(List.of("--abdominal-support", "-5")));
        assertTrue(bad.getMessage().contains("--abdominal-support") && bad.getMessage().contains("-5")
                && bad.getMessage().contains("Pa/m"), bad.getMessage());
        assertEquals(300, viaCommandLine(List.of("--abdominal-pressure", "300")).breathing().abdominalPressurePa(), 0);
        IllegalArgumentException high = assertThrows(IllegalArgumentException.class,
                () -> viaCommandLine(List.of("--abdominal-pressure", "9000")));
        assertTrue(high.getMessage().contains("--abdominal-pressure") && high.getMessage().contains("9000")
                && high.getMessage().contains("0..5000"), high.getMessage());
        assertEquals(org.tensim.scene.diaphragm.DiaphragmSpec.Cage.DEFAULT_APPOSITION_PA,
                viaCommandLine(List.of()).cage().appositionPressurePa(), 0);
        assertEquals(0, viaCommandLine(List.of("--apposition-pressure", "0")).cage().appositionPressurePa(), 0,
                "0 turns it off");
        assertEquals(viaCommandLine(List.of("--apposition-pressure", "150")),
                viaSpecFile(dir, Map.of("apposition-pressure", 150.0)));
        IllegalArgumentException app = assertThrows(IllegalArgumentException.class,
                () -> viaCommandLine(List.of("--apposition-pressure", "-20")));
        assertTrue(app.getMessage().contains("--apposition-pressure") && app.getMessage().contains("-20")
                && app.getMessage().contains("0..5000"), app.getMessage());
    }

    @Test
    void theCageIsSegmentsOrSurfacesEverywhereAndAThoraxIsNeverSegments(@TempDir Path dir) throws Exception {
        DiaphragmSpec surfaces = viaCommandLine(List.of("--cage", "surfaces"));
        assertTrue(surfaces.cage().surfaces() && surfaces.cage().boneSurfaces() && surfaces.cage().thorax() == null);
        assertEquals(surfaces, viaGui(List.of("--cage", "surfaces")));
        assertEquals(surfaces, viaSpecFile(dir, Map.of("cage", "surfaces")));
        DiaphragmSpec segments = viaCommandLine(List.of("--cage", "segments"));
        assertEquals(DiaphragmOptions.parse(List.of()).spec(null, TunableScenes.defaultRings()), segments,
                "segments is the default");
        assertTrue(!segments.cage().boneSurfaces());
        IllegalArgumentException bad = assertThrows(IllegalArgumentException.class,
                () -> viaCommandLine(List.of("--cage", "tubes")));
        assertTrue(bad.getMessage().contains("--cage") && bad.getMessage().contains("tubes")
                && bad.getMessage().contains("surfaces"), bad.getMessage());
        Path thorax = Files.createDirectories(dir.resolve("thorax"));
        IllegalArgumentException both = assertThrows(IllegalArgumentException.class,
                () -> viaCommandLine(List.of("--cage", "segments", "--thorax", thorax.toString())));
        assertTrue(both.getMessage().contains("--cage segments") && both.getMessage().contains("--thorax"),
                both.getMessage());
        SpecReader.SpecException inSpec = assertThrows(SpecReader.SpecException.class,
                () -> viaSpecFile(dir, Map.of("cage", "tubes")));
        assertTrue(inSpec.getMessage().contains("tubes"), inSpec.getMessage());
        assertTrue(viaCommandLine(List.of("--thorax", thorax.toString())).cage().boneSurfaces(),
                "a thorax's bones are surfaces");
    }

    @Test
    void thePaperModelIsOneNameEverywhere(@TempDir Path dir) throws Exception {
        DiaphragmSpec paper = viaCommandLine(List.of("--model", "paper"));
        assertEquals(DiaphragmSpec.paper().boundary(), paper.boundary());
        assertEquals(DiaphragmSpec.paper().tissue(), paper.tissue());
        assertEquals(org.tensim.scene.diaphragm.TendonRule.PLANE, paper.tendonRule(), "the paper's plane tendon");
        assertEquals(org.tensim.scene.diaphragm.TendonRule.GEODESIC, viaCommandLine(List.of()).tendonRule(),
                "the default rule");
        assertEquals(org.tensim.scene.diaphragm.TendonRule.GEODESIC,
                viaCommandLine(List.of("--model", "paper", "--tendon-rule", "geodesic")).tendonRule(),
                "--tendon-rule overrides the paper's");
        assertEquals(paper, viaGui(List.of("--model", "paper")));
        assertEquals(paper, viaSpecFile(dir, Map.of("model", "paper")));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> viaCommandLine(List.of("--model", "paper", "--muscle-load", "fibres")));
        assertTrue(e.getMessage().contains("--muscle-load"), e.getMessage());
    }

    @Test
    void aBadValueInASpecFileIsRefusedNamingTheFieldAndTheValue(@TempDir Path dir) throws Exception {
        SpecReader.SpecException unknown = assertThrows(SpecReader.SpecException.class,
                () -> viaSpecFile(dir, Map.of("no-such-option", 1)));
        assertTrue(unknown.getMessage().contains("diaphragm.no-such-option")
                && unknown.getMessage().contains("muscle-load"), unknown.getMessage());
        SpecReader.SpecException bad = assertThrows(SpecReader.SpecException.class,
                () -> viaSpecFile(dir, Map.of("muscle-load", "bogus")));
        assertTrue(bad.getMessage().contains("bogus") && bad.getMessage().contains("spec.json"), bad.getMessage());
        SpecReader.SpecException missing = assertThrows(SpecReader.SpecException.class,
                () -> viaSpecFile(dir, Map.of("thorax", "nowhere")));
        assertTrue(missing.getMessage().contains("nowhere"), missing.getMessage());
        SpecReader.SpecException rings = assertThrows(SpecReader.SpecException.class,
                () -> viaSpecFile(dir, Map.of("rings", 3)));
        assertTrue(rings.getMessage().contains("--rings") && rings.getMessage().contains("3"), rings.getMessage());
    }

    private static DiaphragmSpec viaCommandLine(List<String> args) {
        DiaphragmCommand c = new DiaphragmCommand();
        new CommandLine(c).parseArgs(args.toArray(String[]::new));
        return c.scene.spec(null, TunableScenes.defaultRings());
    }

    private static DiaphragmSpec viaGui(List<String> args) throws Exception {
        GuiCommand g = new GuiCommand();
        new CommandLine(g).parseArgs(args.toArray(String[]::new));
        java.lang.reflect.Field f = GuiCommand.class.getDeclaredField("options");
        f.setAccessible(true);
        return ((DiaphragmOptions) f.get(g)).spec(null, TunableScenes.defaultRings());
    }

    private static DiaphragmSpec viaSpecFile(Path dir, Map<String, Object> diaphragm) throws Exception {
        ObjectNode root = Json.mapper().createObjectNode();
        root.put("scene", "diaphragm");
        root.set("diaphragm", Json.mapper().valueToTree(diaphragm));
        Path file = dir.resolve("spec.json");
        Files.writeString(file, root.toString());
        SpecReader r = new SpecReader(file);
        RunSetup s = r.setup(r.root(file));
        return s.diaphragmSpec();
    }
}

package org.tensim.scene.file;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.tensim.app.Main;
import picocli.CommandLine;

/**
 * {@code tensim check} on each malformed scene file of src/test/resources/scenes/bad: the usage exit code, one
 * message that starts with the file, line, column and key path where the fault is, says what is wrong, and no
 * stack trace.
 */
class MalformedScenesTest {
    static final Path BAD = Path.of("src/test/resources/scenes/bad");

    /** File checked; where the message must point (file:line:column: path); a part of what it must say. */
    static Stream<String[]> cases() {
        return Stream.of(new String[][] {
            {"syntax-yaml.yaml", "syntax-yaml.yaml:3:30: bodies.c.side", "syntax error: while parsing a flow"},
            {"syntax-json.json", "syntax-json.json:4:3: (top level)", "was expecting comma"},
            {"empty-file.yaml", "empty-file.yaml:1:1: (top level)", "the file is empty"},
            {"top-level-list.yaml", "top-level-list.yaml:1:1: (top level)", "expected a map of keys"},
            {"duplicate-key.yaml", "duplicate-key.yaml:11:1: probes", "given twice (first at duplicate-key.yaml:8:1)"},
            {"unknown-top-key.yaml", "unknown-top-key.yaml:2:1: bodys", "did you mean 'bodies'?"},
            {"unknown-body-key.yaml", "unknown-body-key.yaml:3:19: bodies.c.stifness", "did you mean 'stiffness'?"},
            {"unknown-body-type.yaml", "unknown-body-type.yaml:3:13: bodies.c.type", "did you mean 'cube'?"},
            {"unknown-integrator.yaml", "unknown-integrator.yaml:10:19: run.integrator", "did you mean 'rk2'?"},
            {"unknown-region-reference.yaml", "unknown-region-reference.yaml:7:27: conditions[0].region",
                "did you mean 'bottom'?"},
            {"unknown-law-reference.yaml", "unknown-law-reference.yaml:9:76: conditions[0].law",
                "did you mean 'wave'?"},
            {"unknown-probe-body.yaml", "unknown-probe-body.yaml:9:13: probes.p.body", "is not a body of this file"},
            {"stiffness-in-kpa.yaml", "stiffness-in-kpa.yaml:3:30: bodies.c.stiffness",
                "\"3 kPa\" is not a stiffness (expected a value in N/m"},
            {"force-in-kpa.yaml", "force-in-kpa.yaml:7:66: conditions[0].magnitude",
                "\"3 kPa\" is not a force (expected a value in N"},
            {"unknown-unit.yaml", "unknown-unit.yaml:3:25: bodies.c.side", "unknown unit \"parsecs\""},
            {"units-block-wrong-dimension.yaml", "units-block-wrong-dimension.yaml:2:17: units.length",
                "\"kg\" is not a length"},
            {"word-for-number.yaml", "word-for-number.yaml:3:30: bodies.c.node_mass", "\"heavy\" is not a mass"},
            {"list-for-value.yaml", "list-for-value.yaml:3:25: bodies.c.side", "a list is not a length"},
            {"boolean-for-length.yaml", "boolean-for-length.yaml:3:25: bodies.c.side", "\"true\" is not a length"},
            {"negative-stiffness.yaml", "negative-stiffness.yaml:3:30: bodies.c.stiffness", "must be > 0"},
            {"bad-element.yaml", "bad-element.yaml:3:28: bodies.c.element", "is not one of tensegrity"},
            {"missing-version.yaml", "missing-version.yaml:1:1: version", "the key is required at the top level"},
            {"bad-version.yaml", "bad-version.yaml:1:10: version", "not a version this program reads (expected 1)"},
            {"missing-run.yaml", "missing-run.yaml:1:1: run", "the key is required at the top level"},
            {"missing-dt.yaml", "missing-dt.yaml:10:6: run.dt", "the key is required in run"},
            {"step-longer-than-run.yaml", "step-longer-than-run.yaml:10:6: run", "longer than the run"},
            {"missing-law-file.yaml", "missing-law-file.yaml:5:28: laws.trace.file", "no such file"},
            {"missing-label-file.yaml", "missing-label-file.yaml:5:27: regions.bottom.labels.file", "no such file"},
            {"empty-region.yaml", "empty-region.yaml:5:11: regions.bottom", "selects no node of body 'c'"},
            {"index-out-of-range.yaml", "index-out-of-range.yaml:5:28: regions.bottom.indices[2]",
                "vertex 20 does not exist"},
            {"region-two-ways.yaml", "region-two-ways.yaml:5:11: regions.bottom", "more than one way"},
            {"region-cycle.yaml", "region-cycle.yaml:5:6: regions.a", "defined through itself (a -> b -> a)"},
            {"box-max-below-min.yaml", "box-max-below-min.yaml:5:39: regions.bottom.box.max", "max is below min"},
            {"probe-node-out-of-range.yaml", "probe-node-out-of-range.yaml:9:13: probes.p.node",
                "node 99 does not exist"},
            {"non-monotonic-table.yaml", "non-monotonic-table.yaml:7:35: laws.steps.points[2][0]",
                "times must increase"},
            {"fixed-and-driven.yaml", "fixed-and-driven.yaml:8:5: conditions[1]", "node 0 is fixed; it cannot also"
                + " be driven (body 'c', region 'bottom')"},
            {"unknown-condition-type.yaml", "unknown-condition-type.yaml:5:12: conditions[0].type",
                "is not one of fixed, force, gravity, motion"},
            {"unknown-region-in-union.yaml", "unknown-region-in-union.yaml:6:26: regions.both.union[1]",
                "\"tops\" is not a region of this file"},
            {"non-monotonic-csv-law.yaml", "non-monotonic.csv:4:1: laws.trace.file (non-monotonic.csv)",
                "times must increase"},
            {"expect-not-a-list.yaml", "expect-not-a-list.yaml:11:9: expect", "expected a list of checks"},
            {"expect-unknown-key.yaml", "expect-unknown-key.yaml:12:33: expect[0].betwen", "did you mean 'between'?"},
            {"expect-unknown-column.yaml", "expect-unknown-column.yaml:12:14: expect[0].column",
                "\"p_dy\" is not a column of this scene's CSV; did you mean 'p_dy_m'?"},
            {"expect-unknown-summary-key.yaml", "expect-unknown-summary-key.yaml:12:15: expect[0].summary",
                "\"step\" is not a number of this scene's summary; did you mean 'steps'?"},
            {"expect-column-and-summary.yaml", "expect-column-and-summary.yaml:12:5: expect[0]",
                "give either column"},
            {"expect-unknown-stat.yaml", "expect-unknown-stat.yaml:12:28: expect[0].stat",
                "\"minimum\" is not one of min, max, final, mean"},
            {"expect-missing-stat.yaml", "expect-missing-stat.yaml:12:5: expect[0].stat", "the key is required"},
            {"expect-pressure-for-length.yaml", "expect-pressure-for-length.yaml:12:57: expect[0].tolerance",
                "\"3 kPa\" is not a length (expected a value in m"},
            {"expect-range-reversed.yaml", "expect-range-reversed.yaml:12:48: expect[0].between[1]",
                "high \"-1 m\" is below low \"0 m\""},
            {"expect-value-without-tolerance.yaml", "expect-value-without-tolerance.yaml:12:5: expect[0].tolerance",
                "the key is required"},
            {"expect-both-ranges.yaml", "expect-both-ranges.yaml:12:5: expect[0]", "give either between"},
            {"expect-negative-tolerance.yaml", "expect-negative-tolerance.yaml:12:57: expect[0].tolerance",
                "a tolerance must be >= 0"},
            {"parameter-live-on-rebuild-key.yaml", "parameter-live-on-rebuild-key.yaml:10:63: parameters.side.apply",
                "parameter side is marked live, but bodies.c.side can only apply on rebuild"},
            {"parameter-live-cell-size.yaml", "parameter-live-cell-size.yaml:12:64: parameters.cell.apply",
                "bodies.v.cell can only apply on rebuild"},
            {"parameter-default-out-of-range.yaml", "parameter-default-out-of-range.yaml:10:51: parameters.k.range",
                "the default of parameter k, 100 N/m (bodies.c.stiffness at parameter-default-out-of-range.yaml:3:30),"
                    + " is outside its range [200, 400] N/m"},
            {"parameter-unit-wrong-dimension.yaml", "parameter-unit-wrong-dimension.yaml:10:39: parameters.k.unit",
                "\"kPa\" is not a unit of stiffness, the dimension of bodies.c.stiffness"},
            {"parameter-path-not-in-file.yaml", "parameter-path-not-in-file.yaml:10:13: parameters.m.path",
                "the file has no value at bodies.c.node_mass"},
            {"parameter-bad-apply.yaml", "parameter-bad-apply.yaml:10:69: parameters.k.apply",
                "\"later\" is not one of live, rebuild"},
            {"parameter-range-reversed.yaml", "parameter-range-reversed.yaml:10:57: parameters.k.range[1]",
                "the range's max \"10\" must be above its min \"400\""},
            {"parameter-not-a-quantity.yaml", "parameter-not-a-quantity.yaml:10:18: parameters.region.path",
                "conditions[0].region (parameter-not-a-quantity.yaml:7:27) is not a quantity this scene reads"},
            {"unknown-rigid-body.yaml", "unknown-rigid-body.yaml:8:43: conditions[0].with",
                "\"plat\" is not a rigid body of this file; did you mean 'plate'?"},
            {"contact-with-deformable.yaml", "contact-with-deformable.yaml:8:43: conditions[0].with",
                "body 'c' (type cube) carries no surface to touch: with: names a rigid body or a deformable body with a"
                + " surface"},
            {"region-on-rigid-body.yaml", "region-on-rigid-body.yaml:6:17: regions.under.body",
                "body 'plate' is rigid: it has no nodes"},
            {"pressure-no-face.yaml", "pressure-no-face.yaml:9:30: conditions[0].region",
                "region 'line' covers no face of body 'b''s surface"},
            {"surface-of-cube.yaml", "surface-of-cube.yaml:5:19: regions.skin.surface",
                "body 'c' (type cube) carries no surface"},
            {"rigid-two-surfaces.yaml", "rigid-two-surfaces.yaml:4:9: bodies.tool",
                "a rigid body needs exactly one surface"},
            {"helical-without-breathing.yaml", "helical-without-breathing.yaml:7:86: bodies.rib.motion.law",
                "the helical-axis rib law follows a breathing cycle"},
            {"shell-zone-modulus-not-pressure.yaml", "shell-zone-modulus-not-pressure.yaml:7:59: zones.scar.material.E",
                "\"80 N/m\" is not a pressure (expected a value in Pa"},
            {"region-unknown-part.yaml", "region-unknown-part.yaml:5:15: regions.top.part",
                "\"uper\" is not a part of body 's' (type shell); did you mean 'upper'? (its parts: upper, lower)"},
            {"region-part-of-cube.yaml", "region-part-of-cube.yaml:5:18: regions.tendon.part",
                "body 'c' (type cube) declares no parts"},
            {"fixed-unknown-axis.yaml", "fixed-unknown-axis.yaml:7:45: conditions[0].axes[1]",
                "\"w\" is not an axis (expected x, y or z)"},
            {"force-magnitude-and-total.yaml", "force-magnitude-and-total.yaml:7:5: conditions[0]",
                "give either magnitude (N on each node) or total (N split over the region's nodes), not both"},
            {"diaphragm-expect-column.yaml", "diaphragm-expect-column.yaml:6:14: expect[0].column",
                "this scene's run writes no CSV columns: check its summary instead (summary: KEY; keys:"
                    + " dome_excursion_mm"},
            {"diaphragm-zones.yaml", "diaphragm-zones.yaml:7:3: zones",
                "a diaphragm body brings its own tissues (its own keys set them): its file has no zones block"},
            {"diaphragm-contact-condition.yaml", "diaphragm-contact-condition.yaml:7:12: conditions[0].type",
                "a contact condition cannot act on body 'd' (type diaphragm): the diaphragm's contacts are its own"},
            {"diaphragm-beside-rigid.yaml", "diaphragm-beside-rigid.yaml:3:3: bodies",
                "a diaphragm body brings its own supports, bones and loads and is a file's only body; got [d, liver]"},
            {"attachment-bad-mode.yaml", "attachment-bad-mode.yaml:8:75: conditions[0].mode",
                "\"tied\" is not one of drive, fix, tie, band; did you mean 'tie'?"},
            {"attachment-stiffness-without-tie.yaml", "attachment-stiffness-without-tie.yaml:8:80:"
                + " conditions[0].stiffness", "stiffness goes with mode: tie (a spring to the rigid body); mode drive"
                + " has none"},
        });
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void checkRefusesWithPlaceAndPathAndNoStackTrace(String file, String where, String says) {
        String[] r = check(BAD.resolve(file).toString());
        assertEquals("2", r[0], "exit code of check " + file + "; stderr: " + r[1]);
        String msg = r[1].strip();
        assertTrue(msg.startsWith("tensim check: " + where + ": "), "message names " + where + ":\n" + msg);
        assertTrue(msg.contains(says), "message says " + says + ":\n" + msg);
        assertFalse(msg.contains("\n"), "one line:\n" + msg);
        assertFalse(msg.contains("\tat ") || msg.contains("Exception") || msg.contains("internal error"),
                "no stack trace or exception name:\n" + msg);
    }

    /** Every fixture scene file is among the cases (a new fixture without an expectation would go untested). */
    @Test
    void everyFixtureIsChecked() throws IOException {
        Set<String> listed = cases().map(c -> c[0]).collect(Collectors.toCollection(TreeSet::new));
        Set<String> files;
        try (Stream<Path> s = Files.list(BAD)) {
            files = s.map(p -> p.getFileName().toString()).filter(n -> n.matches(".*\\.(yaml|json)"))
                    .collect(Collectors.toCollection(TreeSet::new));
        }
        assertEquals(files, listed);
        assertTrue(listed.size() >= 25, "at least 25 malformed scenes: " + listed.size());
    }

    /** Runs {@code tensim check FILE} in this JVM: exit code, then everything written to stderr. */
    static String[] check(String file) {
        CommandLine cl = Main.commandLine();
        StringWriter err = new StringWriter();
        cl.setOut(new PrintWriter(new StringWriter()));
        cl.setErr(new PrintWriter(err, true));
        PrintStream before = System.err;
        ByteArrayOutputStream raw = new ByteArrayOutputStream();
        int code;
        System.setErr(new PrintStream(raw, true, StandardCharsets.UTF_8));
        try {
            code = cl.execute("check", file);
        } finally {
            System.setErr(before);
        }
        return new String[] {String.valueOf(code), err + raw.toString(StandardCharsets.UTF_8)};
    }
}

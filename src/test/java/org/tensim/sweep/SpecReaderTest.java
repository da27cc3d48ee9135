package org.tensim.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Bad sweep specs are refused before any run, naming the field; good ones are read as written. */
class SpecReaderTest {
    @TempDir
    Path dir;

    private Path spec(String json) throws IOException {
        Path f = dir.resolve("s.json");
        Files.writeString(f, json);
        return f;
    }

    @Test
    void readsAGridSpec() throws Exception {
        SweepSpec s = SpecReader.readSweep(spec("{\"scene\": \"cube\", \"parameters\": {"
                + "\"forceAmplitudeN\": {\"min\": 100, \"max\": 400, \"steps\": 4},"
                + "\"stiffnessNPerM\": {\"values\": [300, 1000]}}, \"fixed\": {\"dampingNsPerM\": 2},"
                + "\"solver\": {\"seconds\": 0.5, \"dtS\": 0.002}, \"outputs\": [\"mss_peak_y_m\"]}"));
        assertEquals(java.util.List.of("forceAmplitudeN", "stiffnessNPerM"), s.parameterNames());
        assertEquals(8, SweepPoints.of(s).size());
        assertEquals(0.002, s.setup().dtS());
        assertEquals(0.5, s.setup().seconds());
        assertEquals(2.0, s.fixed().get("dampingNsPerM"));
        assertEquals(java.util.List.of("mss_peak_y_m"), s.outputs());
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
        // what is wrong | parameters and extras | field the message must name
        "unknown parameter | \"parameters\": {\"stiffnes\": {\"min\": 1, \"max\": 2, \"steps\": 2}} | parameters.stiffnes",
        "empty range | \"parameters\": {\"stiffnessNPerM\": {\"min\": 500, \"max\": 100, \"steps\": 2}} | parameters.stiffnessNPerM",
        "empty value list | \"parameters\": {\"stiffnessNPerM\": {\"values\": []}} | parameters.stiffnessNPerM.values",
        "bound below range | \"parameters\": {\"stiffnessNPerM\": {\"min\": 1, \"max\": 100, \"steps\": 2}} | parameters.stiffnessNPerM.min",
        "bound above range | \"parameters\": {\"forceAmplitudeN\": {\"min\": 1, \"max\": 1e5, \"steps\": 2}} | parameters.forceAmplitudeN.max",
        "non-finite bound | \"parameters\": {\"forceAmplitudeN\": {\"min\": 1, \"max\": 1e999, \"steps\": 2}} | parameters.forceAmplitudeN.max",
        "bound as text | \"parameters\": {\"forceAmplitudeN\": {\"min\": \"1\", \"max\": 2, \"steps\": 2}} | parameters.forceAmplitudeN.min",
        "no steps | \"parameters\": {\"forceAmplitudeN\": {\"min\": 1, \"max\": 2}} | parameters.forceAmplitudeN.steps",
        "lhs without points | \"parameters\": {\"forceAmplitudeN\": {\"min\": 1, \"max\": 2}}, \"sampling\": {\"method\": \"lhs\"} | sampling.points",
        "unknown field | \"parameters\": {\"forceAmplitudeN\": {\"values\": [1]}}, \"solverr\": {} | solverr",
        "fixed out of range | \"parameters\": {\"forceAmplitudeN\": {\"values\": [1]}}, \"fixed\": {\"dampingNsPerM\": -1} | fixed.dampingNsPerM",
        "unknown integrator | \"parameters\": {\"forceAmplitudeN\": {\"values\": [1]}}, \"solver\": {\"integrator\": \"rk9\"} | solver.integrator",
        "negative seconds | \"parameters\": {\"forceAmplitudeN\": {\"values\": [1]}}, \"solver\": {\"seconds\": -1} | solver.seconds",
        "mesh on the cube | \"parameters\": {\"forceAmplitudeN\": {\"values\": [1]}}, \"mesh\": {\"rings\": 8} | mesh",
        "muscle load on the cube | \"parameters\": {\"forceAmplitudeN\": {\"values\": [1]}}, \"muscleLoad\": \"fibres\" | muscleLoad",
    })
    void refusesNamingTheField(String what, String body, String field) throws IOException {
        String outputs = "\"outputs\": [\"mss_peak_y_m\"]";
        Path f = spec("{\"scene\": \"cube\", " + body + ", " + outputs + "}");
        SpecReader.SpecException e = assertThrows(SpecReader.SpecException.class, () -> SpecReader.readSweep(f), what);
        assertTrue(e.getMessage().contains("'" + field + "'"), what + ": message names " + field + ": "
                + e.getMessage());
        assertTrue(e.getMessage().startsWith(f.toString()), "message names the file: " + e.getMessage());
    }

    @Test
    void readsTheDiaphragmsMuscleLoadAndRefusesAnUnknownOne() throws Exception {
        String body = "\"scene\": \"diaphragm\", \"mesh\": {\"rings\": 6}, \"parameters\":"
                + " {\"muscleActionPa\": {\"values\": [15000]}}, \"outputs\": [\"dome_excursion_mm\"]";
        assertEquals(org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad.FIBRES, SpecReader.readSweep(spec("{" + body
                + ", \"muscleLoad\": \"fibres\"}")).setup()
                .muscleLoad());
        assertEquals(org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad.FIBRES,
                SpecReader.readSweep(spec("{" + body + "}")).setup().muscleLoad(), "the default");
        Path f = spec("{" + body + ", \"muscleLoad\": \"fibers\"}");
        String m = assertThrows(SpecReader.SpecException.class, () -> SpecReader.readSweep(f)).getMessage();
        assertTrue(m.contains("'muscleLoad'") && m.contains("fibres") && m.contains("pressure"), m);
    }

    @Test
    void refusesAnUnknownOutputAndAMissingMesh() throws IOException {
        Path f = spec("{\"scene\": \"cube\", \"parameters\": {\"forceAmplitudeN\": {\"values\": [1]}},"
                + " \"outputs\": [\"dome_excursion_mm\"]}");
        assertTrue(assertThrows(SpecReader.SpecException.class, () -> SpecReader.readSweep(f)).getMessage()
                .contains("'outputs[0]'"));
        Path g = spec("{\"scene\": \"diaphragm\", \"mesh\": {\"file\": \"nope.obj\"}, \"parameters\":"
                + " {\"muscleActionPa\": {\"values\": [1]}}, \"outputs\": [\"dome_excursion_mm\"]}");
        assertTrue(assertThrows(SpecReader.SpecException.class, () -> SpecReader.readSweep(g)).getMessage()
                .contains("'mesh.file'"));
    }
}

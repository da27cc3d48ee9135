package org.tensim.io.mesh;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.scene.diaphragm.DoubleDomeGenerator;

/** Geometry checks: stray vertices and sizes that do not fit the declared units are refused, with advice. */
class MeshExtentTest {
    @TempDir
    Path dir;

    private Path dome(MeshUnits writtenIn) throws Exception {
        Path p = dir.resolve("dome-" + writtenIn + ".obj");
        ObjWriter.write(p, DoubleDomeGenerator.shell(DoubleDomeGenerator.Shape.adult().withRings(6)), writtenIn,
                List.of(), 6);
        return p;
    }

    @Test
    void aMetreFileReadAsMillimetresIsRefusedWithTheSizeAndTheRightUnits() throws Exception {
        Path m = dome(MeshUnits.M);
        TriangleMesh asMm = MeshLoader.load(m, MeshUnits.MM).mesh();
        MeshFormatException e = assertThrows(MeshFormatException.class,
                () -> MeshExtent.refuseImplausibleSize(asMm, m, MeshUnits.MM, "diaphragm", 0.08, 1.0));
        assertTrue(e.getMessage().contains(m.getFileName().toString()), e.getMessage());
        assertTrue(e.getMessage().contains("measures 0.2") && e.getMessage().contains("use --units m"),
                e.getMessage());
        Path mm = dome(MeshUnits.MM);
        TriangleMesh asM = MeshLoader.load(mm, MeshUnits.M).mesh();
        MeshFormatException f = assertThrows(MeshFormatException.class,
                () -> MeshExtent.refuseImplausibleSize(asM, mm, MeshUnits.M, "diaphragm", 0.08, 1.0));
        assertTrue(f.getMessage().contains("use --units mm"), f.getMessage());
        TriangleMesh right = MeshLoader.load(mm, MeshUnits.MM).mesh();
        assertDoesNotThrow(() -> MeshExtent.refuseImplausibleSize(right, mm, MeshUnits.MM, "diaphragm", 0.08, 1.0));
    }

    @Test
    void aStrayVertexFarAwayIsRefusedNotDropped() throws Exception {
        for (String far : new String[] {"2e6", "1e300", "-1e300"}) {
            Path p = dir.resolve("stray.obj");
            String text = Files.readString(dome(MeshUnits.MM));
            // One vertex of the first triangle moved far away (a km or 1e300 mm).
            int at = text.startsWith("v ") ? 0 : text.indexOf("\nv ") + 1;
            int end = text.indexOf('\n', at);
            Files.writeString(p, text.substring(0, at) + "v " + far + " 0 0" + text.substring(end));
            MeshFormatException e = assertThrows(MeshFormatException.class, () -> MeshLoader.load(p, MeshUnits.MM),
                    far);
            assertTrue(e.getMessage().contains("stray.obj") && e.getMessage().contains("vertex 1 ")
                    && e.getMessage().contains("far from the rest"), e.getMessage());
        }
    }
}

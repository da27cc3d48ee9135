package org.tensim.io.thorax;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.io.ProjectFolder;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.io.thorax.ThoraxPart.Group;
import org.tensim.io.thorax.ThoraxPart.Side;

class ThoraxLoaderTest {
    private static final Path SHARED = ProjectFolder.resolve("..", "shared", "meshes", "thorax");

    @TempDir
    Path tmp;

    private static Path shared() {
        Assumptions.assumeTrue(Files.isRegularFile(SHARED.resolve("parts.json")),
                SHARED.resolve("parts.json").toAbsolutePath() + " not found");
        return SHARED;
    }

    @Test
    void theSharedThoraxHasTheWholeSkeletonInMetres() throws IOException {
        Thorax t = ThoraxLoader.load(shared());
        List<ThoraxPart> ribs = t.group(Group.RIB);
        assertEquals(24, ribs.size(), "ribs");
        for (Side s : new Side[] {Side.LEFT, Side.RIGHT}) {
            assertEquals(numbers(1, 12), t.group(Group.RIB, s).stream().map(ThoraxPart::index)
                    .collect(Collectors.toCollection(TreeSet::new)), s + " rib numbers");
            assertEquals(numbers(1, 10), t.group(Group.CARTILAGE, s).stream().map(ThoraxPart::index)
                    .collect(Collectors.toCollection(TreeSet::new)), s + " cartilage numbers");
        }
        assertEquals(20, t.group(Group.CARTILAGE).size(), "cartilages");
        assertEquals(3, t.group(Group.STERNUM).size(), "sternum parts");
        assertEquals(Set.of("T10", "T11", "T12", "L1", "L2", "L3"),
                t.group(Group.VERTEBRA).stream().map(ThoraxPart::level).collect(Collectors.toSet()));
        assertEquals(1, t.group(Group.LIVER).size(), "the liver is loaded by default");
        assertTrue(t.group(Group.LUNG).isEmpty() && t.group(Group.PLEURA).isEmpty() && t.group(Group.OTHER).isEmpty(),
                "lungs, pleura and the second diaphragm are skipped by default");
        assertTrue(t.frame().contains("millimetres"), t.frame());

        // metres: the rib cage is 0.2-0.4 m wide and 0.2-0.5 m tall
        double[] cage = t.bounds(Group.RIB);
        double width = cage[3] - cage[0];
        assertTrue(width > 0.2 && width < 0.4, "rib cage width " + width + " m");
        double height = cage[5] - cage[2];
        assertTrue(height > 0.2 && height < 0.5, "rib cage height " + height + " m");

        // the frame: +x is the patient's left, +z superior; ribs descend with their number
        for (int n = 1; n <= 12; n++) {
            double[] l = t.rib(Side.LEFT, n).orElseThrow().mesh().bounds();
            double[] r = t.rib(Side.RIGHT, n).orElseThrow().mesh().bounds();
            assertTrue(l[0] + l[3] > 0 && r[0] + r[3] < 0, "rib " + n + ": left at +x, right at -x");
            if (n > 1) {
                double[] above = t.rib(Side.LEFT, n - 1).orElseThrow().mesh().bounds();
                assertTrue(l[5] < above[5], "rib " + n + "'s top lies below rib " + (n - 1) + "'s");
            }
        }
        assertTrue(t.vertebra("T10").orElseThrow().mesh().bounds()[5]
                > t.vertebra("L3").orElseThrow().mesh().bounds()[5], "T10 above L3");
        assertEquals("rib-r9", t.part("rib-r9").name());
        assertEquals(Side.RIGHT, t.part("costal-cartilage-r7").side());
    }

    @Test
    void loadsOnlyTheGroupsAskedFor() throws IOException {
        Thorax bones = ThoraxLoader.load(shared(), EnumSet.of(Group.VERTEBRA, Group.STERNUM));
        assertEquals(9, bones.parts().size());
        assertTrue(bones.find("rib-l1").isEmpty());
        Thorax organs = ThoraxLoader.load(shared(), EnumSet.of(Group.LUNG, Group.PLEURA, Group.OTHER));
        assertEquals(5, organs.group(Group.LUNG).size(), "lobes");
        assertEquals(1, organs.group(Group.PLEURA).size());
        assertEquals("diaphragm-zanatomy", organs.group(Group.OTHER).get(0).name());
    }

    @Test
    void refusesAPartThatNamesAMissingFile() throws IOException {
        writeTetra("rib-r1.obj", 1);
        Path json = writeParts("", rib("rib-r1.obj", "1", "") + ",\n" + rib("rib-r2.obj", "2", ""));
        IOException e = assertThrows(IOException.class, () -> ThoraxLoader.load(tmp));
        assertNames(e, json, "parts[1]", "rib-r2.obj");
        assertTrue(e.getMessage().contains("missing file"), e.getMessage());
    }

    @Test
    void refusesARibWithoutItsNumber() throws IOException {
        writeTetra("rib-r1.obj", 1);
        writeTetra("rib-r2.obj", 1);
        Path json = writeParts("", rib("rib-r1.obj", "1", "") + ",\n"
                + "{\"file\": \"rib-r2.obj\", \"group\": \"rib\", \"side\": \"right\"}");
        IOException e = assertThrows(IOException.class, () -> ThoraxLoader.load(tmp));
        assertNames(e, json, "parts[1]", "rib-r2.obj");
        assertTrue(e.getMessage().contains("without its number") && e.getMessage().contains("1-12"), e.getMessage());
    }

    @Test
    void refusesAPartDeclaredInOtherUnits() throws IOException {
        writeTetra("rib-r1.obj", 1);
        writeTetra("rib-r2.obj", 1);
        Path json = writeParts("", rib("rib-r1.obj", "1", "") + ",\n" + rib("rib-r2.obj", "2", ", \"units\": \"m\""));
        IOException e = assertThrows(IOException.class, () -> ThoraxLoader.load(tmp));
        assertNames(e, json, "parts[1]", "rib-r2.obj");
        assertTrue(e.getMessage().contains("'m'") && e.getMessage().contains("'mm'"), e.getMessage());

        writeParts("\"units\": \"inch\",", rib("rib-r1.obj", "1", ""));
        IOException inch = assertThrows(IOException.class, () -> ThoraxLoader.load(tmp));
        assertTrue(inch.getMessage().contains("\"inch\"") && inch.getMessage().contains("\"mm\" or \"m\""),
                inch.getMessage());
    }

    @Test
    void refusesAMeshWrittenInMetresUnderMillimetres() throws IOException {
        writeTetra("rib-r1.obj", 1);
        writeTetra("rib-r2.obj", 1e-3); // the same 10 mm tetrahedron, written in metres
        Path json = writeParts("", rib("rib-r1.obj", "1", "") + ",\n" + rib("rib-r2.obj", "2", ""));
        IOException e = assertThrows(IOException.class, () -> ThoraxLoader.load(tmp));
        assertNames(e, json, "parts[1]", "rib-r2.obj");
        assertTrue(e.getMessage().contains("bounds_mm") && e.getMessage().contains("0.001"), e.getMessage());
    }

    @Test
    void refusesAnUnknownGroupListingTheKnownOnes() throws IOException {
        writeTetra("clavicle.obj", 1);
        Path json = writeParts("", "{\"file\": \"clavicle.obj\", \"group\": \"clavicle\"}");
        IOException e = assertThrows(IOException.class, () -> ThoraxLoader.load(tmp));
        assertNames(e, json, "parts[0]", "clavicle.obj");
        assertTrue(e.getMessage().contains("rib, cartilage, sternum, vertebra"), e.getMessage());
    }

    @Test
    void readsASmallThoraxInMetresWhenDeclared() throws IOException {
        writeTetra("rib-l3.obj", 1e-3);
        writeParts("\"units\": \"m\",", rib("rib-l3.obj", "3", "").replace("right", "left"));
        Thorax t = ThoraxLoader.load(tmp);
        double[] b = t.rib(Side.LEFT, 3).orElseThrow().mesh().bounds();
        assertEquals(0.010, b[3] - b[0], 1e-12, "10 mm tetrahedron, m");
        assertEquals(MeshUnits.M, t.fileUnits(), "the units declared in parts.json");
    }

    private static Set<Integer> numbers(int from, int to) {
        Set<Integer> s = new TreeSet<>();
        for (int i = from; i <= to; i++) {
            s.add(i);
        }
        return s;
    }

    private static void assertNames(IOException e, Path json, String entry, String file) {
        String m = e.getMessage();
        assertTrue(m.contains(json.toString()) && m.contains(entry) && m.contains(file),
                "message should name " + json + ", " + entry + " and " + file + ": " + m);
    }

    /** A rib entry whose bounds_mm are those of {@link #writeTetra}'s 10 mm tetrahedron. */
    private static String rib(String file, String index, String extra) {
        return "{\"file\": \"" + file + "\", \"group\": \"rib\", \"side\": \"right\", \"index\": " + index
                + ", \"bounds_mm\": [[0, 0, 0], [10, 10, 10]]" + extra + "}";
    }

    private Path writeParts(String top, String entries) throws IOException {
        Path json = tmp.resolve("parts.json");
        Files.writeString(json, "{\"frame\": \"test frame, millimetres\", " + top + "\n\"parts\": [\n" + entries
                + "\n]}\n");
        return json;
    }

    /** A tetrahedron with legs of 10 mm, coordinates written times {@code scale} (1: mm, 1e-3: m). */
    private void writeTetra(String name, double scale) throws IOException {
        double s = 10 * scale;
        Files.writeString(tmp.resolve(name), "v 0 0 0\nv " + s + " 0 0\nv 0 " + s + " 0\nv 0 0 " + s + "\n"
                + "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    }
}

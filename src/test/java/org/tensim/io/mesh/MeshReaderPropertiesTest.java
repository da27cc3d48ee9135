package org.tensim.io.mesh;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tensim.RandomCases;

/**
 * Property-based tests ({@link RandomCases}: many seeded random cases) of the mesh readers and the loader: a damaged file
 * (truncated anywhere, a byte changed anywhere, a huge count, a non-finite or
 * enormous value) is either refused with a {@link MeshFormatException} naming the
 * file, or read into a valid mesh (finite coordinates, corners that exist). No other
 * exception ever escapes.
 */
class MeshReaderPropertiesTest {
    enum Format { OBJ, OFF, STL_ASCII, STL_BINARY }

    @TempDir
    Path dir;

    /** A closed octahedron, scaled and moved: a small valid mesh in each format. */
    static byte[] valid(Format f, double scale, double shift) {
        double[][] v = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        int[][] t = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
        StringBuilder b = new StringBuilder();
        switch (f) {
            case OBJ -> {
                b.append("# octahedron\n");
                for (double[] p : v) {
                    b.append(String.format(Locale.ROOT, "v %.6f %.6f %.6f%n", shift + scale * p[0],
                            shift + scale * p[1], shift + scale * p[2]));
                }
                for (int[] c : t) {
                    b.append("f ").append(c[0] + 1).append(' ').append(c[1] + 1).append(' ').append(c[2] + 1)
                            .append('\n');
                }
            }
            case OFF -> {
                b.append("OFF\n").append(v.length).append(' ').append(t.length).append(" 0\n");
                for (double[] p : v) {
                    b.append(String.format(Locale.ROOT, "%.6f %.6f %.6f%n", shift + scale * p[0],
                            shift + scale * p[1], shift + scale * p[2]));
                }
                for (int[] c : t) {
                    b.append("3 ").append(c[0]).append(' ').append(c[1]).append(' ').append(c[2]).append('\n');
                }
            }
            case STL_ASCII -> {
                b.append("solid octa\n");
                for (int[] c : t) {
                    b.append("facet normal 0 0 0\nouter loop\n");
                    for (int k : c) {
                        b.append(String.format(Locale.ROOT, "vertex %.6f %.6f %.6f%n", shift + scale * v[k][0],
                                shift + scale * v[k][1], shift + scale * v[k][2]));
                    }
                    b.append("endloop\nendfacet\n");
                }
                b.append("endsolid octa\n");
            }
            case STL_BINARY -> {
                ByteBuffer bb = ByteBuffer.allocate(84 + 50 * t.length).order(ByteOrder.LITTLE_ENDIAN);
                bb.position(80);
                bb.putInt(t.length);
                for (int[] c : t) {
                    bb.putFloat(0).putFloat(0).putFloat(0);
                    for (int k : c) {
                        for (int a = 0; a < 3; a++) {
                            bb.putFloat((float) (shift + scale * v[k][a]));
                        }
                    }
                    bb.putShort((short) 0);
                }
                return bb.array();
            }
            default -> throw new IllegalStateException();
        }
        return b.toString().getBytes(StandardCharsets.US_ASCII);
    }

    private Path file(Format f, byte[] bytes) throws IOException {
        String ext = f == Format.OBJ ? ".obj" : f == Format.OFF ? ".off" : ".stl";
        Path p = Files.createTempFile(dir, "m", ext);
        Files.write(p, bytes);
        return p;
    }

    /** Reading and loading give a valid mesh or a MeshFormatException naming the file; nothing else. */
    static void refusedOrValid(Path file) throws IOException {
        for (int pass = 0; pass < 2; pass++) {
            try {
                TriangleMesh m = pass == 0 ? MeshReaders.read(file, MeshUnits.MM)
                        : MeshLoader.load(file, MeshUnits.MM).mesh();
                assertTrue(m.vertexCount() > 0 && m.triangleCount() > 0, "a mesh has vertices and triangles");
                for (int i = 0; i < m.vertexCount(); i++) {
                    for (int a = 0; a < 3; a++) {
                        assertTrue(Double.isFinite(m.coord(i, a)), "finite coordinates");
                    }
                }
                for (int t = 0; t < m.triangleCount(); t++) {
                    for (int k = 0; k < 3; k++) {
                        int c = m.corner(t, k);
                        assertTrue(c >= 0 && c < m.vertexCount(), "corner " + c + " exists");
                    }
                }
            } catch (MeshFormatException e) {
                assertTrue(e.getMessage().contains(file.getFileName().toString()), "names the file: " + e.getMessage());
            }
        }
    }

    private static Format anyFormat(SplittableRandom r) {
        return RandomCases.oneOf(r, Format.values());
    }

    @Test
    void truncatedAnywhere() throws Exception {
        RandomCases.check("truncated", 150, r -> {
            Format f = anyFormat(r);
            byte[] b = valid(f, 100, 10);
            refusedOrValid(file(f, java.util.Arrays.copyOf(b, r.nextInt(b.length + 1))));
        });
    }

    @Test
    void bytesChangedAnywhere() throws Exception {
        RandomCases.check("bytes changed", 250, r -> {
            Format f = anyFormat(r);
            byte[] b = valid(f, 100, 10);
            int count = 1 + r.nextInt(4);
            for (int i = 0; i < count; i++) {
                b[r.nextInt(b.length)] = (byte) r.nextInt(256);
            }
            refusedOrValid(file(f, b));
        });
    }

    /** Numbers no mesh file may hold where a coordinate, a count or an index stands. */
    static final String[] BAD_NUMBERS = {"nan", "NaN", "inf", "-Infinity", "1e400", "-1e999", "1e300", "-1e300",
        "99999999999", "2147483648", "-2147483649", "0x1p3", "1,5", "", "--1"};

    /** A number of the text formats (a coordinate, a count or an index) replaced by a bad or huge one. */
    @Test
    void aNumberReplacedByANonFiniteOrHugeOne() throws Exception {
        RandomCases.check("number replaced", 300, r -> {
            Format f = RandomCases.oneOf(r, Format.OBJ, Format.OFF, Format.STL_ASCII);
            String bad = RandomCases.oneOf(r, BAD_NUMBERS);
            String text = new String(valid(f, 100, 10), StandardCharsets.US_ASCII);
            java.util.regex.Matcher m = java.util.regex.Pattern.compile("-?[0-9]+(\\.[0-9]+)?").matcher(text);
            int which = r.nextInt(80);
            int i = 0;
            StringBuilder out = new StringBuilder();
            while (m.find()) {
                m.appendReplacement(out, i++ == which ? java.util.regex.Matcher.quoteReplacement(bad) : m.group());
            }
            m.appendTail(out);
            refusedOrValid(file(f, out.toString().getBytes(StandardCharsets.US_ASCII)));
        });
    }

    /** A binary STL whose triangle count or one of its floats is replaced by any 32-bit pattern. */
    @Test
    void binaryStlCountsAndFloatsReplaced() throws Exception {
        RandomCases.check("binary STL", 200, r -> {
            byte[] b = valid(Format.STL_BINARY, 100, 10);
            ByteBuffer bb = ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN);
            int which = r.nextInt(97); // 0: the count; 1..96: one of the 8 x 12 floats (normals and corners)
            int pos = which == 0 ? 80 : 84 + 50 * ((which - 1) / 12) + 4 * ((which - 1) % 12);
            int pattern = RandomCases.oneOf(r, r.nextInt(), Float.floatToIntBits(Float.NaN), 0x7f800000,
                    Float.floatToIntBits(3e38f), -1, Integer.MAX_VALUE);
            bb.putInt(pos, pattern);
            refusedOrValid(file(Format.STL_BINARY, b));
        });
    }

    /** OFF headers that declare enormous counts are refused quickly (no allocation of the count). */
    @Test
    void hugeOffCounts() throws Exception {
        RandomCases.check("huge OFF counts", 50, r -> {
            int vertices = 7 + r.nextInt(Integer.MAX_VALUE - 7);
            int faces = 9 + r.nextInt(Integer.MAX_VALUE - 9);
            String text = new String(valid(Format.OFF, 1, 0), StandardCharsets.US_ASCII)
                    .replaceFirst("6 8 0", vertices + " " + faces + " 0");
            refusedOrValid(file(Format.OFF, text.getBytes(StandardCharsets.US_ASCII)));
        });
    }
}

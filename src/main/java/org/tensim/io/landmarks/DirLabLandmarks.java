package org.tensim.io.landmarks;

import com.fasterxml.jackson.databind.MappingIterator;
import com.fasterxml.jackson.dataformat.csv.CsvMapper;
import com.fasterxml.jackson.dataformat.csv.CsvParser;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;

/**
 * DIR-Lab's expert landmarks on the 4D-CT of five patients breathing freely (Castillo et al. 2009, Phys Med Biol
 * 54: 1849-1870; the six-phase sets Castillo et al. 2010, Phys Med Biol 55: 305-327), as the shared folder
 * {@code ../shared/data/4dct-lung-landmarks} holds them (its ATTRIBUTION.md gives the sources and the licence):
 * <ul>
 * <li>{@code caseN-300-ee-ei.csv}: 300 landmarks at end-exhale and end-inhale, columns {@code landmark, ee_x_mm,
 * ee_y_mm, ee_z_mm, ei_x_mm, ei_y_mm, ei_z_mm}; phases {@code ee}, {@code ei};</li>
 * <li>{@code caseN-75-six-phases.csv}: 75 landmarks at six phases, {@code t00} (end-inhale) to {@code t50}
 * (end-exhale) in tenths of the cycle, columns {@code landmark}, then {@code tPP_x_mm, tPP_y_mm, tPP_z_mm}.</li>
 * </ul>
 * Coordinates are millimetres in each scan's image frame ({@code (voxel index - 1) x voxel size}); they come out in
 * metres, in the same frame. Its z is the slice axis and increases towards the feet, so the set's superior
 * direction is {@code (0, 0, -1)}; x and y are the scan's in-plane axes. Every case is its own person and frame.
 *
 * <p>A file is refused with its name, the line and what was expected: a header other than the one above, a row
 * of another number of columns, a field that is not a finite number, a landmark number that is not a whole number
 * or repeats, or a file without rows.
 */
public final class DirLabLandmarks {
    /** DIR-Lab's frames: z increases towards the feet, so the head is along -z. */
    public static final double[] SUPERIOR = {0, 0, -1};
    /** The six phases of the 75-landmark files, end-inhale first. */
    public static final List<String> SIX_PHASES = List.of("t00", "t10", "t20", "t30", "t40", "t50");
    /** The two phases of the 300-landmark files. */
    public static final List<String> EE_EI = List.of("ee", "ei");

    private DirLabLandmarks() {
    }

    /** The 300 pairs of case {@code n} (1-5) in {@code folder}: {@code caseN-300-ee-ei.csv}. */
    public static LandmarkSet readPairs(Path folder, int n) throws IOException, LandmarkFormatException {
        return read(folder.resolve("case" + n + "-300-ee-ei.csv"), EE_EI);
    }

    /** The 75 landmarks at six phases of case {@code n} (1-5) in {@code folder}: {@code caseN-75-six-phases.csv}. */
    public static LandmarkSet readSixPhases(Path folder, int n) throws IOException, LandmarkFormatException {
        return read(folder.resolve("case" + n + "-75-six-phases.csv"), SIX_PHASES);
    }

    /**
     * Reads a landmark file whose columns are {@code landmark}, then {@code P_x_mm, P_y_mm, P_z_mm} for each phase
     * P of {@code phases}, in that order.
     *
     * @throws IOException             when the file cannot be read at all
     * @throws LandmarkFormatException naming the file and line when its content is not as expected
     */
    public static LandmarkSet read(Path file, List<String> phases) throws IOException, LandmarkFormatException {
        List<String> header = headerOf(phases);
        CsvMapper m = new CsvMapper();
        m.enable(CsvParser.Feature.WRAP_AS_ARRAY);
        m.enable(CsvParser.Feature.SKIP_EMPTY_LINES);
        List<Integer> ids = new ArrayList<>();
        List<double[]> rows = new ArrayList<>();
        Set<Integer> seen = new HashSet<>();
        int line = 0;
        boolean headerRead = false;
        try (MappingIterator<String[]> it = m.readerFor(String[].class).readValues(file.toFile())) {
            while (it.hasNext()) {
                String[] row = it.next();
                line = it.getParser().currentTokenLocation().getLineNr();
                if (!headerRead) {
                    checkHeader(file, line, row, header);
                    headerRead = true;
                    continue;
                }
                if (row.length != 1 + 3 * phases.size()) {
                    throw new LandmarkFormatException(file, line, "a row of " + row.length + " fields; expected "
                            + (1 + 3 * phases.size()) + " (landmark, then x, y, z in mm at each of " + phases + ")");
                }
                int id = landmark(file, line, row[0]);
                if (!seen.add(id)) {
                    throw new LandmarkFormatException(file, line, "landmark " + id + " appears a second time;"
                            + " expected each landmark once");
                }
                double[] xyz = new double[3 * phases.size()];
                for (int k = 0; k < xyz.length; k++) {
                    String column = phases.get(k / 3) + "_" + "xyz".charAt(k % 3) + "_mm";
                    xyz[k] = millimetres(file, line, row[1 + k], column) * 1e-3;
                }
                ids.add(id);
                rows.add(xyz);
            }
        } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
            throw new LandmarkFormatException(file, e.getLocation() == null ? line : e.getLocation().getLineNr(),
                    "not readable as CSV (" + e.getOriginalMessage() + ")");
        }
        if (rows.isEmpty()) {
            throw new LandmarkFormatException(file, 0, "no landmark row after the header; expected rows of "
                    + String.join(",", headerOf(phases)));
        }
        double[][] pos = new double[phases.size()][3 * rows.size()];
        for (int i = 0; i < rows.size(); i++) {
            for (int p = 0; p < phases.size(); p++) {
                System.arraycopy(rows.get(i), 3 * p, pos[p], 3 * i, 3);
            }
        }
        String name = file.getFileName().toString().replaceFirst("\\.csv$", "");
        return new LandmarkSet(name, ids.stream().mapToInt(Integer::intValue).toArray(), phases, pos, SUPERIOR);
    }

    private static List<String> headerOf(List<String> phases) {
        List<String> h = new ArrayList<>();
        h.add("landmark");
        for (String p : phases) {
            h.add(p + "_x_mm");
            h.add(p + "_y_mm");
            h.add(p + "_z_mm");
        }
        return h;
    }

    private static void checkHeader(Path file, int line, String[] row, List<String> header)
            throws LandmarkFormatException {
        List<String> got = new ArrayList<>();
        for (String s : row) {
            got.add(s.trim().toLowerCase(Locale.ROOT));
        }
        if (!got.equals(header)) {
            throw new LandmarkFormatException(file, line, "the header is " + String.join(",", row)
                    + "; expected " + String.join(",", header));
        }
    }

    private static int landmark(Path file, int line, String token) throws LandmarkFormatException {
        try {
            int id = Integer.parseInt(token.trim());
            if (id < 1) {
                throw new LandmarkFormatException(file, line, "landmark number " + id + "; expected a whole number"
                        + " from 1");
            }
            return id;
        } catch (NumberFormatException e) {
            throw new LandmarkFormatException(file, line, "landmark '" + token + "' is not a whole number; expected"
                    + " the landmark's number from 1");
        }
    }

    private static double millimetres(Path file, int line, String token, String column)
            throws LandmarkFormatException {
        double d;
        try {
            d = Double.parseDouble(token.trim());
        } catch (NumberFormatException e) {
            throw new LandmarkFormatException(file, line, column + " is '" + token + "', not a number; expected a"
                    + " coordinate in mm");
        }
        if (!Double.isFinite(d)) {
            throw new LandmarkFormatException(file, line, column + " is " + token + "; expected a finite"
                    + " coordinate in mm");
        }
        return d;
    }

    /** Whether {@code folder} holds both files of case {@code n}. */
    public static boolean hasCase(Path folder, int n) {
        return Files.isRegularFile(folder.resolve("case" + n + "-300-ee-ei.csv"))
                && Files.isRegularFile(folder.resolve("case" + n + "-75-six-phases.csv"));
    }
}

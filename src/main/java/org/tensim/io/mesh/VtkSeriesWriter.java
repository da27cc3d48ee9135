package org.tensim.io.mesh;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Writes a time series for ParaView: one legacy VTK POLYDATA file per frame
 * ({@code <base>_NNNN.vtk}: points at their current positions in metres, the
 * triangles, the displacement from the rest position as point VECTORS and an
 * integer label per point as SCALARS) and a {@code <base>.pvd} collection that
 * lists them with their times. A series of {@link #points points} draws each point as a vertex instead of
 * triangles (points followed in a body, not its surface). The .pvd is rewritten after every frame, so a run
 * that stops early leaves a series that opens.
 */
public final class VtkSeriesWriter {
    private final Path dir;
    private final String base;
    private final int[] triangles;
    private final int[] labels;
    private final String labelName;
    /** Each point a VERTICES cell (a point series) rather than triangles. */
    private boolean vertices;
    private final List<double[]> frames = new ArrayList<>();
    private final List<String> files = new ArrayList<>();

    /**
     * @param dir       output folder
     * @param base      file name stem
     * @param triangles vertex indices of the triangles to draw (3 per triangle)
     * @param labels    one integer per point (e.g. 0 muscle, 1 tendon)
     * @param labelName name of the label array in ParaView
     */
    public VtkSeriesWriter(Path dir, String base, int[] triangles, int[] labels, String labelName) throws IOException {
        this.dir = dir;
        this.base = base;
        this.triangles = triangles.clone();
        this.labels = labels.clone();
        this.labelName = labelName;
        org.tensim.io.OutputFiles.createFolder(dir);
    }

    /**
     * A series of points alone, each drawn as a vertex (ParaView shows them without a Glyph filter).
     *
     * @param labels    one integer per point (e.g. 0 right lung, 1 left)
     * @param labelName name of the label array in ParaView
     */
    public static VtkSeriesWriter points(Path dir, String base, int[] labels, String labelName) throws IOException {
        VtkSeriesWriter w = new VtkSeriesWriter(dir, base, new int[0], labels, labelName);
        w.vertices = true;
        return w;
    }

    /**
     * Writes one frame.
     *
     * @param timeS     simulated time, s
     * @param positions current positions, m (3 per point)
     * @param rest      rest positions, m (3 per point)
     * @return the file written
     */
    public Path frame(double timeS, double[] positions, double[] rest) throws IOException {
        int n = labels.length;
        if (positions.length != 3 * n || rest.length != 3 * n) {
            throw new IllegalArgumentException("VTK frame has " + positions.length / 3 + " positions and "
                    + rest.length / 3 + " rest positions; expected " + n + " (one per label)");
        }
        String name = String.format(Locale.ROOT, "%s_%04d.vtk", base, files.size());
        Path file = dir.resolve(name);
        // Written whole then renamed: a frame is complete or absent, whenever the run stops.
        org.tensim.io.OutputFiles.writeAtomically(file, out -> {
            BufferedWriter w = new BufferedWriter(new java.io.OutputStreamWriter(out, StandardCharsets.US_ASCII));
            w.write("# vtk DataFile Version 3.0\n");
            w.write(String.format(Locale.ROOT, "tensim %s t=%.6f s%n", base, timeS));
            w.write("ASCII\nDATASET POLYDATA\n");
            w.write("POINTS " + n + " double\n");
            for (int i = 0; i < n; i++) {
                w.write(String.format(Locale.ROOT, "%.7g %.7g %.7g%n", positions[3 * i], positions[3 * i + 1],
                        positions[3 * i + 2]));
            }
            if (vertices) {
                w.write("VERTICES " + n + " " + 2 * n + "\n");
                for (int i = 0; i < n; i++) {
                    w.write("1 " + i + "\n");
                }
            }
            int nt = triangles.length / 3;
            if (!vertices) {
                w.write("POLYGONS " + nt + " " + 4 * nt + "\n");
            }
            for (int t = 0; t < nt; t++) {
                w.write("3 " + triangles[3 * t] + " " + triangles[3 * t + 1] + " " + triangles[3 * t + 2] + "\n");
            }
            w.write("POINT_DATA " + n + "\n");
            w.write("VECTORS displacement double\n");
            for (int i = 0; i < n; i++) {
                w.write(String.format(Locale.ROOT, "%.7g %.7g %.7g%n", positions[3 * i] - rest[3 * i],
                        positions[3 * i + 1] - rest[3 * i + 1], positions[3 * i + 2] - rest[3 * i + 2]));
            }
            w.write("SCALARS " + labelName + " int 1\nLOOKUP_TABLE default\n");
            for (int i = 0; i < n; i++) {
                w.write(labels[i] + "\n");
            }
            w.flush();
        });
        files.add(name);
        frames.add(new double[] {timeS});
        writeCollection();
        return file;
    }

    /** Frames written so far. */
    public int frameCount() {
        return files.size();
    }

    /** The .pvd collection file. */
    public Path collection() {
        return dir.resolve(base + ".pvd");
    }

    private void writeCollection() throws IOException {
        org.tensim.io.OutputFiles.writeAtomically(collection(), out -> {
            BufferedWriter w = new BufferedWriter(new java.io.OutputStreamWriter(out, StandardCharsets.US_ASCII));
            w.write("<?xml version=\"1.0\"?>\n");
            w.write("<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n");
            for (int i = 0; i < files.size(); i++) {
                w.write(String.format(Locale.ROOT, "    <DataSet timestep=\"%.6f\" part=\"0\" file=\"%s\"/>%n",
                        frames.get(i)[0], files.get(i)));
            }
            w.write("  </Collection>\n</VTKFile>\n");
            w.flush();
        });
    }
}

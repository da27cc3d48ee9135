package org.tensim.scene.diaphragm;

import java.util.Arrays;
import org.tensim.io.mesh.TriangleMesh;
import org.tensim.model.Check;
import org.tensim.scene.shell.SurfaceGeometry;

/**
 * The project's own parametric diaphragm: a thin closed shell shaped as a double
 * dome, in the BodyParts3D frame (x = patient's left, y = posterior, z = superior;
 * metres), so that it sits among the rib boxes of
 * {@code rib-sternum-bounds-mm.json} like the real mesh does.
 *
 * <p><b>Shape.</b> Over an elliptical footprint (semi-axes {@code a} transverse,
 * {@code b} antero-posterior, centred at {@code y = centreY}) with normalised
 * coordinates {@code u = x / a}, {@code w = (y - centreY) / b},
 * {@code r^2 = u^2 + w^2}, the upper (thoracic) surface is
 * <pre>
 *   z(u, w) = zRim(w) + (zTop(u, w) - zRim(w)) (1 - r^4)
 *   zRim(w) = rimLateral + rimAnteriorRise max(0, -w)^3 + rimPosteriorRise max(0, w)
 *   zTop(u, w) = topCentre + rightDome g(u + 0.45, w) + leftDome g(u - 0.45, w),  g = exp(-(du^2 + w^2) / 0.15)
 * </pre>
 * {@code 1 - r^4} gives a flat top and steep sides (the zone of apposition);
 * the right dome ({@code x < 0}) is higher than the left by
 * {@code rightDome - leftDome} (about 1-2 cm in adults). The lower (abdominal)
 * surface is the upper one offset by {@code thickness} along the inward normals,
 * and a strip of triangles closes the rim.
 *
 * <p><b>Triangulation.</b> Concentric rings: ring i (1..rings) has 6 i vertices
 * (a hexagonal disc), zipped to the ring inside it. Rings are spaced by equal arc
 * length along a mean meridian, so triangles on the steep sides are not
 * stretched. Each face has {@code 1 + 3 rings (rings + 1)} vertices and
 * {@code 6 rings^2} triangles; the default 43 rings give 11,354 vertices and
 * 22,704 triangles in all, close to the paper's 11,359 nodes and 22,722
 * triangles.
 */
public final class DoubleDomeGenerator {
    /**
     * Shape parameters, metres.
     *
     * @param rings             rings per face (resolution), >= 2
     * @param semiAxisX         transverse semi-axis of the footprint, m
     * @param semiAxisY         antero-posterior semi-axis, m
     * @param centreY           y of the footprint's centre, m
     * @param rimLateral        z of the rim at the sides, m
     * @param rimAnteriorRise   extra height of the rim at the front (xiphoid), m
     * @param rimPosteriorRise  extra height of the rim at the back, m
     * @param topCentre         z of the top between the domes, m
     * @param rightDome         rise of the right dome above topCentre, m
     * @param leftDome          rise of the left dome above topCentre, m
     * @param thickness         shell thickness, m (diaphragm 1.9 +/- 0.4 mm by ultrasound; BodyParts3D about 3 mm)
     */
    public record Shape(int rings, double semiAxisX, double semiAxisY, double centreY, double rimLateral,
            double rimAnteriorRise, double rimPosteriorRise, double topCentre, double rightDome, double leftDome,
            double thickness) {
        public Shape {
            Check.atLeast("double dome rings", rings, 2);
            if (rings > MAX_RINGS) {
                throw new IllegalArgumentException("double dome rings must be at most " + MAX_RINGS + " ("
                        + faceVertices(MAX_RINGS) + " vertices a face), got " + rings);
            }
            Check.positive("double dome transverse semi-axis", "m", semiAxisX);
            Check.positive("double dome antero-posterior semi-axis", "m", semiAxisY);
            Check.finite("double dome centre y", "m", centreY);
            Check.finite("double dome lateral rim z", "m", rimLateral);
            Check.nonNegative("double dome anterior rim rise", "m", rimAnteriorRise);
            Check.nonNegative("double dome posterior rim rise", "m", rimPosteriorRise);
            Check.finite("double dome top z", "m", topCentre);
            Check.nonNegative("right dome rise", "m", rightDome);
            Check.nonNegative("left dome rise", "m", leftDome);
            Check.positive("double dome thickness", "m", thickness);
            if (topCentre <= rimLateral + rimAnteriorRise || topCentre <= rimLateral + rimPosteriorRise) {
                throw new IllegalArgumentException("double dome top z " + topCentre
                        + " m must be above the rim (lateral " + rimLateral + " m plus its rises)");
            }
        }

        /**
         * An adult diaphragm in the BodyParts3D frame: 240 x 176 mm footprint, rim at
         * z 1015 mm (sides) to 1165 mm (front, at the xiphoid), right dome top near 1190 mm, left
         * 12 mm lower, 2.5 mm thick, 43 rings.
         */
        public static Shape adult() {
            return new Shape(43, 0.120, 0.088, -0.118, 1.015, 0.15, 0.025, 1.170, 0.021, 0.009, 0.0025);
        }

        public Shape withRings(int n) {
            return new Shape(n, semiAxisX, semiAxisY, centreY, rimLateral, rimAnteriorRise, rimPosteriorRise,
                    topCentre, rightDome, leftDome, thickness);
        }

        public Shape withThickness(double m) {
            return new Shape(rings, semiAxisX, semiAxisY, centreY, rimLateral, rimAnteriorRise, rimPosteriorRise,
                    topCentre, rightDome, leftDome, m);
        }

        /** Height of the upper surface at normalised footprint coordinates (u, w), m. */
        double height(double u, double w) {
            double r2 = u * u + w * w;
            double rim = rimLateral + rimAnteriorRise * Math.pow(Math.max(0, -w), 3)
                    + rimPosteriorRise * Math.max(0, w);
            double top = topCentre + rightDome * bump(u + 0.45, w) + leftDome * bump(u - 0.45, w);
            return rim + (top - rim) * (1 - r2 * r2);
        }

        private static double bump(double du, double w) {
            return Math.exp(-(du * du + w * w) / 0.15);
        }
    }

    private DoubleDomeGenerator() {
    }

    /**
     * Most rings per face: 500 give 751,501 vertices a face, 60 times the paper's model; the
     * counts of larger ones overflow the int indices of the mesh long before memory runs out.
     */
    public static final int MAX_RINGS = 500;

    /** Vertices per face for a number of rings. */
    public static int faceVertices(int rings) {
        return 1 + 3 * rings * (rings + 1);
    }

    /** The closed shell (upper face, lower face, rim strip), metres. */
    public static TriangleMesh shell(Shape s) {
        TriangleMesh upper = upperSurface(s);
        int nv = upper.vertexCount();
        double[] normals = SurfaceGeometry.vertexNormals(upper);
        double[] xyz = new double[6 * nv];
        for (int v = 0; v < nv; v++) {
            for (int a = 0; a < 3; a++) {
                xyz[3 * v + a] = upper.coord(v, a);
                xyz[3 * (nv + v) + a] = upper.coord(v, a) - s.thickness() * normals[3 * v + a];
            }
        }
        int nt = upper.triangleCount();
        int rimCount = 6 * s.rings();
        int[] tri = new int[3 * (2 * nt + 2 * rimCount)];
        int k = 0;
        for (int t = 0; t < nt; t++) {
            tri[k++] = upper.corner(t, 0);
            tri[k++] = upper.corner(t, 1);
            tri[k++] = upper.corner(t, 2);
        }
        for (int t = 0; t < nt; t++) { // reversed: the lower face's normals point down (outwards)
            tri[k++] = nv + upper.corner(t, 0);
            tri[k++] = nv + upper.corner(t, 2);
            tri[k++] = nv + upper.corner(t, 1);
        }
        int first = nv - rimCount; // the outer ring is stored last
        for (int i = 0; i < rimCount; i++) {
            int u0 = first + i;
            int u1 = first + (i + 1) % rimCount;
            tri[k++] = u0;
            tri[k++] = nv + u0;
            tri[k++] = nv + u1;
            tri[k++] = u0;
            tri[k++] = nv + u1;
            tri[k++] = u1;
        }
        return new TriangleMesh(xyz, tri);
    }

    /** The upper (thoracic) surface alone, an open surface whose normals point up and out. */
    public static TriangleMesh upperSurface(Shape s) {
        int n = s.rings();
        double[] radius = ringRadii(s);
        int nv = faceVertices(n);
        double[] xyz = new double[3 * nv];
        int v = 0;
        for (int i = 0; i <= n; i++) {
            int count = i == 0 ? 1 : 6 * i;
            for (int j = 0; j < count; j++) {
                double th = 2 * Math.PI * j / count;
                double u = radius[i] * Math.cos(th);
                double w = radius[i] * Math.sin(th);
                xyz[3 * v] = s.semiAxisX() * u;
                xyz[3 * v + 1] = s.centreY() + s.semiAxisY() * w;
                xyz[3 * v + 2] = s.height(u, w);
                v++;
            }
        }
        return new TriangleMesh(xyz, ringTriangles(n));
    }

    /**
     * Triangles of a disc of concentric rings: vertex 0 at the centre, then ring i (1..rings) of 6 i
     * vertices in order of angle; each ring is zipped to the one inside it by angle, so every
     * triangle advances one of the two rings by one vertex (6 rings^2 triangles, 3 indices each).
     */
    public static int[] ringTriangles(int rings) {
        int n = rings;
        int[] ringStart = new int[n + 1];
        for (int i = 1; i <= n; i++) {
            ringStart[i] = ringStart[i - 1] + (i == 1 ? 1 : 6 * (i - 1));
        }
        int[] tri = new int[3 * 6 * n * n];
        int k = 0;
        for (int i = 1; i <= n; i++) {
            int nIn = i == 1 ? 1 : 6 * (i - 1);
            int nOut = 6 * i;
            int in0 = ringStart[i - 1];
            int out0 = ringStart[i];
            int j = 0;
            int q = 0;
            // Zip the two rings by angle: each triangle advances one of them by one vertex.
            while (q < nOut || (nIn > 1 && j < nIn)) {
                double nextOut = (q + 1.0) / nOut;
                double nextIn = nIn == 1 ? Double.POSITIVE_INFINITY : (j + 1.0) / nIn;
                if (q < nOut && (nextOut <= nextIn || j >= nIn)) {
                    tri[k++] = in0 + (j % nIn);
                    tri[k++] = out0 + q;
                    tri[k++] = out0 + (q + 1) % nOut;
                    q++;
                } else {
                    tri[k++] = in0 + j;
                    tri[k++] = out0 + (q % nOut);
                    tri[k++] = in0 + (j + 1) % nIn;
                    j++;
                }
            }
        }
        return Arrays.copyOf(tri, k);
    }

    /** Normalised ring radii 0..1, equally spaced in arc length along the mean meridian. */
    private static double[] ringRadii(Shape s) {
        int samples = 4000;
        double rEff = Math.sqrt(s.semiAxisX() * s.semiAxisY());
        double[] arc = new double[samples + 1];
        double prevZ = meanHeight(s, 0);
        for (int i = 1; i <= samples; i++) {
            double r = (double) i / samples;
            double z = meanHeight(s, r);
            double dr = rEff / samples;
            arc[i] = arc[i - 1] + Math.sqrt(dr * dr + (z - prevZ) * (z - prevZ));
            prevZ = z;
        }
        double[] radius = new double[s.rings() + 1];
        int idx = 0;
        for (int i = 1; i <= s.rings(); i++) {
            double target = arc[samples] * i / s.rings();
            while (idx < samples && arc[idx + 1] < target) {
                idx++;
            }
            double f = idx >= samples ? 0 : (target - arc[idx]) / (arc[idx + 1] - arc[idx]);
            radius[i] = Math.min(1, (idx + f) / samples);
        }
        radius[s.rings()] = 1;
        return radius;
    }

    /** Height averaged around the ring of normalised radius r, m. */
    private static double meanHeight(Shape s, double r) {
        double z = 0;
        int m = 24;
        for (int j = 0; j < m; j++) {
            double th = 2 * Math.PI * j / m;
            z += s.height(r * Math.cos(th), r * Math.sin(th));
        }
        return z / m;
    }
}

package org.tensim.view;

import org.tensim.scene.tunable.FrameBuffer;
import org.tensim.scene.tunable.Body;
import org.tensim.scene.tunable.LiveState;
import java.util.ArrayList;
import java.util.List;
import org.jogamp.java3d.Appearance;
import org.jogamp.java3d.ColoringAttributes;
import org.jogamp.java3d.GeometryArray;
import org.jogamp.java3d.GeometryUpdater;
import org.jogamp.java3d.IndexedGeometryArray;
import org.jogamp.java3d.IndexedLineArray;
import org.jogamp.java3d.IndexedPointArray;
import org.jogamp.java3d.IndexedTriangleArray;
import org.jogamp.java3d.LineArray;
import org.jogamp.java3d.LineAttributes;
import org.jogamp.java3d.Material;
import org.jogamp.java3d.PointAttributes;
import org.jogamp.java3d.PolygonAttributes;
import org.jogamp.java3d.RenderingAttributes;
import org.jogamp.java3d.Shape3D;
import org.jogamp.java3d.TransparencyAttributes;
import org.jogamp.vecmath.Color3f;
import org.tensim.solver.SystemState;

/**
 * The Java3D shapes of one {@link Body}: shaded surface (if it has triangles),
 * springs, rigid links, nodes, the probe node and displacement vectors. All
 * geometry is by reference: its float arrays are rewritten from a
 * {@link FrameBuffer.Frame} inside {@link GeometryArray#updateData}, the only
 * place Java3D allows it, by {@link FrameUpdateBehavior}.
 */
final class BodyShapes {
    /** The layers a user can show or hide. */
    enum Layer { SURFACE, SPRINGS, LINKS, NODES, VECTORS, STRUCTURE, ORGANS }

    /**
     * Opacity of an organ's surface (the lungs, the liver): 0.35, through which the diaphragm and the other organs
     * show. Java3D draws translucent shapes after the opaque ones with the depth buffer frozen (the view's default),
     * so the organs hide nothing they cover.
     */
    static final float ORGAN_OPACITY = 0.35f;

    private static final int REF = GeometryArray.COORDINATES | GeometryArray.BY_REFERENCE;
    private static final int REF_INDEXED = REF | GeometryArray.USE_COORD_INDEX_ONLY;

    private final Body body;
    private final float[] rest;
    private final double vectorScale;
    private final List<Part> parts = new ArrayList<>();
    /** Colours of the live state's marks (null: the body is not marked), and the marks of the frame being drawn. */
    private final float[][] markColours;
    private byte[] marks;

    /** One shape, its geometry, its layer, and the updater that refills its arrays from positions. */
    private static final class Part implements GeometryUpdater {
        final Layer layer;
        final Shape3D shape;
        final GeometryArray geometry;
        final RenderingAttributes visibility;
        final Filler filler;
        private float[] source;

        Part(Layer layer, Shape3D shape, GeometryArray geometry, RenderingAttributes visibility, Filler filler) {
            this.layer = layer;
            this.shape = shape;
            this.geometry = geometry;
            this.visibility = visibility;
            this.filler = filler;
        }

        void refill(float[] positions) {
            source = positions;
            geometry.updateData(this);
        }

        @Override
        public void updateData(org.jogamp.java3d.Geometry g) {
            filler.fill(source);
        }
    }

    @FunctionalInterface
    private interface Filler {
        void fill(float[] positions);
    }

    /**
     * @param markColours colours of the live state's marks 1, 2, ... on this body's surface ({@code LiveState}), or
     *                    null when it has none
     */
    BodyShapes(Body body, float[] initial, double vectorScale, float[][] markColours) {
        this(body, initial, vectorScale, markColours, false);
    }

    /**
     * As {@link #BodyShapes(Body, float[], double, float[][])}; an {@code organ} body is only its surface, drawn
     * translucent ({@link #ORGAN_OPACITY}) in the {@link Layer#ORGANS} layer: its vertices are carried points, not
     * nodes with springs, and no marks or vectors are drawn on it.
     */
    BodyShapes(Body body, float[] initial, double vectorScale, float[][] markColours, boolean organ) {
        this.body = body;
        this.markColours = markColours;
        this.vectorScale = vectorScale;
        this.rest = new float[initial.length];
        SystemState s = body.simulation().state();
        for (int k = 0; k < rest.length; k++) {
            rest[k] = (float) s.x0[k];
        }
        int n = body.nodeCount();
        if (organ) {
            addSurface(n, Layer.ORGANS);
            update(initial);
            return;
        }
        if (body.triangles().length > 0) {
            addSurface(n, Layer.SURFACE);
        }
        int visible = body.visibleNodes();
        int[] springs = pairs(s.springA, s.springB, visible);
        if (springs.length > 0) {
            addLines(Layer.SPRINGS, n, springs, new Color3f(0.35f, 0.55f, 0.85f), 1.5f, body.vertexColours());
        }
        int[] links = pairs(s.linkA, s.linkB, visible);
        if (links.length > 0) {
            addLines(Layer.LINKS, n, links, new Color3f(0.9f, 0.15f, 0.1f), n > 2000 ? 2f : 4f, null);
        }
        if (body.structureEdges().length > 0) {
            addLines(Layer.STRUCTURE, n, body.structureEdges(), new Color3f(0.93f, 0.89f, 0.76f), 3f, null);
        }
        int[] all = new int[visible];
        for (int i = 0; i < visible; i++) {
            all[i] = i;
        }
        addPoints(Layer.NODES, n, all, new Color3f(0.95f, 0.95f, 0.95f), n > 2000 ? 1.5f : 5f);
        addPoints(Layer.NODES, n, new int[] {body.probeNode()}, new Color3f(1f, 0.85f, 0.1f), 12f);
        addVectors(visible);
        update(initial);
    }

    /** The shapes, to hang under the body's transform. */
    List<Shape3D> shapes() {
        List<Shape3D> l = new ArrayList<>();
        for (Part p : parts) {
            l.add(p.shape);
        }
        return l;
    }

    /** Shows or hides a layer (any thread: Java3D applies it at the next frame). */
    void setVisible(Layer layer, boolean visible) {
        for (Part p : parts) {
            if (p.layer == layer) {
                p.visibility.setVisible(visible);
            }
        }
    }

    /** Rewrites every geometry from positions (m, 3 per node). Behaviour thread only. */
    void update(float[] positions) {
        update(positions, null);
    }

    /**
     * Rewrites every geometry from positions (m, 3 per node) and, on a marked body, the surface's colours from the
     * frame's marks (one per node; null: the body's own colours). Behaviour thread only.
     */
    void update(float[] positions, byte[] frameMarks) {
        marks = frameMarks;
        for (Part p : parts) {
            p.refill(positions);
        }
    }

    /** End points of the elements whose both ends are drawn, two per element. */
    private static int[] pairs(int[] a, int[] b, int visible) {
        int m = 0;
        for (int i = 0; i < a.length; i++) {
            m += a[i] < visible && b[i] < visible ? 1 : 0;
        }
        int[] idx = new int[2 * m];
        for (int i = 0, k = 0; i < a.length; i++) {
            if (a[i] < visible && b[i] < visible) {
                idx[k++] = a[i];
                idx[k++] = b[i];
            }
        }
        return idx;
    }

    private static RenderingAttributes visibility() {
        RenderingAttributes ra = new RenderingAttributes();
        ra.setCapability(RenderingAttributes.ALLOW_VISIBLE_WRITE);
        return ra;
    }

    private static void writable(GeometryArray g) {
        g.setCapability(GeometryArray.ALLOW_REF_DATA_WRITE);
        g.setCapability(GeometryArray.ALLOW_REF_DATA_READ);
    }

    private void addSurface(int n, Layer layer) {
        int[] tri = body.triangles();
        boolean coloured = body.vertexColours() != null;
        int format = REF_INDEXED | GeometryArray.NORMALS | (coloured ? GeometryArray.COLOR_3 : 0);
        IndexedTriangleArray g = new IndexedTriangleArray(n, format, tri.length);
        writable(g);
        g.setCoordinateIndices(0, tri);
        float[] coords = new float[3 * n];
        float[] normals = new float[3 * n];
        g.setCoordRefFloat(coords);
        g.setNormalRefFloat(normals);
        float[] own = coloured ? body.vertexColours().clone() : null;
        float[] colours = coloured ? own.clone() : null;
        if (coloured) {
            g.setColorRefFloat(colours);
        }
        boolean live = coloured && markColours != null;
        Appearance app = new Appearance();
        Material m = new Material();
        m.setDiffuseColor(0.8f, 0.45f, 0.4f);
        m.setSpecularColor(0.25f, 0.25f, 0.25f);
        m.setShininess(24f);
        m.setColorTarget(Material.DIFFUSE);
        m.setLightingEnable(true);
        app.setMaterial(m);
        PolygonAttributes pa = new PolygonAttributes();
        pa.setCullFace(PolygonAttributes.CULL_NONE);
        pa.setBackFaceNormalFlip(true);
        pa.setPolygonOffsetFactor(1f); // lines drawn on the surface stay visible
        pa.setPolygonOffset(1f);
        app.setPolygonAttributes(pa);
        if (layer == Layer.ORGANS) {
            app.setTransparencyAttributes(new TransparencyAttributes(TransparencyAttributes.BLENDED,
                    1 - ORGAN_OPACITY));
        }
        RenderingAttributes ra = visibility();
        app.setRenderingAttributes(ra);
        parts.add(new Part(layer, new Shape3D(g, app), g, ra, p -> {
            System.arraycopy(p, 0, coords, 0, coords.length);
            Normals.compute(p, tri, normals);
            if (live && marks != null) {
                LiveState.paint(own, marks, markColours, colours);
            }
        }));
    }

    private void addLines(Layer layer, int n, int[] idx, Color3f colour, float width, float[] colours) {
        int format = REF_INDEXED | (colours != null ? GeometryArray.COLOR_3 : 0);
        IndexedLineArray g = new IndexedLineArray(n, format, idx.length);
        writable(g);
        g.setCoordinateIndices(0, idx);
        float[] coords = new float[3 * n];
        g.setCoordRefFloat(coords);
        if (colours != null) {
            g.setColorRefFloat(colours.clone());
        }
        Appearance app = new Appearance();
        app.setColoringAttributes(new ColoringAttributes(colour, ColoringAttributes.SHADE_FLAT));
        app.setLineAttributes(new LineAttributes(width, LineAttributes.PATTERN_SOLID, true));
        RenderingAttributes ra = visibility();
        app.setRenderingAttributes(ra);
        parts.add(new Part(layer, new Shape3D(g, app), g, ra, p -> System.arraycopy(p, 0, coords, 0, coords.length)));
    }

    private void addPoints(Layer layer, int n, int[] idx, Color3f colour, float size) {
        IndexedGeometryArray g = new IndexedPointArray(n, REF_INDEXED, idx.length);
        writable(g);
        g.setCoordinateIndices(0, idx);
        float[] coords = new float[3 * n];
        g.setCoordRefFloat(coords);
        Appearance app = new Appearance();
        app.setColoringAttributes(new ColoringAttributes(colour, ColoringAttributes.SHADE_FLAT));
        app.setPointAttributes(new PointAttributes(size, true));
        RenderingAttributes ra = visibility();
        app.setRenderingAttributes(ra);
        parts.add(new Part(layer, new Shape3D(g, app), g, ra, p -> System.arraycopy(p, 0, coords, 0, coords.length)));
    }

    /** Displacement vectors: from each node's rest position to rest + scale * displacement. */
    private void addVectors(int n) {
        LineArray g = new LineArray(2 * n, REF);
        writable(g);
        float[] coords = new float[6 * n];
        g.setCoordRefFloat(coords);
        Appearance app = new Appearance();
        app.setColoringAttributes(new ColoringAttributes(new Color3f(0.2f, 0.9f, 0.3f), ColoringAttributes.SHADE_FLAT));
        RenderingAttributes ra = visibility();
        ra.setVisible(false);
        app.setRenderingAttributes(ra);
        float scale = (float) vectorScale;
        parts.add(new Part(Layer.VECTORS, new Shape3D(g, app), g, ra, p -> {
            for (int i = 0; i < n; i++) {
                for (int k = 0; k < 3; k++) {
                    float r = rest[3 * i + k];
                    coords[6 * i + k] = r;
                    coords[6 * i + 3 + k] = r + scale * (p[3 * i + k] - r);
                }
            }
        }));
    }
}

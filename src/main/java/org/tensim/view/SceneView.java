package org.tensim.view;

import org.tensim.scene.tunable.FrameBuffer;
import org.tensim.scene.tunable.Body;
import java.awt.AWTException;
import java.awt.GraphicsConfiguration;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import org.jogamp.java3d.AmbientLight;
import org.jogamp.java3d.Background;
import org.jogamp.java3d.BoundingSphere;
import org.jogamp.java3d.BranchGroup;
import org.jogamp.java3d.Canvas3D;
import org.jogamp.java3d.DirectionalLight;
import org.jogamp.java3d.Shape3D;
import org.jogamp.java3d.Transform3D;
import org.jogamp.java3d.TransformGroup;
import org.jogamp.java3d.View;
import org.jogamp.java3d.utils.behaviors.vp.OrbitBehavior;
import org.jogamp.java3d.utils.universe.SimpleUniverse;
import org.jogamp.vecmath.Color3f;
import org.jogamp.vecmath.Point3d;
import org.jogamp.vecmath.Vector3d;
import org.jogamp.vecmath.Vector3f;
import org.tensim.model.Vec3;

/**
 * The Java3D view of a scene: a {@link Canvas3D} in a universe whose content is
 * one branch per scene (replaced on reset), lit, with orbit (left drag), zoom
 * (middle drag or wheel) and pan (right drag) by {@link OrbitBehavior}, and a
 * home view that frames every body. The scene graph is a listener of the
 * simulation: it reads frames from a {@link FrameBuffer} and never touches the
 * model.
 */
public final class SceneView {
    private static final BoundingSphere EVERYWHERE = new BoundingSphere(new Point3d(), Double.MAX_VALUE);

    private final FpsCanvas canvas;
    private final SimpleUniverse universe;
    private final OrbitBehavior orbit;
    private final Map<BodyShapes.Layer, Boolean> visible = new EnumMap<>(BodyShapes.Layer.class);
    private BranchGroup content;
    private List<BodyShapes> shapes = List.of();
    private FrameUpdateBehavior updater;

    /** A Canvas3D that counts the frames it shows. */
    private static final class FpsCanvas extends Canvas3D {
        private static final long serialVersionUID = 1L;
        final AtomicLong frames = new AtomicLong();

        FpsCanvas(GraphicsConfiguration gc) {
            super(gc);
        }

        @Override
        public void postSwap() {
            frames.incrementAndGet();
        }
    }

    /** Makes the canvas and the universe. Needs a display (throws HeadlessException without). */
    public SceneView() {
        canvas = new FpsCanvas(SimpleUniverse.getPreferredConfiguration());
        universe = new SimpleUniverse(canvas);
        View view = universe.getViewer().getView();
        // Java3D 1.7.2 puts the default front clip plane too deep for small images (docs/gui.md):
        // clip relative to the eye, at distances set from the scene's size in show().
        view.setFrontClipPolicy(View.VIRTUAL_EYE);
        view.setBackClipPolicy(View.VIRTUAL_EYE);
        setFrameCap(DEFAULT_FRAME_CAP_FPS);
        orbit = new OrbitBehavior(canvas, OrbitBehavior.REVERSE_ALL | OrbitBehavior.PROPORTIONAL_ZOOM);
        orbit.setSchedulingBounds(EVERYWHERE);
        universe.getViewingPlatform().setViewPlatformBehavior(orbit);
        for (BodyShapes.Layer l : BodyShapes.Layer.values()) {
            visible.put(l, l != BodyShapes.Layer.VECTORS);
        }
    }

    /**
     * Frames per second drawn at most by default: 40, so that the window keeps 30 or more (smooth to the eye) while
     * the renderer leaves the rest of its core to the simulation. The cap is Java3D's minimum frame cycle time
     * (25 ms here), a floor under each frame's time rather than a schedule: a cap of 30 (33 ms) drew 29.4-29.9
     * frames per second, never 30, and 40 drew 36.6-37.5 with the mapped diaphragm still at 2.2 of real time
     * unpaced (docs/gui.md; the runs: history.md).
     */
    public static final int DEFAULT_FRAME_CAP_FPS = 40;

    private int frameCapFps;

    /** Draws at most {@code fps} frames per second; 0 for no cap (as fast as the display allows). */
    public void setFrameCap(int fps) {
        if (fps < 0 || fps > 1000) {
            throw new IllegalArgumentException("frame cap must be 0 (none) to 1000 frames per second, got " + fps);
        }
        frameCapFps = fps;
        universe.getViewer().getView().setMinimumFrameCycleTime(fps == 0 ? 0 : Math.round(1000.0 / fps));
    }

    /** The frame cap, frames per second (0: none). */
    public int frameCap() {
        return frameCapFps;
    }

    public Canvas3D canvas() {
        return canvas;
    }

    /**
     * Replaces what is drawn with the bodies of {@code frames}, at their current
     * positions, and frames them in the home view. Call on the Swing thread.
     */
    public void show(FrameBuffer frames, double displacementScale, Vec3 up, Vec3 viewFrom) {
        show(frames, displacementScale, up, viewFrom, List.of());
    }

    /**
     * As {@link #show(FrameBuffer, double, Vec3, Vec3)}, the bodies of index {@code organs} drawn as translucent
     * surfaces in the organs' layer ({@link #showOrgans}).
     */
    public void show(FrameBuffer frames, double displacementScale, Vec3 up, Vec3 viewFrom, List<Integer> organs) {
        if (content != null) {
            content.detach();
        }
        BranchGroup root = new BranchGroup();
        root.setCapability(BranchGroup.ALLOW_DETACH);
        Background bg = new Background(new Color3f(0.11f, 0.12f, 0.15f));
        bg.setApplicationBounds(EVERYWHERE);
        root.addChild(bg);
        AmbientLight ambient = new AmbientLight(new Color3f(0.35f, 0.35f, 0.35f));
        ambient.setInfluencingBounds(EVERYWHERE);
        root.addChild(ambient);
        // Lights placed for the home view: a key light from above the eye and to its right, a dim fill from
        // the other side, whatever the scene's up direction.
        Vec3 u = up.normalized();
        Vec3 f = viewFrom.normalized();
        Vec3 right = new Vec3(u.y() * f.z() - u.z() * f.y(), u.z() * f.x() - u.x() * f.z(), u.x() * f.y() - u.y() * f.x());
        Vec3 keyFrom = f.plus(u.times(0.8)).plus(right.times(0.4));
        Vec3 fillFrom = f.times(0.5).minus(right.times(0.8)).minus(u.times(0.3));
        DirectionalLight key = new DirectionalLight(new Color3f(0.85f, 0.85f, 0.8f), toward(keyFrom));
        key.setInfluencingBounds(EVERYWHERE);
        root.addChild(key);
        DirectionalLight fill = new DirectionalLight(new Color3f(0.35f, 0.36f, 0.42f), toward(fillFrom));
        fill.setInfluencingBounds(EVERYWHERE);
        root.addChild(fill);

        List<Body> bodies = frames.bodies();
        List<BodyShapes> made = new ArrayList<>();
        double[] lo = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
        double[] hi = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        // Frame what matters: the surfaces when there are any (not the ribs around them), else every node drawn.
        boolean surfaces = bodies.stream().anyMatch(b -> b.triangles().length > 0);
        for (Body b : bodies) {
            boolean organ = organs.contains(bodies.indexOf(b));
            double[] x = b.simulation().state().x;
            float[] initial = new float[x.length];
            double[] off = {b.offset().x(), b.offset().y(), b.offset().z()};
            for (int k = 0; k < x.length; k++) {
                initial[k] = (float) x[k];
            }
            int[] framed = surfaces ? b.triangles() : null;
            int count = surfaces ? framed.length : b.visibleNodes();
            for (int j = 0; j < count; j++) {
                int node = surfaces ? framed[j] : j;
                for (int a = 0; a < 3; a++) {
                    lo[a] = Math.min(lo[a], x[3 * node + a] + off[a]);
                    hi[a] = Math.max(hi[a], x[3 * node + a] + off[a]);
                }
            }
            boolean marked = frames.live() != null && frames.live().body() == bodies.indexOf(b);
            BodyShapes s = new BodyShapes(b, initial, displacementScale, marked ? frames.live().markColours() : null,
                    organ);
            Transform3D t = new Transform3D();
            t.setTranslation(new Vector3d(off));
            TransformGroup tg = new TransformGroup(t);
            for (Shape3D shape : s.shapes()) {
                tg.addChild(shape);
            }
            root.addChild(tg);
            made.add(s);
        }
        FrameUpdateBehavior behaviour = new FrameUpdateBehavior(frames, made);
        behaviour.setSchedulingBounds(EVERYWHERE);
        root.addChild(behaviour);
        shapes = made;
        updater = behaviour;
        for (Map.Entry<BodyShapes.Layer, Boolean> e : visible.entrySet()) {
            setVisible(e.getKey(), e.getValue());
        }
        frame(lo, hi, up.normalized(), viewFrom.normalized());
        root.compile();
        universe.addBranchGraph(root);
        content = root;
    }

    /** Sets the home view to frame the box [lo, hi] (m), seen from direction {@code from}, and goes there. */
    private void frame(double[] lo, double[] hi, Vec3 up, Vec3 from) {
        Point3d centre = new Point3d((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
        double r = 0.5 * Math.sqrt(sq(hi[0] - lo[0]) + sq(hi[1] - lo[1]) + sq(hi[2] - lo[2]));
        r = Math.max(r, 1e-3);
        // Java3D's field of view is horizontal; the vertical one is narrower on a wide canvas.
        View view = universe.getViewer().getView();
        int w = canvas.getWidth() > 0 ? canvas.getWidth() : canvas.getPreferredSize().width;
        int h = canvas.getHeight() > 0 ? canvas.getHeight() : canvas.getPreferredSize().height;
        double halfH = view.getFieldOfView() / 2;
        double halfV = Math.atan(Math.tan(halfH) * h / Math.max(1, w));
        double d = 1.1 * r / Math.tan(Math.min(halfH, halfV));
        Point3d eye = new Point3d(centre.x + from.x() * d, centre.y + from.y() * d, centre.z + from.z() * d);
        Transform3D look = new Transform3D();
        look.lookAt(eye, centre, new Vector3d(up.x(), up.y(), up.z()));
        look.invert();
        view.setFrontClipDistance(0.01 * r);
        view.setBackClipDistance(20 * r);
        orbit.setRotationCenter(centre);
        orbit.setHomeTransform(look);
        orbit.setMinRadius(0.01 * r);
        orbit.goHome();
    }

    /** The direction a light shines in, from where it comes from. */
    private static Vector3f toward(Vec3 from) {
        return new Vector3f((float) -from.x(), (float) -from.y(), (float) -from.z());
    }

    private static double sq(double v) {
        return v * v;
    }

    /** Back to the home view. */
    public void resetView() {
        orbit.goHome();
    }

    /** Shows or hides the surfaces. */
    public void showSurface(boolean on) {
        setVisible(BodyShapes.Layer.SURFACE, on);
    }

    public void showSprings(boolean on) {
        setVisible(BodyShapes.Layer.SPRINGS, on);
    }

    public void showLinks(boolean on) {
        setVisible(BodyShapes.Layer.LINKS, on);
    }

    public void showNodes(boolean on) {
        setVisible(BodyShapes.Layer.NODES, on);
    }

    /** Ribs, sternum and cartilage (the bodies' structure lines). */
    public void showStructure(boolean on) {
        setVisible(BodyShapes.Layer.STRUCTURE, on);
    }

    /** The organs' translucent surfaces (the lungs and the liver about the diaphragm). */
    public void showOrgans(boolean on) {
        setVisible(BodyShapes.Layer.ORGANS, on);
    }

    /** Whether the organs' layer is shown. */
    public boolean organsShown() {
        return visible.get(BodyShapes.Layer.ORGANS);
    }

    /** Displacement vectors, scaled by the scene's displacement scale. */
    public void showVectors(boolean on) {
        setVisible(BodyShapes.Layer.VECTORS, on);
    }

    private void setVisible(BodyShapes.Layer layer, boolean on) {
        visible.put(layer, on);
        for (BodyShapes s : shapes) {
            s.setVisible(layer, on);
        }
    }

    /** Frames rendered so far. */
    public long framesRendered() {
        return canvas.frames.get();
    }

    /** Simulated time of the frame on screen, s. */
    public double shownTime() {
        return updater == null ? 0 : updater.shownTime();
    }

    /** Step count of the frame on screen. */
    public long shownStep() {
        return updater == null ? 0 : updater.shownStep();
    }

    /** The canvas as it is on screen (java.awt.Robot screen capture). Needs the canvas showing. */
    public BufferedImage capture() throws AWTException {
        Point p = canvas.getLocationOnScreen();
        return new Robot().createScreenCapture(new Rectangle(p.x, p.y, canvas.getWidth(), canvas.getHeight()));
    }

    /**
     * Stops rendering and releases the universe and its threads. Java3D 1.7.2's
     * {@code SimpleUniverse.cleanup()} now and then waits forever for its master
     * control thread; it is therefore run on a helper thread, waited for at most
     * {@code waitMillis}, and left to finish on its own (its threads are daemons:
     * they never keep the program alive).
     *
     * @return true when the clean-up finished in time
     */
    public boolean dispose(long waitMillis) {
        canvas.stopRenderer();
        Thread t = new Thread(universe::cleanup, "tensim-java3d-cleanup");
        t.setDaemon(true);
        t.start();
        try {
            t.join(waitMillis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return !t.isAlive();
    }
}

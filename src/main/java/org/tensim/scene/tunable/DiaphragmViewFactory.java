package org.tensim.scene.tunable;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.tensim.io.mesh.MeshFormatException;
import org.tensim.io.mesh.VertexLabel;
import org.tensim.model.Vec3;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.DiaphragmControls;
import org.tensim.scene.diaphragm.DiaphragmParameters;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.diaphragm.DiaphragmSpec;
import org.tensim.scene.diaphragm.MappedDiaphragm;
import org.tensim.scene.diaphragm.TendonPlane;
import org.tensim.scene.diaphragm.TendonRule;
import org.tensim.scene.shell.TwoSurfaces;

/**
 * The diaphragm's scene factory. Besides its spec's scenes it takes labels painted by the user
 * ({@link #paintLabels}): the scenes it makes from then on are built with them, as from a label file.
 *
 * <p>With {@link #mapMechanics} its scenes run the mechanics on the generated double dome at fewer rings, the spec's
 * mesh carried by it and drawn ({@link MappedDiaphragm}, {@link DiaphragmMappedViewScene}); {@link #setFullModel}
 * switches between that and the spec's mesh running unmapped. A mesh with labels (a file or painted) runs unmapped:
 * its labels name the fine mesh's vertices, not the coarse model's.
 */
public final class DiaphragmViewFactory implements SceneFactory {
    private final DiaphragmSpec base;
    private final BoundaryConditions bc;
    // Read or generated once; every scene, the first included, is then built from these inputs by
    // the same call, outside the lock: the same values give the same scene whatever was built before,
    // and parallel sweep workers do not queue for each other's scene building.
    private DiaphragmSetup.Inputs inputs;
    /** Painted labels and the file they were saved to, or null. */
    private volatile Painted painted;

    /** The mechanics' resolution when mapped, or null; whether the full model runs instead. */
    private volatile Mechanics mechanics;
    private volatile boolean fullModel;
    private DiaphragmSetup.Inputs coarseInputs;
    private int coarseRings;

    private record Painted(VertexLabel[] labels, Path file) {
    }

    /**
     * The mechanics' resolution of a mapped scene.
     *
     * @param rings  rings per face of the generated double dome that runs the mechanics
     * @param error  its measured error against the drawn resolution (relative RMS, a fraction)
     * @param source where that was measured (a pick file), for the window
     */
    public record Mechanics(int rings, double error, String source) {
    }

    /**
     * From now on, the mechanics run at {@code m.rings()} and the spec's mesh is carried by them (unless
     * {@link #setFullModel} says otherwise).
     *
     * @throws IllegalArgumentException with a label file (its labels are the fine mesh's)
     */
    public void mapMechanics(Mechanics m) {
        if (m != null && base.mesh().labels() != null) {
            throw new IllegalArgumentException("--labels " + base.mesh().labels() + " labels the drawn mesh's vertices:"
                    + " a mapped model cannot take them; open the full model (--rings " + base.mesh().rings() + ")");
        }
        mechanics = m;
    }

    /** The lungs and the liver built into every scene from now on ({@link #setOrgans}), or null. */
    private volatile DiaphragmOrgans organs;

    /**
     * From now on, every scene has these organs in its state, drawn translucent ({@link DiaphragmOrgansViewScene});
     * null for none. The organs run with the full model: the mapped mechanics are not used with them.
     */
    public void setOrgans(DiaphragmOrgans o) {
        organs = o;
    }

    /** The organs set, or null. */
    public DiaphragmOrgans organs() {
        return organs;
    }

    /** The mapped mechanics set, or null. */
    public Mechanics mechanics() {
        return mechanics;
    }

    /** Whether the next scenes run the full model unmapped (true) or the mapped mechanics when set (false). */
    public void setFullModel(boolean full) {
        fullModel = full;
    }

    /** Whether the full model is chosen over the mapped mechanics. */
    public boolean fullModel() {
        return fullModel;
    }

    /** The run of the scene file its spec comes from ({@link DiaphragmSceneFile}), or null. */
    private volatile org.tensim.scene.file.RunSettings fileRun;

    /** What the scene file applies to each diaphragm built (its regions, conditions), giving its probes; or null. */
    private volatile java.util.function.Function<DiaphragmSetup.Built, List<org.tensim.scene.file.SceneProbe>> extras;

    /**
     * From now on its scenes run as the scene file's run says, their controls starting at their values, and each
     * diaphragm built takes the file's regions and conditions ({@code extras}, null for none) before it runs: the
     * scene {@code tensim run} runs. With them the scenes run unmapped.
     */
    void openedFrom(org.tensim.scene.file.RunSettings run,
            java.util.function.Function<DiaphragmSetup.Built, List<org.tensim.scene.file.SceneProbe>> extras) {
        fileRun = run;
        this.extras = extras;
    }

    /** The diaphragm the file's loader built, its conditions on it, with its probes: the first scene's, or null. */
    private DiaphragmSetup.Built loaded;
    private List<org.tensim.scene.file.SceneProbe> loadedProbes = List.of();

    /**
     * The next scene of the loaded file's own spec is {@code built} itself (with {@code probes}), once, instead of
     * the same diaphragm built a second time.
     */
    synchronized void firstIs(DiaphragmSetup.Built built, List<org.tensim.scene.file.SceneProbe> probes) {
        loaded = built;
        loadedProbes = List.copyOf(probes);
    }

    /** How many diaphragms this factory has built for its scenes (the loader's, when taken, not counted). */
    private final java.util.concurrent.atomic.AtomicInteger builds = new java.util.concurrent.atomic.AtomicInteger();

    int builds() {
        return builds.get();
    }

    /** The loaded diaphragm when its spec is {@code spec} and nothing was painted (then never again), else null. */
    private synchronized DiaphragmSetup.Built loadedFor(DiaphragmSpec spec, Painted painting) {
        DiaphragmSetup.Built b = loaded;
        loaded = null;
        if (b == null || painting != null || organs != null) {
            return null;
        }
        DiaphragmSpec own = b.scene().spec();
        DiaphragmSpec.Breathing br = own.breathing();
        if (br.musclePa() == null) { // the load's default, which the view names
            own = own.withBreathing(new DiaphragmSpec.Breathing(br.periodS(), br.expirationRatio(), br.ribAmplitude(),
                    DiaphragmSetup.defaultMusclePa(own.boundary().muscleLoad()), br.abdominalPressurePa(),
                    br.pauseShare()));
        }
        return own.equals(spec) ? b : null;
    }

    DiaphragmViewFactory(DiaphragmSpec base, DiaphragmSetup.Inputs read) {
        this.base = base;
        this.bc = base.boundary();
        this.inputs = read;
    }

    /**
     * From now on, scenes are built with these labels, one per mesh vertex, as from the label file they
     * were saved to ({@code file}, which the spec then names): the tendon and the origins as painted.
     */
    public void paintLabels(VertexLabel[] labels, Path file) {
        painted = new Painted(labels.clone(), java.util.Objects.requireNonNull(file, "label file"));
    }

    /** The spec the next scene is built from (its label file the painted one, if any). */
    public DiaphragmSpec spec() {
        Painted p = painted;
        return p == null ? base : base.withMesh(base.mesh().withLabels(p.file()));
    }

    @Override
    public String name() {
        return "diaphragm";
    }

    @Override
    public boolean hasTendonChoice() {
        return true;
    }

    private synchronized DiaphragmSetup.Inputs inputs() throws IOException, MeshFormatException {
        if (inputs == null) {
            inputs = DiaphragmSetup.read(base);
        }
        return inputs;
    }

    private synchronized DiaphragmSetup.Inputs coarseInputs(DiaphragmSpec coarse) throws IOException,
            MeshFormatException {
        if (coarseInputs == null || coarseRings != coarse.mesh().rings()) {
            coarseInputs = DiaphragmSetup.read(coarse);
            coarseRings = coarse.mesh().rings();
        }
        return coarseInputs;
    }

    @Override
    public BoundaryConditions.MuscleLoad muscleLoad() {
        return bc.muscleLoad();
    }

    @Override
    public ViewScene create(boolean tensegrityTendon, Map<String, Double> values) {
        return create(tensegrityTendon, null, values);
    }

    @Override
    public List<TunableParameter> parameters(BoundaryConditions.MuscleLoad muscleLoad) {
        return DiaphragmViewScene.parameters(muscleLoad, base.tendonRule(), spec().mesh().labels() != null);
    }

    @Override
    public ViewScene create(boolean tensegrityTendon, BoundaryConditions.MuscleLoad muscleLoad,
            Map<String, Double> values) {
        BoundaryConditions b = muscleLoad == null ? bc : bc.withMuscleLoad(muscleLoad);
        // A value not given is a scene file's (the muscle action only with its load, whose stress it is), else quiet
        // breathing's, where the built-in scene's controls start.
        DiaphragmSpec.Breathing given = fileRun != null ? base.breathing() : DiaphragmSpec.Breathing.defaults();
        double period = values.getOrDefault(DiaphragmViewScene.BREATHING_PERIOD, given.periodS());
        double musclePa = given.musclePa() != null && b.muscleLoad() == bc.muscleLoad() ? given.musclePa()
                : DiaphragmSetup.defaultMusclePa(b.muscleLoad());
        Painted painting = painted;
        DiaphragmSpec spec = (painting == null ? base : base.withMesh(base.mesh().withLabels(painting.file())))
                .withBoundary(b).withActionLines(b.muscleLoad()
                == BoundaryConditions.MuscleLoad.FIBRES ? null : base.actionLines())
                .withBreathing(new DiaphragmSpec.Breathing(period, given.expirationRatio(),
                        values.getOrDefault(DiaphragmViewScene.RIB_AMPLITUDE, given.ribAmplitude()),
                        values.getOrDefault(DiaphragmViewScene.MUSCLE_ACTION, musclePa),
                        base.breathing().abdominalPressurePa(), base.breathing().pauseShare()));
        try {
            DiaphragmSetup.Inputs in = inputs();
            if (painting != null) {
                in = new DiaphragmSetup.Inputs(in.surfaces(), in.report(), in.boxes(), in.bones(),
                        painting.labels(), in.source());
            }
            DiaphragmSpec fineSpec = withTendonBoundary(spec, in.surfaces().surfaces(), values);
            DiaphragmControls controls = fineSpec.newControls();
            var fileExtras = extras;
            DiaphragmSetup.Built fine = loadedFor(fineSpec, painting);
            List<org.tensim.scene.file.SceneProbe> probes = fine != null ? loadedProbes : List.of();
            if (fine == null) {
                fine = DiaphragmSetup.build(in, fineSpec, controls);
                builds.incrementAndGet();
                probes = fileExtras == null ? List.of() : fileExtras.apply(fine);
            }
            DiaphragmScene s = fine.scene();
            DiaphragmOrgans o = organs;
            if (o != null) {
                DiaphragmOrgans.Built built = o.install(s);
                return new DiaphragmOrgansViewScene(new DiaphragmViewScene(s, tensegrityTendon, b.muscleLoad(), o,
                        built), built);
            }
            Mechanics m = mechanics;
            if (m == null || fullModel || painting != null || fileExtras != null) {
                DiaphragmViewScene v = new DiaphragmViewScene(s, tensegrityTendon, b.muscleLoad());
                return fileRun == null ? v : v.asFile(fileRun, probes);
            }
            DiaphragmSpec coarse = spec.withMesh(spec.mesh().withFile(null, spec.mesh().units()).withRings(m.rings()));
            DiaphragmSetup.Inputs cin = coarseInputs(coarse);
            coarse = withTendonBoundary(coarse, cin.surfaces().surfaces(), values);
            DiaphragmScene c = DiaphragmSetup.build(cin, coarse, controls).scene();
            return new DiaphragmMappedViewScene(new DiaphragmViewScene(c, tensegrityTendon, b.muscleLoad()),
                    MappedDiaphragm.of(c, s), m);
        } catch (IOException e) {
            throw new UncheckedIOException(e.getMessage(), e);
        } catch (MeshFormatException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
    }

    /**
     * The spec with the tendon's boundary the values set: the area share of the geodesic rule
     * ({@link DiaphragmViewScene#TENDON_SHARE}), or the plane of the plane rule moved along its normal by {@link DiaphragmViewScene#TENDON_PLANE} mm from
     * where the spec's share (or point) places it; unchanged with a label file or without either value.
     *
     * @throws IllegalArgumentException when the moved plane leaves no tendon or no muscle on the upper surface
     */
    static DiaphragmSpec withTendonBoundary(DiaphragmSpec spec, TwoSurfaces surfaces, Map<String, Double> values) {
        if (spec.mesh().labels() != null) {
            return spec;
        }
        DiaphragmParameters p = spec.tissue();
        if (spec.tendonRule() == TendonRule.GEODESIC) {
            Double share = values.get(DiaphragmViewScene.TENDON_SHARE);
            return share == null ? spec : spec.withTissue(p.withTendonAreaFraction(share));
        }
        Double shiftMm = values.get(DiaphragmViewScene.TENDON_PLANE);
        if (shiftMm == null || shiftMm == 0) {
            return spec;
        }
        Vec3 n = p.tendonNormal();
        double from = p.tendonPoint() != null ? n.dot(p.tendonPoint())
                : TendonPlane.offsetForShare(surfaces, n, p.tendonAreaFraction());
        double to = from + 1e-3 * shiftMm;
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (int v = 0; v < surfaces.mesh().vertexCount(); v++) {
            if (surfaces.isUpper(v)) {
                double h = n.x() * surfaces.mesh().coord(v, 0) + n.y() * surfaces.mesh().coord(v, 1)
                        + n.z() * surfaces.mesh().coord(v, 2);
                lo = Math.min(lo, h);
                hi = Math.max(hi, h);
            }
        }
        if (!(to <= hi && to > lo)) {
            throw new IllegalArgumentException(String.format(java.util.Locale.ROOT, "tendon plane height %+.1f mm"
                    + " puts the plane %s the upper surface (it spans %.1f to %+.1f mm from the default plane): no %s"
                    + " would be left", shiftMm, to > hi ? "above" : "below", 1e3 * (lo - from), 1e3 * (hi - from),
                    to > hi ? "tendon" : "muscle"));
        }
        return spec.withTissue(p.withTendonPlane(n, n.times(to)));
    }
}

package org.tensim.scene.tunable;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.tensim.io.mesh.MeshFormatException;
import org.tensim.io.mesh.VertexLabel;
import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.DiaphragmScene;
import org.tensim.scene.diaphragm.DiaphragmSetup;
import org.tensim.scene.diaphragm.DiaphragmSpec;

/**
 * The diaphragm's scene factory. Besides its spec's scenes it takes labels painted by the user
 * ({@link #paintLabels}): the scenes it makes from then on are built with them, as from a label file.
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

    private record Painted(VertexLabel[] labels, Path file) {
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
        double period = values.getOrDefault(DiaphragmViewScene.BREATHING_PERIOD, 4.0);
        Painted painting = painted;
        DiaphragmSpec spec = (painting == null ? base : base.withMesh(base.mesh().withLabels(painting.file())))
                .withBoundary(b).withActionLines(b.muscleLoad()
                == BoundaryConditions.MuscleLoad.FIBRES ? null : base.actionLines())
                .withBreathing(new DiaphragmSpec.Breathing(period, DiaphragmViewScene.EXPIRATION_RATIO,
                        values.getOrDefault(DiaphragmViewScene.RIB_AMPLITUDE, 1.0),
                        values.getOrDefault(DiaphragmViewScene.MUSCLE_ACTION,
                                DiaphragmSetup.defaultMusclePa(b.muscleLoad())),
                        base.breathing().abdominalPressurePa()));
        try {
            DiaphragmSetup.Inputs in = inputs();
            if (painting != null) {
                in = new DiaphragmSetup.Inputs(in.surfaces(), in.report(), in.boxes(), in.bones(),
                        painting.labels(), in.source());
            }
            spec = DiaphragmViewScene.withTendonBoundary(spec, in.surfaces().surfaces(), values);
            DiaphragmScene s = DiaphragmSetup.build(in, spec, spec.newControls()).scene();
            return new DiaphragmViewScene(s, tensegrityTendon, b.muscleLoad());
        } catch (IOException e) {
            throw new UncheckedIOException(e.getMessage(), e);
        } catch (MeshFormatException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
    }
}

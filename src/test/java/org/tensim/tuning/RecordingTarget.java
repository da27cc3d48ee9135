package org.tensim.tuning;

import java.util.List;
import org.tensim.solver.integrators.IntegratorChoice;

/** A tuning target that records what reaches it, as "key=value" in order (preset tests). */
public final class RecordingTarget implements Tuning.Target {
    private final List<String> applied;

    public RecordingTarget(List<String> applied) {
        this.applied = applied;
    }

    @Override
    public void applyParameter(String key, double value) {
        applied.add(key + "=" + value);
    }

    @Override
    public void applyIntegrator(IntegratorChoice choice) {
        applied.add("integrator=" + choice.name());
    }

    @Override
    public void applyTendonModel(boolean tensegrity) {
        applied.add("tendon=" + tensegrity);
    }

    @Override
    public void applyMuscleLoad(org.tensim.scene.diaphragm.BoundaryConditions.MuscleLoad load) {
        applied.add("muscleLoad=" + org.tensim.scene.diaphragm.BoundaryConditions.name(load));
    }
}

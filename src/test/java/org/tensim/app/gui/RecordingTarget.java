package org.tensim.app.gui;

import java.util.List;

/** A tuning target that records what reaches it, as "key=value" in order (preset tests). */
final class RecordingTarget implements Tuning.Target {
    private final List<String> applied;

    RecordingTarget(List<String> applied) {
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
    public void applyMuscleLoad(String load) {
        applied.add("muscleLoad=" + load);
    }
}

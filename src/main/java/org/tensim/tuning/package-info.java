/**
 * The headless model of a tuning session: the scenes that can be tuned, by name
 * ({@link org.tensim.tuning.TunableScenes}), the parameters, integrator and step of a
 * session ({@link org.tensim.tuning.Tuning}, {@link org.tensim.tuning.Settings}), presets
 * and last-used parameters ({@link org.tensim.tuning.PresetFile},
 * {@link org.tensim.tuning.ConfigDir}) and the simulation thread
 * ({@link org.tensim.tuning.SimulationRunner}). The GUI ({@code org.tensim.app.gui}, Swing
 * only), sweeps and calibration share it. It sits above scenes, solver and I/O and below
 * the view and the application: it uses no Swing, AWT or Java3D, and nothing of
 * {@code app}.
 */
package org.tensim.tuning;

/**
 * Lung motion in normalised terms, for comparing a model with measured 4D-CT landmarks of other people: the
 * superior-inferior displacement against normalised height ({@link SiProfile}), each phase's share of the
 * end-inhale displacement ({@link PhaseShares}), the split of a point cloud into its two lungs
 * ({@link LungSplit}), the figures of measured cases ({@link MeasuredCase}), a model's points over its cycle
 * ({@link ModelMotion}, in a run folder {@link LungPointsFolder}), its figures in the same terms
 * ({@link ModelFigures}) and the comparison with the targets' verdicts ({@link FourDctComparison}). Reads the
 * measured sets through io.landmarks; draws no chart.
 */
package org.tensim.analysis.lungs;

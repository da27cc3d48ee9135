/**
 * Lung motion in normalised terms, for comparing a model with measured 4D-CT landmarks of other people: the
 * superior-inferior displacement against normalised height ({@link SiProfile}), each phase's share of the
 * end-inhale displacement ({@link PhaseShares}), the split of a point cloud into its two lungs
 * ({@link LungSplit}) and the figures of measured cases ({@link MeasuredCases}). Depends on io.landmarks only for
 * the measured sets; knows nothing of charts or files.
 */
package org.tensim.analysis.lungs;

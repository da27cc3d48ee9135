/**
 * The lungs as volume bodies: each lung's lobes from the shared thorax merged into one closed surface and filled
 * with a lattice of the volumetric fit ({@link org.tensim.scene.lungs.LungVolumes}), and points sampled in their
 * volumes to follow and compare with measured 4D-CT motion ({@link org.tensim.scene.lungs.LungSamples}); the
 * parietal pleura carried by the diaphragm and the ribs ({@link org.tensim.scene.lungs.PleuraCarriers}) and the
 * lungs and liver built into a diaphragm scene's state with their couplings
 * ({@link org.tensim.scene.lungs.ThoraxOrgans}). See docs/lungs.md.
 */
package org.tensim.scene.lungs;

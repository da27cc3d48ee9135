/**
 * The organs of a thorax run recorded: the lung points over the measured cycle, the couplings' departures from
 * their rest relation, the liver's motion ({@link org.tensim.experiment.lungs.OrganRecorder}). See docs/lungs.md.
 */
package org.tensim.experiment.lungs;

/**
 * Numerical analysis of the solver: reference solutions (Hipparchus), the
 * accuracy (work-precision) study and the stability study behind
 * {@code ./tensim accuracy} and {@code ./tensim stability}. Depends on model and
 * solver; knows nothing of charts or files (the app layer writes those).
 */
package org.tensim.analysis;

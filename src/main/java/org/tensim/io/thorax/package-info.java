/**
 * Reading a thorax (ribs, costal cartilages, sternum, vertebrae, organs) from a folder of surface meshes and the
 * {@code parts.json} that lists them ({@link org.tensim.io.thorax.ThoraxLoader}). Coordinates come out in metres.
 */
package org.tensim.io.thorax;

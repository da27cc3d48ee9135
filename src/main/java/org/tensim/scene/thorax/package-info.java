/**
 * The thorax as contact bodies: signed distance grids of bones built from their surface meshes
 * ({@link org.tensim.scene.thorax.DistanceGrid}).
 */
package org.tensim.scene.thorax;

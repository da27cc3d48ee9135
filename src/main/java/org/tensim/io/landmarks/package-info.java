/**
 * Reading measured landmark sets: DIR-Lab's expert landmarks on 4D-CT of the lungs ({@link DirLabLandmarks}), as
 * the shared folder {@code ../shared/data/4dct-lung-landmarks} holds them. Coordinates come out in metres, in each
 * scan's own frame, with the frame's superior direction named ({@link LandmarkSet#superior()}).
 */
package org.tensim.io.landmarks;

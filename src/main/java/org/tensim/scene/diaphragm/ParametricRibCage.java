package org.tensim.scene.diaphragm;

import java.util.LinkedHashMap;
import java.util.Map;
import org.tensim.model.Check;

/**
 * The project's own rib cage and sternum: twelve pairs of ribs and a sternum laid out from
 * anatomical dimensions, placed on the generated double dome, as the named boxes that
 * {@link RibCage} fills with ribs ({@code rib-r1..rib-r12}, {@code rib-l1..rib-l12},
 * {@code sternum}; metres, BodyParts3D frame: x = patient's left, y = posterior, z = superior).
 * It makes the diaphragm scene independent of BodyParts3D's boxes, which stay one option.
 *
 * <p><b>Anatomy</b> (the defaults, {@link Dimensions#adult()}):
 * <ul>
 * <li>12 pairs of ribs: 1-7 true (their cartilage reaches the sternum), 8-10 false (their
 *     cartilage joins the one above), 11-12 floating (Gray, <i>Anatomy of the Human Body</i>,
 *     1918, section II.4b). {@link RibCage} wires the cartilage that way.</li>
 * <li>Rib heads one thoracic level apart: a vertebral body plus a disc. Thoracic bodies are
 *     about 17 mm high at T2 to 20-23 mm at T9-T12 (Panjabi et al., Spine 1991; Egwu et al.,
 *     J Anat Soc India 2019), discs 4.5-7.2 mm, thicker caudally (Kunkel et al., J Anat 2011):
 *     the spacing grows linearly from 22 mm (T1-T2) to 30 mm (T11-T12).</li>
 * <li>Inclination: each rib runs down from its head to its anterior end; the drop, in
 *     vertebral levels, rises from 2.7 at rib 1 to 5.1 at rib 8 and falls to 2.7 at rib 12
 *     (Gray: the obliquity increases down to the ninth rib and decreases below it).</li>
 * <li>Rib lengths: the ribs lengthen from the first to the seventh and shorten below it (Gray);
 *     the cage is widest at ribs 7-8 (274 mm across) and deepest at rib 6 (190 mm from the
 *     rib angles to the anterior ends).</li>
 * <li>Sternum: 170 mm long (Gray: "about 17 cm" in the adult, longer in men), inclined
 *     forwards from above downwards (Gray) by 18.5 degrees from the vertical, 54 mm wide.</li>
 * </ul>
 * The profiles' shapes (peak rib, exponents) were fitted to BodyParts3D's boxes of an adult
 * male (rib-sternum-bounds-mm.json): every box face lies within 17 mm of theirs
 * (docs/diaphragm.md). Each profile is {@link Profile}: a value at rib 1, a peak at a rib, a
 * value at rib 12, and a power law in between.
 *
 * <p><b>Placement</b> on the dome ({@link #forDome}): the sternum's lower end (the xiphoid) is the
 * dome's anterior rim point, where the rim rises to the xiphoid; rib 9's head is
 * {@code rib9HeadAboveXiphoidMm} above it (the xiphisternal joint lies at the level of T9 in
 * clinical anatomy); the rib angles lie {@code thoraxDepthMm} behind the xiphoid at rib 7 and
 * further forwards above and below (the thoracic kyphosis).
 */
public final class ParametricRibCage {
    /** Rib pairs: RibCage's cartilage wiring (true 1-7, false 8-10, floating 11-12) is for twelve. */
    public static final int RIB_PAIRS = 12;

    private ParametricRibCage() {
    }

    /**
     * A quantity along the ribs: {@code rib1} at rib 1, {@code peak} at rib {@code peakRib},
     * {@code rib12} at rib 12, and in between
     * {@code peak - (peak - end) ((r - peakRib) / (endRib - peakRib))^exponent} towards each end.
     */
    public record Profile(double rib1, double peakRib, double peak, double rib12, double exponent) {
        public Profile {
            Check.finite("profile value at rib 1", "-", rib1);
            Check.finite("profile peak", "-", peak);
            Check.finite("profile value at rib 12", "-", rib12);
            Check.positive("profile exponent", "-", exponent);
            if (!(peakRib > 1 && peakRib < RIB_PAIRS)) {
                throw new IllegalArgumentException("profile peak rib " + peakRib + " must lie between 1 and "
                        + RIB_PAIRS + " (exclusive)");
            }
        }

        /** The value at rib r (1..12). */
        public double at(int r) {
            boolean upper = r <= peakRib;
            double t = upper ? (peakRib - r) / (peakRib - 1) : (r - peakRib) / (RIB_PAIRS - peakRib);
            return peak - (peak - (upper ? rib1 : rib12)) * Math.pow(t, exponent);
        }
    }

    /**
     * The cage's dimensions, millimetres and degrees.
     *
     * @param levelSpacingTopMm      vertical distance from rib 1's head to rib 2's (T1-T2 level), mm
     * @param levelSpacingBottomMm   from rib 11's head to rib 12's (T11-T12), mm; linear in between
     * @param endDropLevels          drop from each rib's head to its anterior end, in vertebral levels
     * @param halfWidthMm            lateral extent of each rib from the midline, mm
     * @param depthMm                antero-posterior extent of each rib (rib angle to anterior end), mm
     * @param angleOffsetMm          y of each rib's angle relative to the rearmost (negative: forwards), mm
     * @param headOffsetMm           distance of the rib heads from the midline, mm (half a vertebral body)
     * @param sternumLengthMm        manubrium to xiphoid tip, mm
     * @param sternumInclinationDeg  angle of the sternum from the vertical, its top further back, degrees
     * @param sternumWidthMm         width of the sternum's box, mm
     * @param rib9HeadAboveXiphoidMm height of rib 9's head above the xiphoid tip, mm
     * @param thoraxDepthMm          from the xiphoid tip back to the rearmost rib angle, mm
     */
    public record Dimensions(double levelSpacingTopMm, double levelSpacingBottomMm, Profile endDropLevels,
            Profile halfWidthMm, Profile depthMm, Profile angleOffsetMm, double headOffsetMm, double sternumLengthMm,
            double sternumInclinationDeg, double sternumWidthMm, double rib9HeadAboveXiphoidMm,
            double thoraxDepthMm) {
        public Dimensions {
            Check.positive("rib level spacing at the top", "mm", levelSpacingTopMm);
            Check.positive("rib level spacing at the bottom", "mm", levelSpacingBottomMm);
            Check.positive("rib head offset from the midline", "mm", headOffsetMm);
            Check.positive("sternum length", "mm", sternumLengthMm);
            Check.positive("sternum width", "mm", sternumWidthMm);
            Check.finite("rib 9 head above the xiphoid", "mm", rib9HeadAboveXiphoidMm);
            Check.positive("thorax depth", "mm", thoraxDepthMm);
            if (!(sternumInclinationDeg >= 0 && sternumInclinationDeg < 60)) {
                throw new IllegalArgumentException("sternum inclination " + sternumInclinationDeg
                        + " degrees: expected 0 to 60 (from the vertical)");
            }
            for (int r = 1; r <= RIB_PAIRS; r++) {
                if (!(endDropLevels.at(r) > 0 && depthMm.at(r) > 0 && halfWidthMm.at(r) > headOffsetMm)) {
                    throw new IllegalArgumentException("rib " + r + ": drop " + endDropLevels.at(r) + " levels, depth "
                            + depthMm.at(r) + " mm, half-width " + halfWidthMm.at(r)
                            + " mm; expected a positive drop and depth and a half-width beyond the head offset "
                            + headOffsetMm + " mm");
                }
            }
        }

        /** An adult male thorax (the sources and the fit are in the class comment). */
        public static Dimensions adult() {
            return new Dimensions(22, 30, new Profile(2.7, 8, 5.1, 2.7, 2.2), new Profile(70, 7.5, 137, 87, 2),
                    new Profile(66, 6, 190, 38, 1.75), new Profile(-60, 7, 0, -24, 2), 15, 170, 18.5, 54, 21, 202);
        }

        /** Vertical distance from rib r's head to rib r+1's, mm (r = 1..11). */
        public double levelSpacingMm(int r) {
            return levelSpacingTopMm + (levelSpacingBottomMm - levelSpacingTopMm) * (r - 1) / (RIB_PAIRS - 2);
        }
    }

    /**
     * The boxes of the cage placed on a dome: its xiphoid at the dome's anterior rim point.
     *
     * @return {min x, min y, min z, max x, max y, max z} in metres, by name, sternum first
     */
    public static Map<String, double[]> forDome(Dimensions d, DoubleDomeGenerator.Shape dome) {
        return boxes(d, 0, dome.centreY() - dome.semiAxisY(), dome.rimLateral() + dome.rimAnteriorRise());
    }

    /** The default cage on the default dome. */
    public static Map<String, double[]> adult() {
        return forDome(Dimensions.adult(), DoubleDomeGenerator.Shape.adult());
    }

    /**
     * The boxes with the xiphoid tip at (xiphoidX, xiphoidY, xiphoidZ), metres.
     *
     * @return {min x, min y, min z, max x, max y, max z} in metres, by name, sternum first
     */
    public static Map<String, double[]> boxes(Dimensions d, double xiphoidX, double xiphoidY, double xiphoidZ) {
        double mm = 1e-3;
        Map<String, double[]> out = new LinkedHashMap<>();
        // RibCage runs the sternum from TOP of the box's depth behind its back face down to BOTTOM above its
        // front face; the box is sized so that this line has the given length and inclination.
        double incl = Math.toRadians(d.sternumInclinationDeg());
        double rise = d.sternumLengthMm() * Math.cos(incl) * mm;
        double back = d.sternumLengthMm() * Math.sin(incl) * mm;
        double depth = back / (1 - RibCage.STERNUM_TOP_DEPTH_FRACTION - RibCage.STERNUM_BOTTOM_DEPTH_FRACTION);
        double yFront = xiphoidY - RibCage.STERNUM_BOTTOM_DEPTH_FRACTION * depth;
        double halfWidth = 0.5 * d.sternumWidthMm() * mm;
        out.put("sternum", new double[] {xiphoidX - halfWidth, yFront, xiphoidZ, xiphoidX + halfWidth,
            yFront + depth, xiphoidZ + rise});
        double[] head = new double[RIB_PAIRS + 1];
        head[9] = xiphoidZ + d.rib9HeadAboveXiphoidMm() * mm;
        for (int r = 8; r >= 1; r--) {
            head[r] = head[r + 1] + d.levelSpacingMm(r) * mm;
        }
        for (int r = 10; r <= RIB_PAIRS; r++) {
            head[r] = head[r - 1] - d.levelSpacingMm(r - 1) * mm;
        }
        double rearmost = xiphoidY + d.thoraxDepthMm() * mm;
        for (String side : new String[] {"r", "l"}) {
            double sign = side.equals("r") ? -1 : 1;
            for (int r = 1; r <= RIB_PAIRS; r++) {
                double drop = d.endDropLevels().at(r) * d.levelSpacingMm(Math.min(r, RIB_PAIRS - 1)) * mm;
                double posterior = rearmost + d.angleOffsetMm().at(r) * mm;
                double medial = xiphoidX + sign * d.headOffsetMm() * mm;
                double lateral = xiphoidX + sign * d.halfWidthMm().at(r) * mm;
                out.put("rib-" + side + r, new double[] {Math.min(medial, lateral), posterior - d.depthMm().at(r) * mm,
                    head[r] - drop, Math.max(medial, lateral), posterior, head[r]});
            }
        }
        return out;
    }
}

package simpview.compare;

/**
 * Colours put through sRGB's gamma: a renderer that takes its colours for
 * linear light and encodes them as sRGB before writing them (by its own
 * conversion, or an image type or library that converts), or decodes them
 * the other way. Every shape is in place and the black and white pixels are
 * right, but each level between is moved along one curve: brighter in the
 * darks when encoded, darker when decoded. The patches cover whatever is
 * shaded, and the pixel to look at says only "brighter"; this names the
 * curve, measured on the pixels that differ.
 */
final class SrgbGamma {

    /** Below this share of the panel differing beyond the tolerance, nothing is said. */
    static final double MIN_DIFFERING = 0.01;
    /** The least share of the differing pixels the curve must explain, each channel within the tolerance. */
    static final double MIN_EXPLAINED = 0.9;

    /** Each level 0 to 255 encoded as sRGB (linear to sRGB), rounded. */
    private static final int[] ENCODED = new int[256];
    /** Each level decoded from sRGB (sRGB to linear), rounded. */
    private static final int[] DECODED = new int[256];

    static {
        for (int v = 0; v < 256; v++) {
            double c = v / 255.0;
            double encoded = c <= 0.0031308 ? 12.92 * c : 1.055 * Math.pow(c, 1 / 2.4) - 0.055;
            double decoded = c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
            ENCODED[v] = (int) Math.round(encoded * 255);
            DECODED[v] = (int) Math.round(decoded * 255);
        }
    }

    private SrgbGamma() {
    }

    /**
     * The note (after "note: ") on the comparison's picture against simpview's, or null when too few pixels
     * differ beyond the tolerance, or neither curve explains {@link #MIN_EXPLAINED} of them.
     */
    static String note(Comparison comparison, int tolerance) {
        if (1 - comparison.share(tolerance, false) < MIN_DIFFERING) {
            return null; // counted already: no pass over the pixels
        }
        int[] ours = comparison.ours();
        int[] theirs = comparison.theirs();
        long differing = 0;
        long encoded = 0;
        long decoded = 0;
        for (int i = 0; i < ours.length; i++) {
            int a = ours[i];
            int b = theirs[i];
            if (comparison.distance(i) <= tolerance) {
                continue;
            }
            differing++;
            encoded += Rasters.distance(through(a, ENCODED), b) <= tolerance ? 1 : 0;
            decoded += Rasters.distance(through(a, DECODED), b) <= tolerance ? 1 : 0;
        }
        boolean encodes = encoded >= decoded;
        long explained = Math.max(encoded, decoded);
        if (explained < MIN_EXPLAINED * differing) {
            return null;
        }
        String curve = encodes
                ? "encoded as sRGB (linear to sRGB: 255 * (1.055 * (c / 255)^(1/2.4) - 0.055), brighter in the darks)"
                : "decoded from sRGB (sRGB to linear: 255 * ((c / 255 + 0.055) / 1.055)^2.4, darker in the darks)";
        return "your colours look put through sRGB's gamma: of the " + Count.of(differing, "pixel") + " that differ"
                + " by more than " + tolerance + "/255, " + Percent.of((double) explained / differing)
                + " are simpview's colours " + curve + ", within " + tolerance + "/255. SPEC writes each channel as"
                + " it is, round(c * 255), with no gamma: look for a colour space conversion (an sRGB or linear image"
                + " type, a library's gamma setting, or pow(c, 1/2.2) of your own)";
    }

    /** The colour with each channel mapped by {@code levels}. */
    private static int through(int colour, int[] levels) {
        return levels[colour >> 16 & 0xFF] << 16 | levels[colour >> 8 & 0xFF] << 8 | levels[colour & 0xFF];
    }
}

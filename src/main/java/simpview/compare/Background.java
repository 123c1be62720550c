package simpview.compare;

/**
 * A background of another colour: where simpview's panel has its most common
 * colour (the colour the panel is cleared to, where nothing is drawn) on a
 * large part of the panel, the picture has one other colour on nearly all of
 * those pixels. A renderer that clears its panel to a colour of its own
 * (grey, white, the window's) fails on every pixel nothing covers, and the
 * shares and the one patch of the whole panel do not say why; this says what
 * was measured.
 */
final class Background {

    /** simpview's most common colour must cover at least this share of the panel to be taken as its background. */
    static final double MIN_SHARE = 0.10;
    /** And the picture must have its one other colour on at least this share of those pixels. */
    static final double SAME_SHARE = 0.95;

    private Background() {
    }

    /**
     * The note (after "note: ") on theirs against ours, two panels of 0xRRGGBB pixels, judged within
     * {@code tolerance}; or null when the picture's pixels where simpview's panel has its most common colour are not
     * nearly all of one other colour.
     */
    static String note(int[] ours, int[] theirs, int tolerance) {
        int background = mostCommon(ours, null, 0);
        int cleared = 0;
        for (int rgb : ours) {
            if ((rgb & 0xFFFFFF) == background) {
                cleared++;
            }
        }
        if (cleared < MIN_SHARE * ours.length) {
            return null;
        }
        int theirsThere = mostCommon(theirs, ours, background);
        if (Rasters.distance(theirsThere, background) <= tolerance) {
            return null;
        }
        int same = 0;
        int rest = 0;
        int restWithin = 0;
        for (int i = 0; i < ours.length; i++) {
            if ((ours[i] & 0xFFFFFF) == background) {
                if ((theirs[i] & 0xFFFFFF) == theirsThere) {
                    same++;
                }
            } else {
                rest++;
                if (Rasters.distance(ours[i], theirs[i]) <= tolerance) {
                    restWithin++;
                }
            }
        }
        if (same < SAME_SHARE * cleared) {
            return null;
        }
        return "where simpview's panel is " + Rasters.words(background) + ", its most common colour ("
                + Percent.of((double) cleared / ours.length) + " of the panel: the background, where nothing is drawn),"
                + " yours is " + Rasters.words(theirsThere) + " at " + Percent.of((double) same / cleared)
                + " of those pixels" + (rest == 0 ? "" : "; the rest of the panel is within " + tolerance + "/255 at "
                + Percent.of((double) restWithin / rest) + ", exactly") + ": is the colour your panel is cleared to "
                + "the course's, " + Rasters.words(background) + "?";
    }

    /**
     * The most common colour of {@code pixels}; with {@code where}, only of the pixels at which {@code where} has
     * the colour {@code only}. Of two as common, the one that got there first in pixel order.
     */
    static int mostCommon(int[] pixels, int[] where, int only) {
        ColourCounts counts = new ColourCounts();
        int best = 0;
        int bestCount = -1;
        for (int i = 0; i < pixels.length; i++) {
            if (where != null && (where[i] & 0xFFFFFF) != only) {
                continue;
            }
            int rgb = pixels[i] & 0xFFFFFF;
            int count = counts.add(rgb);
            if (count > bestCount) {
                best = rgb;
                bestCount = count;
            }
        }
        return best;
    }

    /**
     * How many times each colour was added: open addressing over int arrays,
     * a colour's slot picked by a multiplicative hash. (A HashMap of Integer
     * boxed each pixel, and Integer's hash folds each grey 0xVVVVVV to a low
     * byte of 0, so a page's greys shared a few buckets.)
     */
    private static final class ColourCounts {
        /** A slot's colour with bit 24 set, 0 while the slot is free. */
        private int[] keys = new int[1 << 12];
        private int[] counts = new int[1 << 12];
        private int bits = 12;
        private int used;

        /** Counts rgb (0xRRGGBB) once more: its count now. */
        int add(int rgb) {
            int key = rgb | 1 << 24;
            int slot = slot(key);
            if (keys[slot] == 0) {
                if (2 * (used + 1) > keys.length) {
                    grow();
                    slot = slot(key);
                }
                keys[slot] = key;
                used++;
            }
            return ++counts[slot];
        }

        /** The slot holding key, or the free one it would go in. */
        private int slot(int key) {
            int mask = keys.length - 1;
            int slot = key * 0x9E3779B9 >>> 32 - bits;
            while (keys[slot] != 0 && keys[slot] != key) {
                slot = slot + 1 & mask;
            }
            return slot;
        }

        private void grow() {
            int[] oldKeys = keys;
            int[] oldCounts = counts;
            bits++;
            keys = new int[1 << bits];
            counts = new int[1 << bits];
            for (int i = 0; i < oldKeys.length; i++) {
                if (oldKeys[i] != 0) {
                    int slot = slot(oldKeys[i]);
                    keys[slot] = oldKeys[i];
                    counts[slot] = oldCounts[i];
                }
            }
        }
    }
}

package simpview.surface;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.util.Arrays;

/**
 * The end of every chain: a BufferedImage written through its int[] raster.
 * Image coordinates: origin top-left, y down. Writes outside are dropped.
 *
 * <p>Rows may be owed a fill ({@link #oweRows}): a page canvas's clear,
 * made when the image is next read or written on one thread (each way in
 * settles it first), or by {@link #settle} before several threads write at
 * once, or handed to a picture's band drawers to make row by row on their
 * own threads ({@link #fillOwedByRows}).
 */
public final class ImageDrawable implements Drawable {

    /** Spans shorter than this skip the clamp-free path: 6 conversions to check it, 3 per pixel to clamp. */
    private static final int SHORT_SPAN = 3;
    /** 0, 1, 2, ...: k + RAMP[j] is k + j, exactly. */
    private static final double[] RAMP = new double[1024];

    static {
        for (int j = 0; j < RAMP.length; j++) {
            RAMP[j] = j;
        }
    }

    private BufferedImage image;
    private int[] pixels;
    private final int width;
    private final int height;
    /** What each owed row is to be: width pixels, kept, not copied. */
    private int[] owedRow;
    /** Rows owedFrom &lt;= y &lt; owedTo are owed {@link #owedRow}; an empty range when none is. */
    private int owedFrom;
    private int owedTo;
    /**
     * True while the owed rows are to be made by the next read or write
     * ({@link #settle}), not by rows: set and read on the thread that clears
     * and draws, before other threads write ({@link #settle()}, or
     * {@link #fillOwedByRows}). A plain field: read by every write, a
     * volatile one made A2's page 3 up to 1.4x slower, drawn through a chain
     * that inlines this class's fillSpan in its z-test loop (session 11).
     */
    private boolean owed;

    public ImageDrawable(BufferedImage image) {
        this.image = image;
        this.pixels = raster(image);
        this.width = image.getWidth();
        this.height = image.getHeight();
    }

    /** The image's pixels, one int each, row after row. */
    private static int[] raster(BufferedImage image) {
        int type = image.getType();
        if (type != BufferedImage.TYPE_INT_RGB && type != BufferedImage.TYPE_INT_ARGB) {
            throw new IllegalArgumentException("needs an INT_RGB or INT_ARGB image, got type " + type);
        }
        return ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
    }

    /** The image, any owed rows made first. */
    public BufferedImage image() {
        settle();
        return image;
    }

    /**
     * Writes to {@code next} from now on, and returns the image written to
     * until now, any owed rows made first: a finished picture handed off
     * whole instead of copied ({@link PageCanvas#handOff}). {@code next} has
     * this image's size and type; its pixels stay as they are until written.
     */
    public BufferedImage exchange(BufferedImage next) {
        if (next.getWidth() != width || next.getHeight() != height || next.getType() != image.getType()) {
            throw new IllegalArgumentException("an image of " + next.getWidth() + "x" + next.getHeight() + ", type "
                    + next.getType() + ", in place of one of " + width + "x" + height + ", type " + image.getType());
        }
        BufferedImage written = image();
        pixels = raster(next);
        image = next;
        return written;
    }

    /**
     * Rows from &lt;= y &lt; to are to be {@code row}'s pixels ({@link #width}
     * of them; kept, not copied, so not to be changed): made when the image
     * is next read or written on one thread, or by {@link #settle}, or by
     * rows ({@link #fillOwedByRows}). Rows owed before and not covered now
     * are made first.
     */
    public void oweRows(int from, int to, int[] row) {
        if (row.length != width) {
            throw new IllegalArgumentException("a row of " + row.length + " pixels for an image " + width + " wide");
        }
        int first = Math.max(from, 0);
        int end = Math.max(Math.min(to, height), first);
        if (owed && (first > owedFrom || end < owedTo)) {
            settle();
        }
        owedRow = row;
        owedFrom = first;
        owedTo = end;
        owed = first < end;
    }

    /**
     * Hands the owed rows, if any are, to whoever draws each row, who makes
     * its own ({@link #fillOwedRows}) before it reads or writes there: true
     * when rows were owed. From now on reads and writes do not make them.
     * Called on the thread that owes them, before any row is drawn.
     */
    public boolean fillOwedByRows() {
        boolean were = owed;
        owed = false;
        return were;
    }

    /**
     * The owed rows among from &lt;= y &lt; to made, once {@link #fillOwedByRows}
     * handed them over; each by the one thread that draws it.
     */
    public void fillOwedRows(int from, int to) {
        int end = Math.min(to, owedTo);
        for (int y = Math.max(from, owedFrom); y < end; y++) {
            System.arraycopy(owedRow, 0, pixels, y * width, width);
        }
    }

    /**
     * Makes the owed rows now, if they are owed to the next read or write:
     * what the thread that clears calls before several threads write at
     * once (which they may do only then), or before it draws (a page of its
     * own drawing), as every read and write does first ({@link #made}).
     */
    @Override
    public void settle() {
        if (owed) {
            fillOwed();
        }
    }

    /**
     * The owed rows made, if they are owed: what each read and write does
     * first. Its own method, apart from {@link #settle}: its branch is never
     * taken when the rows are settled before drawing or handed to bands, as
     * they are on every page of the course, so the JIT compiles the fill out
     * of the writes' loops. Sharing settle's branch, taken once a picture,
     * made A2's page 3 1.06-1.11x slower (session 11).
     */
    private void made() {
        if (owed) {
            fillOwed();
        }
    }

    private void fillOwed() {
        fillOwedRows(owedFrom, owedTo);
        owedTo = owedFrom;
        owed = false;
    }

    @Override
    public int width() {
        return width;
    }

    @Override
    public int height() {
        return height;
    }

    @Override
    public void setPixel(int x, int y, double z, int argb) {
        made();
        if (x >= 0 && x < width && y >= 0 && y < height) {
            pixels[y * width + x] = argb;
        }
    }

    /** The part of the run inside the image, copied into the raster in one go. */
    @Override
    public void setRun(int x, int y, int count, double[] depths, int[] colours, int at) {
        made();
        if (y < 0 || y >= height) {
            return;
        }
        int from = Math.max(x, 0);
        int to = Math.min(x + count, width);
        if (from < to) {
            System.arraycopy(colours, at + (from - x), pixels, y * width + from, to - from);
        }
    }

    @Override
    public int getPixel(int x, int y) {
        made();
        if (x >= 0 && x < width && y >= 0 && y < height) {
            return pixels[y * width + x] | 0xFF000000;
        }
        return 0;
    }

    /**
     * Each pixel gets {@code Colors.packLevels(c + k * dc, ...)} with
     * {@code k = x - xBase}, as {@link Span#argbAt} computes it. Every step of
     * that evaluation (k * dc, + c, + 0.5, the cast to int) is monotone in k,
     * so a channel whose two end pixels need no clamp needs none in between:
     * then the loop packs without clamping, and a span of one colour is a fill.
     * Spans of a few pixels are packed directly: checking their ends would
     * cost more than the clamps it saves.
     */
    @Override
    public void fillSpan(Span s) {
        made();
        if (s.y < 0 || s.y >= height) {
            return;
        }
        int from = Math.max(s.x0, 0);
        int to = Math.min(s.x1, width);
        if (from >= to) {
            return;
        }
        int row = s.y * width;
        int k0 = from - s.xBase;
        int k1 = to - 1 - s.xBase;
        if (s.dr == 0 && s.dg == 0 && s.db == 0) {
            Arrays.fill(pixels, row + from, row + to, s.argbAt(from));
        } else {
            int range = to - from < SHORT_SPAN ? 0
                    : byteRange(s.r, s.dr, k0, k1) & byteRange(s.g, s.dg, k0, k1) & byteRange(s.b, s.db, k0, k1);
            if (range == 0) {
                packClamped(s, row, from, to);
            } else if (!packOneShade(s, row, from, to, range == FLOORS)) {
                packUnclamped(s, row, from, to, range == FLOORS);
            }
        }
    }

    /** {@link #byteRange}: no clamp needed, and truncating is flooring (c + k dc + 0.5 at least 0). */
    private static final int FLOORS = 3;
    /** {@link #byteRange}: no clamp needed. */
    private static final int TRUNCATES = 1;

    /**
     * How c + k * dc rounds at both k = k0 and k = k1: {@link #FLOORS} when
     * c + k dc + 0.5 is in [0, 256) at both, {@link #TRUNCATES} when its
     * truncation is in [0, 255] at both (it may be in (-1, 0)), 0 when a
     * clamp is needed. Each step is monotone in k, so what holds at both
     * ends holds between them; the three channels' answers are and-ed.
     */
    private static int byteRange(double c, double dc, int k0, int k1) {
        double first = c + k0 * dc + 0.5;
        double last = c + k1 * dc + 0.5;
        if (first >= 0 && first < 256 && last >= 0 && last < 256) {
            return FLOORS;
        }
        int a = (int) first;
        int b = (int) last;
        return a >= 0 && a <= 255 && b >= 0 && b <= 255 ? TRUNCATES : 0;
    }

    /**
     * Colors.packLevels without the clamp: every channel is known to stay in
     * [0, 255]. With {@code floors} each channel's c + k dc + 0.5 is also at
     * least 0 at both ends (so everywhere, as it is monotone in k): truncating
     * it is flooring it, and the three floors make one whole number below
     * 2^24, exactly: floor(r) 65536 + floor(g) 256 + floor(b), in a loop that
     * C2 packs (it packs floors, not conversions to int, and k comes from
     * RAMP: nor int to double), then converted once per pixel
     * ({@link #putLevels}). Measured 2.6-3.4x faster than three conversions a
     * pixel (session 10).
     */
    private void packUnclamped(Span s, int row, int from, int to, boolean floors) {
        double r = s.r;
        double dr = s.dr;
        double g = s.g;
        double dg = s.dg;
        double b = s.b;
        double db = s.db;
        if (!floors) {
            packTruncated(row, from, to, from - s.xBase, r, dr, g, dg, b, db);
            return;
        }
        double[] levels = levels(s, to - from);
        for (int at = from; at < to; at += RAMP.length) {
            int n = Math.min(RAMP.length, to - at);
            double kAt = at - s.xBase;
            for (int j = 0; j < n; j++) {
                double k = kAt + RAMP[j];
                levels[j] = Math.floor(r + k * dr + 0.5) * 65536 + Math.floor(g + k * dg + 0.5) * 256
                        + Math.floor(b + k * db + 0.5);
            }
            putLevels(row + at, n, 0xFF000000, levels);
        }
    }

    /**
     * packUnclamped's pixels from k = k0 on, a channel at a time truncated, as
     * Colors.packLevels without the clamp.
     */
    private void packTruncated(int row, int from, int to, int k0, double r, double dr, double g, double dg,
            double b, double db) {
        int[] p = pixels;
        int k = k0;
        for (int i = row + from; i < row + to; i++, k++) {
            p[i] = 0xFF000000 | (int) (r + k * dr + 0.5) << 16 | (int) (g + k * dg + 0.5) << 8
                    | (int) (b + k * db + 0.5);
        }
    }

    /**
     * Packs a span whose varying channels all share one value and slope, as
     * depth cueing towards white or a primary colour makes them: one
     * conversion per pixel, the level copied into each varying channel. A
     * channel of slope 0 keeps one level (c + k * 0 is c). Returns false,
     * packing nothing, for any other span. Channels are known to need no
     * clamp; with {@code floors} the level is at least 0 at both ends, and is
     * floored as in {@link #packUnclamped}.
     */
    private boolean packOneShade(Span s, int row, int from, int to, boolean floors) {
        double c = s.dr != 0 ? s.r : s.dg != 0 ? s.g : s.b;
        double dc = s.dr != 0 ? s.dr : s.dg != 0 ? s.dg : s.db;
        int fixed = 0xFF000000;
        int copies = 0; // the level times copies sets the level in every varying channel
        if (s.dr == 0) {
            fixed |= Colors.level(s.r) << 16;
        } else if (s.r == c && s.dr == dc) {
            copies |= 1 << 16;
        } else {
            return false;
        }
        if (s.dg == 0) {
            fixed |= Colors.level(s.g) << 8;
        } else if (s.g == c && s.dg == dc) {
            copies |= 1 << 8;
        } else {
            return false;
        }
        if (s.db == 0) {
            fixed |= Colors.level(s.b);
        } else if (s.b == c && s.db == dc) {
            copies |= 1;
        } else {
            return false;
        }
        if (!floors) {
            int[] p = pixels;
            int k = from - s.xBase;
            for (int i = row + from; i < row + to; i++, k++) {
                p[i] = fixed | (int) (c + k * dc + 0.5) * copies;
            }
            return true;
        }
        // As packUnclamped: the level floored (it is at least 0) times copies, a whole number below 2^24.
        double[] levels = levels(s, to - from);
        double times = copies;
        for (int at = from; at < to; at += RAMP.length) {
            int n = Math.min(RAMP.length, to - at);
            double kAt = at - s.xBase;
            for (int j = 0; j < n; j++) {
                levels[j] = Math.floor(c + (kAt + RAMP[j]) * dc + 0.5) * times;
            }
            putLevels(row + at, n, fixed, levels);
        }
        return true;
    }

    /** Pixels i, i + 1, ... i + n - 1 set to {@code fixed} or-ed with levels[0, n), whole numbers below 2^24. */
    private void putLevels(int i, int n, int fixed, double[] levels) {
        int[] p = pixels;
        for (int j = 0; j < n; j++) {
            p[i + j] = fixed | Colors.whole(levels[j]);
        }
    }

    /** The span's room for the levels of up to RAMP.length of its {@code count} pixels. */
    private static double[] levels(Span s, int count) {
        int n = Math.min(count, RAMP.length);
        if (s.levels.length < n) {
            s.levels = new double[Math.min(Math.max(n, 2 * s.levels.length), RAMP.length)];
        }
        return s.levels;
    }

    private void packClamped(Span s, int row, int from, int to) {
        for (int x = from; x < to; x++) {
            pixels[row + x] = s.argbAt(x);
        }
    }

    /**
     * Fills the rectangle [x0, x1) x [y0, y1) with one colour: its first row
     * by {@link Arrays#fill}, each row after it a copy of that one. The copy
     * is the JVM's stub at every tier, where the fill is a plain loop until
     * C2 compiles it: under C1 a one-thread page's clear (2.25 MB) took
     * about 1 ms by rows of fills, about 0.1 ms by copies; under C2 the two
     * are alike (docs/performance-log.md, "Session 45").
     */
    public void fillRect(int x0, int y0, int x1, int y1, int argb) {
        if (owed && y0 < owedTo && y1 > owedFrom) {
            fillOwed(); // the rows owed that this does not cover
        }
        int left = Math.max(x0, 0);
        int count = Math.min(x1, width) - left;
        int top = Math.max(y0, 0);
        int end = Math.min(y1, height);
        if (count <= 0 || top >= end) {
            return;
        }
        int first = top * width + left;
        Arrays.fill(pixels, first, first + count, argb);
        for (int y = top + 1; y < end; y++) {
            System.arraycopy(pixels, first, pixels, y * width + left, count);
        }
    }
}

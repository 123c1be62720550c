package simpview.surface;

import java.util.Arrays;

/**
 * The panel's pixels that wait to be shaded at a lit picture's end: for each
 * one, the number of the last span that won it and waits (its fragment
 * stage's own numbering; a nearer write of a known colour may have taken the
 * pixel since, which the stage tells by its depth), {@link #NONE} for the
 * others; and per row the columns that may
 * hold a waiting pixel, so that a row with none costs nothing to write or to
 * clear. Kept by the canvas from picture to picture; each row is written only
 * by the thread drawing it.
 */
public final class WaitingPixels {

    /** The pixel waits for nothing. */
    public static final int NONE = -1;

    private final int width;
    private final int height;
    /** Per pixel, row by row from the bottom: the span it waits for, or NONE. */
    final int[] span;
    /** Per row: waiting pixels lie in from[y] &lt;= x &lt; to[y] (empty when from &gt;= to). */
    final int[] from;
    final int[] to;
    /** Per row: a write of a known colour was made there since the row last had no wait. */
    private final boolean[] writtenOver;

    public WaitingPixels(int width, int height) {
        this.width = width;
        this.height = height;
        this.span = new int[width * height];
        this.from = new int[height];
        this.to = new int[height];
        this.writtenOver = new boolean[height];
        Arrays.fill(span, NONE);
        Arrays.fill(from, width);
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** Pixel (x, y) waits for span {@code s} (a number of 0 or more). */
    public void wait(int x, int y, int s) {
        span[y * width + x] = s;
        if (x < from[y]) {
            from[y] = x;
        }
        if (x >= to[y]) {
            to[y] = x + 1;
        }
    }

    /** Pixels x0 &lt;= x &lt; x1 of row y wait for span {@code s}. */
    public void waitRun(int y, int x0, int x1, int s) {
        Arrays.fill(span, y * width + x0, y * width + x1, s);
        if (x0 < from[y]) {
            from[y] = x0;
        }
        if (x1 > to[y]) {
            to[y] = x1;
        }
    }

    /** The span pixel (x, y) waits for, or {@link #NONE}. */
    public int at(int x, int y) {
        return x >= from[y] && x < to[y] ? span[y * width + x] : NONE;
    }

    /**
     * One past the last pixel of the run from (x, y) on that waits for what
     * (x, y) waits for (or for nothing), within row y's waiting pixels:
     * firstIn(y) &lt;= x &lt; endIn(y).
     */
    public int runEnd(int x, int y) {
        int end = to[y];
        if (x < from[y] || x >= end) {
            throw new IndexOutOfBoundsException("x " + x + " outside row " + y + "'s waiting pixels");
        }
        int[] s = span;
        int row = y * width;
        int waitsFor = s[row + x];
        int e = x + 1;
        while (e < end && s[row + e] == waitsFor) {
            e++;
        }
        return e;
    }

    /**
     * A pixel of row y was written with a known colour (by a stage that
     * shades at once): a pixel there that waits may have been taken from its
     * span since, which the stage shading it tells by its depth.
     */
    public void writtenOver(int y) {
        writtenOver[y] = true;
    }

    /** True when a pixel of row y may have been taken from the span it waits for ({@link #writtenOver}). */
    public boolean mayBeWrittenOver(int y) {
        return writtenOver[y];
    }

    /** The first column of row y that may hold a waiting pixel. */
    public int firstIn(int y) {
        return from[y];
    }

    /** One past the last column of row y that may hold a waiting pixel. */
    public int endIn(int y) {
        return to[y];
    }

    /** Rows y0 &lt;= y &lt; y1 wait for nothing any more, whatever an earlier picture left there. */
    public void clearRows(int y0, int y1) {
        for (int y = y0; y < y1; y++) {
            if (from[y] < to[y]) {
                Arrays.fill(span, y * width + from[y], y * width + to[y], NONE);
            }
            from[y] = width;
            to[y] = 0;
            writtenOver[y] = false;
        }
    }
}

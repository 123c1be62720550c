package simpview.surface;

/**
 * A drawable's rows split into {@code count} horizontal bands of (nearly)
 * equal height, band b holding rows {@code start(b) <= y < end(b)}, from the
 * bottom. Each band of a picture drawn by several threads is drawn by one of
 * them at a time, so a band's pixels see their writes in drawing order.
 */
public final class RowBands {

    private final int rows;
    private final int count;
    /** The band of each row. */
    private final int[] bandOf;

    public RowBands(int rows, int count) {
        if (rows < 1 || count < 1 || count > rows) {
            throw new IllegalArgumentException(count + " bands of " + rows + " rows");
        }
        this.rows = rows;
        this.count = count;
        this.bandOf = new int[rows];
        for (int b = 0; b < count; b++) {
            for (int y = start(b); y < end(b); y++) {
                bandOf[y] = b;
            }
        }
    }

    public int rows() {
        return rows;
    }

    public int count() {
        return count;
    }

    /** The first row of band b. */
    public int start(int band) {
        return (int) ((long) band * rows / count);
    }

    /** One past the last row of band b. */
    public int end(int band) {
        return start(band + 1);
    }

    /** The band holding row y, 0 &lt;= y &lt; rows. */
    public int bandOf(int y) {
        return bandOf[y];
    }
}

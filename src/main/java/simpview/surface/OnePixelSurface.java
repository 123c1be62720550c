package simpview.surface;

/**
 * A surface that keeps one pixel and nothing else: its colour (the
 * background until a write reaches it) and whether a write has reached it
 * since it was last asked to {@link #watchAgain}. Every other pixel reads as
 * the background, and a pixel off the surface as 0. For the replays that ask
 * about one pixel without drawing a page: the first assignment's inspector
 * and its status line, while the pointer sweeps a page.
 */
public final class OnePixelSurface implements Drawable {

    private final int width;
    private final int height;
    private final int x;
    private final int y;
    private final int background;
    private int colour;
    private boolean written;

    /** A width x height surface keeping pixel (x, y), every pixel {@code background} (ARGB) at first. */
    public OnePixelSurface(int width, int height, int x, int y, int background) {
        this.width = width;
        this.height = height;
        this.x = x;
        this.y = y;
        this.background = background | 0xFF000000;
        this.colour = this.background;
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
    public void setPixel(int px, int py, double z, int argb) {
        if (px == x && py == y) {
            colour = argb | 0xFF000000;
            written = true;
        }
    }

    @Override
    public int getPixel(int px, int py) {
        if (px < 0 || py < 0 || px >= width || py >= height) {
            return 0;
        }
        return px == x && py == y ? colour : background;
    }

    /** The kept pixel's colour (ARGB). */
    public int colour() {
        return colour;
    }

    /** Whether a write has reached the kept pixel since the surface was made or last told to {@link #watchAgain}. */
    public boolean written() {
        return written;
    }

    /** From now on {@link #written} tells of later writes only. */
    public void watchAgain() {
        written = false;
    }
}

package simpview.testing;

import java.util.ArrayList;
import java.util.List;
import simpview.surface.Drawable;

/**
 * A test surface that keeps every write in the order it came, for tests
 * about order and about each write's depth. Spans go pixel by pixel, through
 * the interface's default. Writes outside the surface are counted as strays
 * instead of being kept.
 */
public final class RecordingDrawable implements Drawable {

    /** One write that landed on the surface. */
    public record Write(int x, int y, double z, int argb) {
    }

    private final int width;
    private final int height;
    private final List<Write> writes = new ArrayList<>();
    private long strays;

    public RecordingDrawable(int width, int height) {
        this.width = width;
        this.height = height;
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
        if (x < 0 || x >= width || y < 0 || y >= height) {
            strays++;
        } else {
            writes.add(new Write(x, y, z, argb));
        }
    }

    /** Nothing is ever shown: 0 everywhere. */
    @Override
    public int getPixel(int x, int y) {
        return 0;
    }

    public List<Write> writes() {
        return writes;
    }

    public long strays() {
        return strays;
    }
}

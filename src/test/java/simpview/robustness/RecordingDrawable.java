package simpview.robustness;

import java.util.ArrayList;
import java.util.List;
import simpview.raster.Drawable;

/**
 * A test surface that keeps every write in order (pixel path only: spans go
 * through the interface's default), and counts writes outside its bounds.
 */
final class RecordingDrawable implements Drawable {

    private final int width;
    private final int height;
    final List<int[]> writes = new ArrayList<>();
    long strays;

    RecordingDrawable(int width, int height) {
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
            writes.add(new int[] {x, y});
        }
    }

    @Override
    public int getPixel(int x, int y) {
        return 0;
    }
}

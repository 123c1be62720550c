package simpview.window;

import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import simpview.geometry.Vertex;
import simpview.raster.FilledPolygonRenderer;
import simpview.surface.Drawable;
import simpview.surface.ImageDrawable;
import simpview.surface.PanelDrawable;
import simpview.surface.ZBuffer;
import simpview.surface.ZBufferDrawable;

/**
 * The window's icon, drawn by simpview's own rasterizer: three blerped
 * triangles crossing in depth, as page 3 crosses its greys, on black.
 */
public final class AppIcon {

    private AppIcon() {
    }

    /** The icon at the usual sizes. */
    static List<BufferedImage> images() {
        List<BufferedImage> images = new ArrayList<>();
        for (int size : new int[] {16, 32, 48, 64, 128}) {
            images.add(draw(size));
        }
        return images;
    }

    static BufferedImage draw(int size) {
        BufferedImage image = new BufferedImage(size, size, BufferedImage.TYPE_INT_ARGB);
        ImageDrawable pixels = new ImageDrawable(image);
        for (int y = 0; y < size; y++) {
            for (int x = 0; x < size; x++) {
                pixels.setPixel(x, y, 0, 0xFF000000);
            }
        }
        Drawable panel = new PanelDrawable(pixels, 0, 0, size);
        Drawable target = new ZBufferDrawable(new ZBuffer(size, size), panel);
        FilledPolygonRenderer renderer = new FilledPolygonRenderer();
        double s = size;
        renderer.drawPolygon(new Vertex(.08 * s, .10 * s, -150, 1, .2, .2), new Vertex(.92 * s, .30 * s, -20, 1, .8, .2),
                new Vertex(.30 * s, .92 * s, -90, .9, .1, .5), target);
        renderer.drawPolygon(new Vertex(.15 * s, .70 * s, -10, .2, .9, .3), new Vertex(.55 * s, .05 * s, -180, .1, .5, .2),
                new Vertex(.95 * s, .85 * s, -60, .6, 1, .4), target);
        renderer.drawPolygon(new Vertex(.05 * s, .40 * s, -100, .2, .4, 1), new Vertex(.85 * s, .08 * s, -100, .3, .8, 1),
                new Vertex(.70 * s, .97 * s, -100, .1, .2, .7), target);
        return image;
    }
}

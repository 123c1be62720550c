package simpview.stage;

import simpview.raster.LitLineRasterizer;
import simpview.raster.LitPolygonRasterizer;

/**
 * The rasterizers a lit scene is drawn with, made only by {@link #make}, so
 * a scene drawn on one thread ({@link LitGeometry}) and one drawn band by band
 * ({@link LitPrimitives}) are drawn by the same ones. Scratch state only:
 * one pair belongs to one thread at a time.
 */
record LitRasterizers(LitPolygonRasterizer fill, LitLineRasterizer lines) {

    /** A fresh pair. */
    static LitRasterizers make() {
        return new LitRasterizers(new LitPolygonRasterizer(), new LitLineRasterizer());
    }
}

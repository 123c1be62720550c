package simpview.stage;

import simpview.raster.DdaLineRenderer;
import simpview.raster.FilledPolygonRenderer;
import simpview.raster.WireframePolygonRenderer;
import simpview.surface.Drawable;

/**
 * The renderers a depth-cued scene is drawn with: DDA lines, fills by the
 * top-left rule, wireframes of DDA lines. Made only by {@link #make}, so a
 * scene drawn on one thread and one drawn band by band on several are drawn
 * by the same renderers. Each holds scratch state only, so one set belongs to
 * one thread at a time.
 */
public record CuedRenderers(DdaLineRenderer lines, FilledPolygonRenderer filled, WireframePolygonRenderer wire) {

    /** A fresh set. */
    public static CuedRenderers make() {
        return new CuedRenderers(new DdaLineRenderer(), new FilledPolygonRenderer(),
                new WireframePolygonRenderer(new DdaLineRenderer()));
    }

    /** A painter that draws with these onto {@code panel}. */
    public Painter painter(Drawable panel) {
        return new Painter(panel, lines, filled, wire);
    }
}

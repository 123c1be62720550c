package simpview.inspect;

import simpview.geometry.Camera;
import simpview.surface.DepthCueDrawable;
import simpview.surface.Drawable;
import simpview.surface.Rgb;

/**
 * The colour of a depth-cued write: the depth cue's
 * {@code far + (near - far) t} with {@code t = (z - yon) / (hither - yon)},
 * or the vertex colour when the scene is drawn in its own colours. The bytes
 * reported are the ones the chain wrote; the colour of a write that never got
 * that far is the one the chain's own depth cue gives its depth.
 */
final class CueExplainer implements PixelWatch.Explainer {

    private final Rgb near;
    private final Rgb far;
    private final Camera view = Camera.PARALLEL;
    /** The scene's own depth cue, writing into one pixel: what a write that was dropped would have been. */
    private final Drawable cue;
    private final OnePixel captured = new OnePixel();

    /** @param near the near colour, or null for a scene drawn in its own colours */
    CueExplainer(Rgb near, Rgb far) {
        this.near = near;
        this.far = far;
        this.cue = near == null ? null : new DepthCueDrawable(near, far, view, captured);
    }

    @Override
    public int colour(PixelWatch watch, double z, double[] levels, int drawnArgb, boolean drawn, Terms terms) {
        if (terms == null) {
            if (drawn || cue == null) {
                return drawnArgb;
            }
            cue.setPixel(0, 0, z, 0);
            return captured.argb;
        }
        terms.put("z", z);
        if (near == null) {
            terms.put("colour", "the vertices' own colours, interpolated (no depth cue)");
        } else {
            double t = (z - view.yon()) / (view.hither() - view.yon());
            terms.put("near", near.r(), near.g(), near.b());
            terms.put("far", far.r(), far.g(), far.b());
            terms.put("t", t);
            terms.put("cued", far.r() + (near.r() - far.r()) * t, far.g() + (near.g() - far.g()) * t,
                    far.b() + (near.b() - far.b()) * t);
        }
        if (levels != null) {
            terms.put("levels", levels);
            if (near != null) {
                noteATieTheLastBitsDecided(z, levels, drawnArgb, terms);
            }
        }
        terms.put("final_rgb", drawnArgb >>> 16 & 0xFF, drawnArgb >>> 8 & 0xFF, drawnArgb & 0xFF);
        return drawnArgb;
    }

    /**
     * A filled span carries its levels from its first pixel by a slope, so
     * at a pixel whose {@code cued * 255} lies exactly on a half (z = -100
     * from white to black: 127.5) the level may come out a last bit below
     * (127.49999999999999) and round down. The lines above then seem to
     * contradict the byte written; say why, once, for the first such channel.
     */
    private void noteATieTheLastBitsDecided(double z, double[] levels, int drawnArgb, Terms terms) {
        double t = (z - view.yon()) / (view.hither() - view.yon());
        double[] nears = {near.r(), near.g(), near.b()};
        double[] fars = {far.r(), far.g(), far.b()};
        for (int c = 0; c < 3; c++) {
            double exact = 255 * (fars[c] + (nears[c] - fars[c]) * t);
            int rounded = (int) Math.max(0, Math.min(255, Math.floor(exact + 0.5)));
            int written = drawnArgb >>> (16 - 8 * c) & 0xFF;
            if (rounded != written && Math.abs(levels[c] - exact) < 1e-9) {
                terms.put("note", "cued * 255 = " + exact + " would round to " + rounded + ", but the level"
                        + " written is " + levels[c] + ": the depth cue's straight line carried along the span"
                        + " from its first pixel, the same value but for the last bits of a double, and here"
                        + " they fall either side of a rounding tie (a renderer of doubles may draw "
                        + rounded + " or " + written + ")");
                return;
            }
        }
    }

    /** A surface of one pixel that keeps the last colour written to it. */
    static final class OnePixel implements Drawable {
        int argb;

        @Override
        public int width() {
            return 1;
        }

        @Override
        public int height() {
            return 1;
        }

        @Override
        public void setPixel(int x, int y, double z, int colour) {
            argb = colour;
        }

        @Override
        public int getPixel(int x, int y) {
            return argb;
        }
    }
}

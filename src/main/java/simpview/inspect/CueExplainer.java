package simpview.inspect;

import simpview.geometry.Camera;
import simpview.geometry.Vertex;
import simpview.raster.WalkingLineRenderer;
import simpview.stage.Painter;
import simpview.surface.Colors;
import simpview.surface.DepthCueDrawable;
import simpview.surface.Drawable;
import simpview.surface.Rgb;

/**
 * The colour of a depth-cued write: the depth cue's
 * {@code far + (near - far) t} with {@code t = (z - yon) / (hither - yon)},
 * or the vertices' colours when the scene is drawn in its own colours (a
 * line's worked out along it, to the pixel's bytes). The bytes
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
            if (watch.kind() == Painter.LINE || watch.kind() == Painter.WIRE) {
                alongTheLine(watch, z, drawnArgb, terms);
            }
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
     * A line's (or a wire polygon's edge's) pixel in the vertices' own
     * colours: the edge the DDA walked (of a wire outline, the one whose
     * depth here is the write's), its ends in the order the walk takes them
     * (from the smaller x of an x-major line, else the smaller y), the step
     * that reached the pixel and t, the share of the way, as the walk works
     * it out; then each channel lerped as the drawing lerps it
     * ({@link WalkingLineRenderer#lerp}, a value both ends share kept as it
     * is), times 255 and rounded half up ({@link Colors#pack}). The same
     * arithmetic on the same numbers, so the bytes are the pixel's; a note
     * says so where they are not. Nothing when no edge steps on the pixel.
     */
    private static void alongTheLine(PixelWatch watch, double z, int drawnArgb, Terms terms) {
        double[] o = watch.outline();
        int s = watch.stride();
        int n = watch.vertices();
        boolean wire = watch.kind() == Painter.WIRE;
        int edges = wire ? n : 1;
        Terms best = null;
        double[] colour = null;
        double nearest = Double.POSITIVE_INFINITY;
        for (int k = 0; k < edges && n >= 2; k++) {
            int a = k * s;
            int b = (k + 1) % n * s;
            if (!Coverage.onLine(o[a + Vertex.X], o[a + Vertex.Y], o[b + Vertex.X], o[b + Vertex.Y],
                    watch.x(), watch.y())) {
                continue;
            }
            DdaSteps dda = DdaSteps.of(o[a + Vertex.X], o[a + Vertex.Y], o[b + Vertex.X], o[b + Vertex.Y]);
            int start = dda.reversed() ? b : a;
            int end = dda.reversed() ? a : b;
            long step = dda.stepAt(watch.x(), watch.y());
            double t = dda.t(step);
            double u = 1 - t;
            double gap = Math.abs(WalkingLineRenderer.lerp(o[start + Vertex.Z], o[end + Vertex.Z], u, t) - z);
            if (!(gap < nearest)) {
                continue;
            }
            nearest = gap;
            colour = new double[3];
            for (int c = 0; c < 3; c++) {
                colour[c] = WalkingLineRenderer.lerp(o[start + Vertex.R + c], o[end + Vertex.R + c], u, t);
            }
            best = new Terms();
            if (wire) {
                best.put("edge", a / s + "-" + b / s);
            }
            boolean oneColour = o[start + Vertex.R] == o[end + Vertex.R] && o[start + Vertex.G] == o[end + Vertex.G]
                    && o[start + Vertex.B] == o[end + Vertex.B];
            best.put("start", lineEnd(o, start, s)).put("end", lineEnd(o, end, s))
                    .put("step", (double) step).put("steps", (double) dda.steps())
                    .put("t", t)
                    .put("rule", "each channel is (1 - t) start + t end, as the line's drawing lerps it from the "
                            + "start of its walk (a channel both ends share is theirs as it is); then times 255, "
                            + "rounded half up to a byte" + (oneColour ? "; both ends have the same colour, so it "
                            + "is every pixel's, to the bit" : ""));
        }
        if (best == null) {
            return;
        }
        terms.put("along", best);
        terms.put("interpolated", colour.clone());
        terms.put("levels", 255 * colour[0], 255 * colour[1], 255 * colour[2]);
        if (Colors.pack(colour[0], colour[1], colour[2]) != drawnArgb) {
            terms.put("note", "the bytes written are not these: the line was drawn otherwise than the DDA of SPEC "
                    + "Part 1 explains it here");
        }
    }

    /** One end of a line as the walk takes it: its vertex number, panel point, z and own colour. */
    private static Terms lineEnd(double[] o, int at, int stride) {
        return new Terms().put("vertex", at / stride).put("panel", o[at + Vertex.X], o[at + Vertex.Y])
                .put("z", o[at + Vertex.Z]).put("colour", o[at + Vertex.R], o[at + Vertex.G], o[at + Vertex.B]);
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

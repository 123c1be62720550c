package simpview.inspect;

import simpview.raster.FragmentLayout;
import simpview.raster.FragmentSink;
import simpview.shading.FragmentStage;

/**
 * Between a lit scene's rasterizers and its fragment stage: every fragment
 * at the inspected pixel is resolved here as the fragment stage resolves it
 * (k = x - from, 1 / q = 1 / (q0 + k dq), each channel (v0 + k dv) / q, the
 * same operations in the same order, so the same bits; the colour of a
 * primitive of one colour, or the kd of a phong polygon of one kd, as it is,
 * {@link FragmentStage#oneColours}), told to the watch
 * with the depth stored before it, and then the span goes on whole to the
 * fragment stage, which draws it; whether it won is read back from the
 * z-buffer. Spans and pixels that miss the inspected pixel go no further:
 * what happens at a pixel depends on the writes at that pixel alone, so
 * the replay leaves the rest of the picture undrawn.
 */
final class FragmentProbe implements FragmentSink {

    private final PixelWatch watch;
    private final FragmentStage stage;
    private final int x;
    private final int y;
    private final int width;
    private final double[] channels = new double[16];

    FragmentProbe(PixelWatch watch, FragmentStage stage, int width) {
        this.watch = watch;
        this.stage = stage;
        this.x = watch.x();
        this.y = watch.y();
        this.width = width;
    }

    @Override
    public void span(int row, int from, int to, double q0, double dq, double[] v0, double[] dv) {
        if (row != y || x < Math.max(from, 0) || x >= Math.min(to, width)) {
            return;
        }
        int k = x - from;
        double inv = 1 / (q0 + k * dq);
        int n = watch.channels();
        for (int c = 0; c < n; c++) {
            channels[c] = (v0[c] + k * dv[c]) * inv;
        }
        if (stage.oneColours()) {
            for (int c = FragmentLayout.R; c <= FragmentLayout.B; c++) {
                channels[c] = v0[c];
            }
        }
        watch.fragment(channels);
        stage.span(row, from, to, q0, dq, v0, dv);
        watch.fragmentDone();
    }

    @Override
    public void pixel(int px, int py, double q, double[] v) {
        if (px != x || py != y) {
            return;
        }
        double inv = 1 / q;
        int n = watch.channels();
        for (int c = 0; c < n; c++) {
            channels[c] = c >= FragmentLayout.R && c <= FragmentLayout.B && stage.oneColours() ? v[c] : v[c] * inv;
        }
        watch.fragment(channels);
        stage.pixel(px, py, q, v);
        watch.fragmentDone();
    }

    /** Passed on: the stage may write a primitive's short spans only when told it is done. */
    @Override
    public void primitiveDone() {
        stage.primitiveDone();
    }
}

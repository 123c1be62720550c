package simpview.inspect;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.function.Supplier;
import simpview.geometry.Camera;
import simpview.raster.FragmentLayout;
import simpview.raster.FragmentSink;
import simpview.scene.SceneException;
import simpview.scene.simp.DrawingWatch;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.scene.simp.SourcePlace;
import simpview.shading.FragmentStage;
import simpview.shading.LitState;
import simpview.stage.PrimitiveTrace;
import simpview.surface.DiscardingDrawable;
import simpview.surface.Drawable;
import simpview.surface.DrawableDecorator;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;
import simpview.surface.ScissorDrawable;
import simpview.surface.Span;
import simpview.surface.ZBuffer;
import simpview.surface.ZBufferDrawable;

/**
 * The overdraw of a whole picture: how many writes reached each panel
 * pixel's depth test (those written plus those that lost it), counted in a
 * replay through the program's pipeline: depth-cued writes after the
 * scissor, lit fragments as the rasterizers hand them to the fragment stage
 * (inside the panel). Row by row from the bottom, as the z-buffer is kept.
 * The pixel history of any pixel has as many written and depth-failed
 * entries as its count here.
 *
 * <p>Only the depth test decides a count, so the replay stops there and
 * makes no colour: depth-cued writes go through the scissor and the
 * z-buffer (the program's own decorators) to a surface that keeps nothing
 * and wants no colour; lit fragments are depth-tested here as the fragment
 * stage tests them (z = (z q) (1 / q) at each pixel, the same operations in
 * the same order, so the same bits; strictly nearer wins and is kept), and
 * never lit. {@code OverdrawTest} holds the counts to the histories, whose
 * fragments the fragment stage itself tests.
 */
public final class Overdraw {

    private Overdraw() {
    }

    /** The counts of the scene, drawn as {@code scene} says, its files from {@code library}. */
    public static int[] of(InspectedScene scene, SceneLibrary library) throws SceneException {
        return counts(scene, library).reached();
    }

    /**
     * Per panel pixel: the writes that reached its depth test, and those of
     * them that lost it (the depth-test failure overlay).
     */
    public record Counts(int[] reached, int[] failed) {
    }

    /**
     * Both counts of the scene, drawn as {@code scene} says; a scene that
     * stops at an error is counted as far as the error, as its page is drawn.
     *
     * @throws SceneException when nothing of the scene could be read
     */
    public static Counts counts(InspectedScene scene, SceneLibrary library) throws SceneException {
        PageCanvas canvas = new PageCanvas();
        int[] counts = new int[PageCanvas.PANEL * PageCanvas.PANEL];
        int[] won = new int[counts.length];
        Counting counting = new Counting(counts, won, canvas.zbuffer());
        ScenePipeline.Options options = ScenePipeline.Options.byCommands(library).withRules(scene.rules())
                .withCue(scene.near(), scene.far()).withOwnColours(scene.ownColours());
        try {
            ScenePipeline.draw(scene.file(), canvas, options, counting);
        } catch (SceneException e) {
            if (scene.nothingRead(e)) {
                throw e;
            }
        }
        int[] failed = new int[counts.length];
        for (int i = 0; i < counts.length; i++) {
            failed[i] = counts[i] - won[i];
        }
        return new Counts(counts, failed);
    }

    /** The largest count. */
    public static int max(int[] counts) {
        int m = 0;
        for (int c : counts) {
            m = Math.max(m, c);
        }
        return m;
    }

    private static final class Counting implements SceneMonitor, DrawingWatch {
        private final int[] counts;
        private final int[] won;
        /** The canvas's z-buffer, whose depths a lit span tests and writes here to see which of its pixels won. */
        private final ZBuffer zbuffer;

        Counting(int[] counts, int[] won, ZBuffer zbuffer) {
            this.counts = counts;
            this.won = won;
            this.zbuffer = zbuffer;
        }

        /** A scene that turns lit after drawing is drawn again from the start: the counts start again too. */
        @Override
        public PrimitiveTrace trace() {
            return new PrimitiveTrace() {
                @Override
                public void read(int index, Path file, int line, int kind, double[] p, int at,
                        int stride, int vertices) {
                }

                @Override
                public boolean drawing(int index) {
                    return true;
                }

                @Override
                public void restart() {
                    Arrays.fill(counts, 0);
                    Arrays.fill(won, 0);
                }
            };
        }

        @Override
        public DrawingWatch watch() {
            return this;
        }

        @Override
        public Drawable depthCued(PageCanvas canvas, Rgb near, Rgb far, boolean ownColours) {
            Camera view = Camera.PARALLEL;
            return new ScissorDrawable(view, new CountedWrites(counts, new ZBufferDrawable(canvas.zbuffer(),
                    new CountedWrites(won, new DiscardingDrawable()))));
        }

        @Override
        public FragmentSink fragments(FragmentStage stage) {
            int width = stage.width();
            int height = stage.height();
            double[] z = zbuffer.depths();
            return new FragmentSink() {
                // k at each pixel of a span as an exact double, and each pixel's 1 / q and z: plain loops over
                // arrays, which C2 compiles to packed operations, as the fragment stage's batches are.
                private final double[] ramp = ramp(width);
                private final double[] inverse = new double[width];
                private final double[] zs = new double[width];

                @Override
                public void span(int y, int from, int to, double q0, double dq, double[] v0, double[] dv) {
                    if (y < 0 || y >= height) {
                        return;
                    }
                    int start = Math.max(from, 0);
                    int m = Math.min(to, width) - start;
                    if (m <= 0) {
                        return;
                    }
                    double k0 = start - from;
                    double z0 = v0[FragmentLayout.Z];
                    double dz = dv[FragmentLayout.Z];
                    double[] inv = inverse;
                    double[] depth = zs;
                    double[] r = ramp;
                    for (int j = 0; j < m; j++) {
                        inv[j] = 1 / (q0 + (k0 + r[j]) * dq);
                    }
                    for (int j = 0; j < m; j++) {
                        depth[j] = (z0 + (k0 + r[j]) * dz) * inv[j];
                    }
                    int at = y * width + start;
                    for (int j = 0; j < m; j++) {
                        counts[at + j]++;
                    }
                    for (int j = 0; j < m; j++) {
                        if (depth[j] > z[at + j]) {
                            z[at + j] = depth[j];
                            won[at + j]++;
                        }
                    }
                    zbuffer.written(y, start, start + m);
                }

                @Override
                public void pixel(int x, int y, double q, double[] v) {
                    if (x < 0 || x >= width || y < 0 || y >= height) {
                        return;
                    }
                    int i = y * width + x;
                    double inv = 1 / q;
                    double depth = v[FragmentLayout.Z] * inv;
                    counts[i]++;
                    if (depth > z[i]) {
                        z[i] = depth;
                        won[i]++;
                        zbuffer.written(y, x, x + 1);
                    }
                }
            };
        }

        @Override
        public void began(Supplier<List<SourcePlace>> chain, LitState lit) {
        }

    }

    /** 0, 1, 2, ... as doubles. */
    private static double[] ramp(int n) {
        double[] r = new double[n];
        for (int i = 0; i < n; i++) {
            r[i] = i;
        }
        return r;
    }

    /** Counts every write that reaches it inside the panel, then passes it on. */
    private static final class CountedWrites extends DrawableDecorator {
        private final int[] counts;
        private final int size = PageCanvas.PANEL;

        CountedWrites(int[] counts, Drawable delegate) {
            super(delegate);
            this.counts = counts;
        }

        @Override
        public void setPixel(int x, int y, double z, int argb) {
            if (x >= 0 && x < size && y >= 0 && y < size) {
                counts[y * size + x]++;
            }
            delegate.setPixel(x, y, z, argb);
        }

        @Override
        public void fillSpan(Span s) {
            if (s.y >= 0 && s.y < size) {
                for (int x = Math.max(s.x0, 0); x < Math.min(s.x1, size); x++) {
                    counts[s.y * size + x]++;
                }
            }
            delegate.fillSpan(s);
        }
    }
}

package simpview.inspect;

import java.util.List;
import java.util.function.Supplier;
import simpview.geometry.Camera;
import simpview.raster.FragmentSink;
import simpview.scene.SceneException;
import simpview.scene.obj.ObjLibrary;
import simpview.scene.simp.DrawingWatch;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.scene.simp.SourcePlace;
import simpview.shading.FragmentStage;
import simpview.shading.LitState;
import simpview.surface.DepthCueDrawable;
import simpview.surface.Drawable;
import simpview.surface.DrawableDecorator;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;
import simpview.surface.ScissorDrawable;
import simpview.surface.Span;
import simpview.surface.ZBufferDrawable;

/**
 * The overdraw of a whole picture: how many writes reached each panel
 * pixel's depth test (those written plus those that lost it), counted in a
 * replay through the program's pipeline: depth-cued writes after the
 * scissor, lit fragments as the rasterizers hand them to the fragment stage
 * (inside the panel). Row by row from the bottom, as the z-buffer is kept.
 * The pixel history of any pixel has as many written and depth-failed
 * entries as its count here.
 */
public final class Overdraw {

    private Overdraw() {
    }

    /** The counts of the scene, drawn as {@code scene} says, its models from {@code models}. */
    public static int[] of(InspectedScene scene, ObjLibrary models) throws SceneException {
        PageCanvas canvas = new PageCanvas();
        int[] counts = new int[PageCanvas.PANEL * PageCanvas.PANEL];
        Counting counting = new Counting(counts);
        ScenePipeline.Options options = ScenePipeline.Options.byCommands(models).withRules(scene.rules())
                .withCue(scene.near(), scene.far()).withOwnColours(scene.ownColours());
        ScenePipeline.draw(scene.file(), canvas, options, counting);
        return counts;
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

        Counting(int[] counts) {
            this.counts = counts;
        }

        @Override
        public DrawingWatch watch() {
            return this;
        }

        @Override
        public Drawable depthCued(PageCanvas canvas, Rgb near, Rgb far, boolean ownColours) {
            Camera view = Camera.PARALLEL;
            Drawable coloured = ownColours ? canvas.panel() : new DepthCueDrawable(near, far, view, canvas.panel());
            return new ScissorDrawable(view, new CountedWrites(counts, new ZBufferDrawable(canvas.zbuffer(), coloured)));
        }

        @Override
        public FragmentSink fragments(FragmentStage stage) {
            int width = stage.width();
            int height = stage.height();
            return new FragmentSink() {
                @Override
                public void span(int y, int from, int to, double q0, double dq, double[] v0, double[] dv) {
                    if (y >= 0 && y < height) {
                        for (int x = Math.max(from, 0); x < Math.min(to, width); x++) {
                            counts[y * width + x]++;
                        }
                    }
                    stage.span(y, from, to, q0, dq, v0, dv);
                }

                @Override
                public void pixel(int x, int y, double q, double[] v) {
                    if (x >= 0 && x < width && y >= 0 && y < height) {
                        counts[y * width + x]++;
                    }
                    stage.pixel(x, y, q, v);
                }
            };
        }

        @Override
        public void began(Supplier<List<SourcePlace>> chain, LitState lit) {
        }
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

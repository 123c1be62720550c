package simpview.inspect;

import java.awt.geom.Line2D;
import java.awt.geom.Rectangle2D;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import simpview.geometry.Camera;
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
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;

/**
 * The primitives of a scene that reach no rasterizer, as outlines on the
 * panel: those culled whole (every vertex outside one plane of the view) and
 * those clipped away whole, each projected as it is by the scene's camera
 * (the depth-cued view's for a depth-cued scene): its part in front of the
 * eye, as the pixel history's coverage test takes it. A primitive wholly at
 * or behind the eye has no outline and is only counted. Found by a replay
 * through {@link ScenePipeline} that writes no pixel: only the geometry runs.
 */
public final class SkippedPrimitives {

    /** One primitive: culled or clipped away, its outline in panel x and y (y up) in turn, where it came from. */
    public record Skipped(boolean culled, int kind, double[] outline, Path file, int line) {
    }

    /** What the replay found: the outlined ones, and how many more had no outline (wholly at or behind the eye). */
    public record Found(List<Skipped> outlined, int unprojectable) {

        public long culled() {
            return outlined.stream().filter(Skipped::culled).count();
        }

        public long clipped() {
            return outlined.size() - culled();
        }

        /**
         * How many of the outlined lie wholly outside the panel: the overlay,
         * cut to the panel, shows nothing of them.
         */
        public long outsideThePanel() {
            return outlined.stream().filter(s -> missesThePanel(s.outline())).count();
        }
    }

    private SkippedPrimitives() {
    }

    /**
     * Whether an outline (panel x and y in turn: a line's two ends, or a
     * polygon's corners) lies wholly outside the panel, 0 to 650 each way:
     * none of its edges crosses the panel. U draws outlines, not fills, so a
     * polygon running all round the panel shows nothing of it either.
     */
    static boolean missesThePanel(double[] outline) {
        Rectangle2D panel = new Rectangle2D.Double(0, 0, PageCanvas.PANEL, PageCanvas.PANEL);
        if (outline.length < 4) {
            return !panel.contains(outline[0], outline[1]);
        }
        int corners = outline.length / 2;
        int edges = corners == 2 ? 1 : corners;
        for (int k = 0; k < edges; k++) {
            int next = (k + 1) % corners;
            if (new Line2D.Double(outline[2 * k], outline[2 * k + 1], outline[2 * next], outline[2 * next + 1])
                    .intersects(panel)) {
                return false;
            }
        }
        return true;
    }

    /**
     * The scene's skipped primitives, drawn as {@code scene} says, its files
     * from {@code library}; of a scene that stops at an error, those before
     * the error, as its page is drawn.
     *
     * @throws SceneException when nothing of the scene could be read
     */
    public static Found of(InspectedScene scene, SceneLibrary library) throws SceneException {
        Collecting collecting = new Collecting();
        ScenePipeline.Options options = ScenePipeline.Options.byCommands(library).withRules(scene.rules())
                .withCue(scene.near(), scene.far()).withOwnColours(scene.ownColours());
        try {
            ScenePipeline.draw(scene.file(), new PageCanvas(), options, collecting);
        } catch (SceneException e) {
            if (scene.nothingRead(e)) {
                throw e;
            }
        }
        return new Found(List.copyOf(collecting.found), collecting.unprojectable);
    }

    private static final class Collecting implements SceneMonitor, DrawingWatch {
        private final List<Skipped> found = new ArrayList<>();
        private int unprojectable;
        private Supplier<Camera> camera = () -> Camera.PARALLEL;

        @Override
        public PrimitiveTrace trace() {
            return new PrimitiveTrace() {
                @Override
                public void read(int index, Path file, int line, int kind, double[] p, int at, int stride,
                        int vertices) {
                }

                @Override
                public boolean drawing(int index) {
                    return true;
                }

                @Override
                public void skipped(Path file, int line, int kind, boolean culled, double[] p, int at, int stride,
                        int vertices) {
                    double[] outline = project(camera.get(), kind, p, at, stride, vertices);
                    if (outline == null) {
                        unprojectable++;
                    } else {
                        found.add(new Skipped(culled, kind, outline, file, line));
                    }
                }

                @Override
                public void restart() {
                    found.clear();
                    unprojectable = 0;
                }
            };
        }

        @Override
        public DrawingWatch watch() {
            return this;
        }

        /** Nothing is written: the outlines need only the geometry. */
        @Override
        public Drawable depthCued(PageCanvas canvas, Rgb near, Rgb far, boolean ownColours) {
            return new DiscardingDrawable();
        }

        @Override
        public FragmentSink fragments(FragmentStage stage) {
            return new FragmentSink() {
                @Override
                public void span(int y, int from, int to, double q0, double dq, double[] v0, double[] dv) {
                }

                @Override
                public void pixel(int x, int y, double q, double[] v) {
                }
            };
        }

        @Override
        public void began(Supplier<List<SourcePlace>> chain, LitState lit) {
            camera = lit != null ? lit::camera : () -> Camera.PARALLEL;
        }
    }

    /**
     * The outline on the panel, panel x and y in turn: the primitive's part
     * in front of the eye, projected as the pixel history's coverage test
     * projects it; null when nothing of it is in front of the eye.
     */
    static double[] project(Camera camera, int kind, double[] p, int at, int stride, int n) {
        double[][] projected = Coverage.projected(camera, kind, p, at, stride, n);
        if (projected == null) {
            return null;
        }
        double[] outline = new double[2 * projected[0].length];
        for (int k = 0; k < projected[0].length; k++) {
            outline[2 * k] = projected[0][k];
            outline[2 * k + 1] = projected[1][k];
        }
        return outline;
    }
}

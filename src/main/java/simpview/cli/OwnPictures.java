package simpview.cli;

import java.util.HashMap;
import java.util.Map;
import simpview.compare.Picture;
import simpview.pages.PageContext;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;

/**
 * simpview's own pictures to compare with, drawn the way {@code render}
 * draws them (through {@link PageDrawing}), each at most once per run.
 */
public final class OwnPictures {

    private final PageDrawing drawing;
    private final PageContext context;
    private final Rgb near;
    private final Rgb far;
    private final boolean ownColours;
    private final Map<CompareTarget, Picture> drawn = new HashMap<>();

    /**
     * Scenes are depth-cued from {@code near} to {@code far}; null means the
     * defaults, white and black; with {@code ownColours}, drawn in their
     * vertices' own colours instead. Drawn with {@code threads}, which the
     * caller owns and closes.
     */
    OwnPictures(PageContext context, Rgb near, Rgb far, boolean ownColours, SceneMonitor monitor,
            DrawingThreads threads) {
        this.drawing = new PageDrawing(monitor, threads);
        this.context = context;
        this.near = near;
        this.far = far;
        this.ownColours = ownColours;
    }

    Picture of(CompareTarget target) throws SceneException {
        Picture picture = drawn.get(target);
        if (picture == null) {
            PageCanvas canvas;
            if (target.isPage()) {
                canvas = drawing.page(target.page(), context);
            } else {
                ScenePipeline.Drawn scene = drawing.scene(target.scene(), near, far, ownColours);
                if (!scene.drawn()) {
                    throw new UsageProblem(PageDrawing.cueColoursProblem(target.scene(), scene.litBecause(),
                            ownColours));
                }
                canvas = drawing.canvas();
            }
            picture = Picture.ofPage(canvas.image(), "simpview's " + describe(target));
            drawn.put(target, picture);
        }
        return picture;
    }

    /**
     * What simpview draws for {@code target}, as a report names it: "page 6 (seed 361)", "scene cube.simp"; a
     * scene drawn in its vertices' own colours says so, since the same scene depth-cued is another picture.
     */
    String describe(CompareTarget target) {
        return target.describe(context) + (ownColours && !target.isPage() ? " in its vertices' own colours" : "");
    }

    PageContext context() {
        return context;
    }
}

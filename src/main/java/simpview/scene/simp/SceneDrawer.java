package simpview.scene.simp;

import java.nio.file.Path;
import simpview.scene.SceneException;
import simpview.surface.PageCanvas;

/**
 * What draws a scene file for the window's render thread: the real one is
 * {@link ScenePipeline#draw}; the window's tests stand in for it to test the
 * machinery around it (progress, cancelling) in any state.
 */
@FunctionalInterface
public interface SceneDrawer {

    SceneDrawer SIMP = ScenePipeline::draw;

    /** As {@link ScenePipeline#draw}: on a canvas just cleared, files reached told to the monitor. */
    ScenePipeline.Drawn draw(Path file, PageCanvas canvas, ScenePipeline.Options options, SceneMonitor monitor)
            throws SceneException;
}

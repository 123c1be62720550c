package simpview.testing;

import java.nio.file.Path;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.PageCanvas;

/** Scenes drawn as the window and {@code render --scene} draw them, for tests that ask what the pipeline decided. */
public final class DrawnScenes {

    private DrawnScenes() {
    }

    /** Draws {@code file} by the rules its commands call for onto {@code canvas} (cleared first). */
    public static ScenePipeline.Drawn draw(Path file, PageCanvas canvas) throws SceneException {
        canvas.clear();
        return ScenePipeline.draw(file, canvas, ScenePipeline.Options.byCommands(new SceneLibrary()), SceneMonitor.NONE);
    }

    /** What drawing {@code file} by its commands' rules drew. */
    public static ScenePipeline.Drawn draw(Path file) throws SceneException {
        return draw(file, new PageCanvas());
    }

    /** True when {@code file} is drawn by the lit rules (SPEC Part 2: any file it reads holds a lit command). */
    public static boolean isLit(Path file) throws SceneException {
        return draw(file).lit();
    }
}

package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.Test;
import simpview.scene.simp.SceneDrawer;
import simpview.scene.simp.ScenePipeline;
import simpview.window.render.RenderedView;
import simpview.window.render.View;

/**
 * Under Xvfb: an editor's save that lands while the window is still drawing
 * the file's previous version (an in-place save: the file is truncated, then
 * written) is drawn too, without F5. The watcher compares the files with
 * their stamps as the picture read them, not as they are once it is done.
 */
public class SaveWhileDrawingWindowTest extends WindowTestCase {

    private static final String BROKEN = "polygon (-50, -50, -50) (50, -50, -50) (0, 50\n";
    private static final String FIXED = "polygon (-50, -50, -50) (50, -50, -50) (0, 50, -50)\n";

    @Test
    void aSaveWhileTheBrokenVersionIsDrawnIsDrawnToo() throws Exception {
        Path scene = Files.writeString(dir.resolve("edited.simp"), BROKEN);
        AtomicBoolean saveOnce = new AtomicBoolean(true);
        SceneDrawer savedWhileDrawing = (file, canvas, options, monitor) -> {
            try {
                return ScenePipeline.draw(file, canvas, options, monitor);
            } finally {
                if (saveOnce.getAndSet(false)) {
                    try {
                        Files.writeString(file, FIXED); // the save lands after the reader, before the picture is shown
                    } catch (IOException e) {
                        throw new UncheckedIOException(e);
                    }
                }
            }
        };
        driver = WindowDriver.open(new WindowOptions(361, dir, Optional.of(scene)), savedWhileDrawing);
        driver.awaitEdt(() -> !driver.window().busy() && driver.window().shown() != null
                && driver.window().shown().error() == null, "the saved version drawn, with no error, without F5");
        RenderedView shown = driver.onEdt(() -> driver.window().shown());
        assertEquals(new View.OfScene(scene), shown.view());
        assertNull(shown.error());
        assertNotNull(shown.image());
        assertEquals(0xBFBFBF, shown.image().getRGB(375, 375) & 0xFFFFFF, "the triangle, cued at z = -50");
    }
}

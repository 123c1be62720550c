package simpview.window.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.Arrays;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.pages.PageContext;
import simpview.scene.simp.SceneDrawer;

/** The render thread keeps the files its pictures read, until it is told to forget them ("Draw again"). */
class BackgroundRendererTest {

    @TempDir
    Path dir;

    private static RenderedView draw(BackgroundRenderer renderer, Path scene) throws Exception {
        CompletableFuture<RenderedView> done = new CompletableFuture<>();
        renderer.submit(new RenderJob(new View.OfScene(scene), PageContext.defaults(), DrawSettings.WINDOW),
                (job, view) -> done.complete(view));
        RenderedView view = done.get(60, TimeUnit.SECONDS);
        assertNotNull(view, "not cancelled");
        return view;
    }

    /** Where the picture's first primitive was drawn: its projected ends. */
    private static double[] firstOutline(RenderedView view) {
        return view.facts().primitives().outline(0);
    }

    /**
     * A change no stamp shows (same size, same inode, the time of last change
     * set back to a settled one, as a tool that keeps times may leave it) is
     * replayed from what was kept, until the renderer forgets its files.
     */
    @Test
    void forgettingTheFilesReadsThemAfresh() throws Exception {
        Path scene = dir.resolve("s.simp");
        FileTime old = FileTime.fromMillis(System.currentTimeMillis() - 60_000);
        Files.writeString(scene, "line (-50, -50, -10) (50, 50, -10)\n");
        Files.setLastModifiedTime(scene, old);
        BackgroundRenderer renderer = new BackgroundRenderer(SceneDrawer.SIMP);
        try {
            double[] before = firstOutline(draw(renderer, scene));
            Files.writeString(scene, "line (-50, -50, -10) (50, 40, -10)\n");
            Files.setLastModifiedTime(scene, old);
            assertArrayEquals(before, firstOutline(draw(renderer, scene)), "the same stamp, settled: replayed");
            renderer.forgetFiles();
            double[] afresh = firstOutline(draw(renderer, scene));
            assertFalse(Arrays.equals(before, afresh), "read afresh: " + Arrays.toString(afresh));
        } finally {
            renderer.shutdown();
        }
    }
}

package simpview.window.render;

import simpview.scene.simp.SceneDrawer;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.scene.simp.SceneLibrary;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;
import simpview.surface.Provenance;

/** What a finished picture tells the instruments, drawn without a window. */
public class RenderJobTest {

    @TempDir
    Path dir;

    private RenderedView draw(View view, DrawSettings settings) {
        return draw(view, settings, new PageRenderer(), new SceneLibrary());
    }

    /** As the render thread draws: its renderer and its library kept from job to job. */
    private RenderedView draw(View view, DrawSettings settings, PageRenderer renderer, SceneLibrary library) {
        return draw(view, settings, renderer, library, new SpareImages());
    }

    /** The same, the canvas going on on the images given back to {@code spares}. */
    private RenderedView draw(View view, DrawSettings settings, PageRenderer renderer, SceneLibrary library,
            SpareImages spares) {
        RenderJob job = new RenderJob(view, PageContext.defaults().withSimpDir(dir), settings);
        return job.run(renderer, SceneDrawer.SIMP, library, new Provenance(PageCanvas.PANEL, PageCanvas.PANEL),
                spares);
    }

    private static int[] pixels(RenderedView view) {
        return view.image().getRGB(0, 0, view.image().getWidth(), view.image().getHeight(), null, 0,
                view.image().getWidth());
    }

    @Test
    void theRenderThreadsLibraryKeepsAPagesFilesFromPictureToPicture() {
        PageRenderer renderer = new PageRenderer();
        SceneLibrary library = new SceneLibrary();
        RenderedView first = draw(new View.OfPage(5), DrawSettings.WINDOW, renderer, library);
        int scans = library.scenes().scanCount();
        assertTrue(scans >= 2, "page5.simp and the files it includes: " + scans);
        RenderedView again = draw(new View.OfPage(5), DrawSettings.WINDOW, renderer, library);
        assertEquals(scans, library.scenes().scanCount(), "the second picture replays them");
        assertArrayEquals(pixels(first), pixels(again));
        assertEquals(first.facts().files(), again.facts().files());
        assertArrayEquals(pixels(first), pixels(draw(new View.OfPage(5), DrawSettings.WINDOW)),
                "the same as a picture with a library of its own");
    }

    /**
     * The window gives a turning drag's frames back once it shows the next, and later pictures are drawn on
     * them: a picture drawn on an image that held another is the one drawn on a new image, to the pixel (a lit
     * scene and a depth-cued one, on one thread and on two, traced and not), and a picture not given back is
     * never drawn on again.
     */
    @Test
    void aPictureDrawnOnAnImageGivenBackIsThePictureDrawnOnANewOne() throws Exception {
        Path lit = Files.writeString(dir.resolve("lit.simp"), String.join("\n", "ambient 0.3 0.3 0.3",
                "camera -1 -1 1 1 -1 -100", "light 1 1 1 1 0", "surface 0.9 0.5 0.1", "phong",
                "polygon (-30, -30, -40) (30, -30, -40) (30, 30, -40)",
                "polygon (-30, -30, -40) (30, 30, -40) (-30, 30, -40)", ""));
        Path cued = Files.writeString(dir.resolve("cued.simp"),
                "polygon (-90, -90, -20) (90, -90, -20) (0, 90, -150)\nline (-90, 90, -10) (90, -90, -190)\n");
        for (int threads : new int[] {1, 2}) {
            for (DrawSettings settings : List.of(DrawSettings.WINDOW, DrawSettings.WINDOW.withRecord(false))) {
                try (DrawingThreads drawing = DrawingThreads.of(threads)) {
                    PageRenderer renderer = new PageRenderer(drawing);
                    SceneLibrary library = new SceneLibrary();
                    SpareImages spares = new SpareImages();
                    RenderedView first = draw(new View.OfScene(lit), settings, renderer, library, spares);
                    RenderedView cuedOnNew = draw(new View.OfScene(cued), settings, renderer, library, spares);
                    int[] cuedPixels = pixels(cuedOnNew);
                    spares.giveBack(first.image());
                    // Drawn on the image made after the first hand-off; the canvas then takes the first's back.
                    draw(new View.OfScene(lit), settings, renderer, library, spares);
                    RenderedView cuedAgain = draw(new View.OfScene(cued), settings, renderer, library, spares);
                    String where = threads + " thread(s), " + (settings.record() ? "traced" : "untraced");
                    assertSame(first.image(), cuedAgain.image(), where + ": drawn on the lit picture's image");
                    assertArrayEquals(cuedPixels, pixels(cuedAgain), where + ": the same picture");
                    assertArrayEquals(cuedPixels, pixels(cuedOnNew), where + ": not given back, not drawn on");
                }
            }
        }
    }

    @Test
    void aSceneSavedBetweenPicturesIsDrawnAsSaved() throws Exception {
        PageRenderer renderer = new PageRenderer();
        SceneLibrary library = new SceneLibrary();
        Path scene = Files.writeString(dir.resolve("edited.simp"), "line (-50, -50, -10) (50, 50, -10)\n");
        assertEquals(1, draw(new View.OfScene(scene), DrawSettings.WINDOW, renderer, library).facts().primitives().size());
        Files.writeString(scene, "line (-50, -50, -10) (50, 50, -10)\nline (-50, 50, -10) (50, -50, -10)\n");
        assertEquals(2, draw(new View.OfScene(scene), DrawSettings.WINDOW, renderer, library).facts().primitives().size());
    }

    @Test
    void aPageWhoseFileIsMissingDoesNotClaimToShowWhatWasDrawnBeforeIt() {
        RenderedView seven = draw(new View.OfPage(7), DrawSettings.WINDOW);
        assertTrue(seven.error().contains("page7.simp was not found"), seven.error());
        assertFalse(seven.facts().drewSomething());
        assertTrue(seven.title().endsWith("— error"), seven.title());
    }

    @Test
    void aSceneErrorAfterSomeLinesKeepsWhatWasDrawn() throws Exception {
        Path scene = Files.writeString(dir.resolve("half.simp"), "line (-50, -50, -10) (50, 50, -10)\nrotate x 30\n");
        RenderedView half = draw(new View.OfScene(scene), DrawSettings.WINDOW);
        assertNotNull(half.error());
        assertTrue(half.facts().drewSomething());
        assertEquals(1, half.facts().primitives().size());
        assertTrue(half.facts().primitives().describe(0).startsWith("half.simp:1 line (-50, -50, -10)"),
                half.facts().primitives().describe(0));
        assertEquals(List.of(scene), half.facts().files());
    }

    @Test
    void withoutTheWindowsSettingsNothingIsRecorded() throws Exception {
        Path scene = Files.writeString(dir.resolve("one.simp"), "line (-50, -50, -10) (50, 50, -10)\n");
        RenderedView plain = draw(new View.OfScene(scene), DrawSettings.PLAIN);
        assertEquals(null, plain.facts().owners());
        assertEquals(0, plain.facts().primitives().size());
        assertEquals(null, plain.facts().depths(), "nor its depths copied out");
    }

    @Test
    void aFrameNotTracedKeepsItsDepthsOnlyForTheDepthView() throws Exception {
        Path scene = Files.writeString(dir.resolve("one.simp"), "line (-50, -50, -10) (50, 50, -10)\n");
        DrawSettings turning = DrawSettings.WINDOW.withRecord(false);
        assertEquals(null, draw(new View.OfScene(scene), turning).facts().depths(), "a turning drag's frame");
        double[] shown = draw(new View.OfScene(scene), turning.withDepthView(true)).facts().depths();
        double[] traced = draw(new View.OfScene(scene), DrawSettings.WINDOW).facts().depths();
        assertNotNull(shown);
        assertEquals(-10, shown[325 * PageCanvas.PANEL + 325], "the line's depth at the panel's centre");
        assertArrayEquals(traced, shown, "the same depths as the traced picture's");
    }
}

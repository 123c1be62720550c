package simpview.pages;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;
import simpview.testing.Images;

/**
 * A scene file drawn as a page by {@link PageRenderer#renderScene}, as
 * {@code render --scene} draws it, from Java: lit or depth-cued by its own
 * commands, on a canvas cleared first.
 */
class PageRendererTest {

    private static final Path OWN = PageContext.PROJECT_SCENES;

    @TempDir
    Path dir;

    @Test
    void aLitSceneIsDrawnByItsOwnRulesToItsGoldenImageWithTheGivenThreads() throws Exception {
        BufferedImage golden = ImageIO.read(Path.of("src/test/resources/golden/own-lit-shading.png").toFile());
        try (DrawingThreads threads = DrawingThreads.of(2)) {
            PageRenderer renderer = new PageRenderer(threads);
            PageCanvas canvas = renderer.renderScene(OWN.resolve("lit-shading.simp"));
            assertSame(renderer.canvas(), canvas);
            assertEquals(0, Images.differingPixels(golden, canvas.snapshot()));
        }
    }

    /**
     * A snapshot is the page's image as it was, pixel for pixel and of its type (TYPE_INT_RGB, which Java2D
     * draws without converting), and stays so while the canvas draws on.
     */
    @Test
    void aSnapshotIsACopyOfThePageOfItsType() throws Exception {
        PageRenderer renderer = new PageRenderer();
        PageCanvas canvas = renderer.render(2, PageContext.of(OWN));
        BufferedImage snapshot = canvas.snapshot();
        assertEquals(BufferedImage.TYPE_INT_RGB, snapshot.getType());
        assertEquals(canvas.image().getType(), snapshot.getType());
        assertEquals(0, Images.differingPixels(canvas.image(), snapshot));
        int side = snapshot.getWidth();
        int[] before = snapshot.getRGB(0, 0, side, side, null, 0, side);
        renderer.render(5, PageContext.of(OWN));
        assertTrue(Images.differingPixels(canvas.image(), snapshot) > 100_000, "page 5 differs from page 2");
        assertArrayEquals(before, snapshot.getRGB(0, 0, side, side, null, 0, side), "the snapshot kept page 2");
    }

    /**
     * The canvas is cleared before the scene: a scene drawn after a page is
     * the scene alone, where {@link ScenePipeline#draw} onto that canvas
     * would have drawn it over the page.
     */
    @Test
    void aSceneDrawnAfterAPageDoesNotShowThePage() throws Exception {
        Path scene = Files.writeString(dir.resolve("one.simp"), "polygon (-20, -20, -10) (20, -20, -10) (0, 20, -10)\n");
        BufferedImage alone = new PageRenderer().renderScene(scene).snapshot();
        PageRenderer renderer = new PageRenderer();
        BufferedImage page = renderer.render(2, PageContext.of(OWN)).snapshot();
        assertTrue(Images.differingPixels(alone, page) > 100_000, "the page covers much of the panel");
        BufferedImage afterPage = renderer.renderScene(scene).snapshot();
        assertEquals(0, Images.differingPixels(alone, afterPage));
    }

    @Test
    void aDepthCuedSceneIsCuedWhiteToBlackAndSaysItWasNotLit() throws Exception {
        PageRenderer renderer = new PageRenderer();
        ScenePipeline.Drawn drawn = renderer.renderScene(OWN.resolve("cube.simp"),
                ScenePipeline.Options.byCommands(new SceneLibrary()), SceneMonitor.NONE);
        assertFalse(drawn.lit());
        BufferedImage viaOptions = renderer.canvas().snapshot();
        assertEquals(0, Images.differingPixels(viaOptions, renderer.renderScene(OWN.resolve("cube.simp")).snapshot()));
    }

    /**
     * A name found only where the course's program ran is found from Java by naming that folder, with no
     * type of the scene package: the scene draws as if the included file were beside it.
     */
    @Test
    void aNameFoundOnlyInTheNamedWorkingFolderIsDrawnFromThere() throws Exception {
        String triangle = "polygon (-20, -20, -10) (20, -20, -10) (0, 20, -10)\n";
        Path beside = Files.createDirectory(dir.resolve("beside"));
        Files.writeString(beside.resolve("shape.simp"), triangle);
        Path together = Files.writeString(beside.resolve("scene.simp"), "file \"shape\"\n");
        Path ran = Files.createDirectory(dir.resolve("ran"));
        Files.writeString(ran.resolve("shape.simp"), triangle);
        Path scenes = Files.createDirectory(dir.resolve("scenes"));
        Path apart = Files.writeString(scenes.resolve("scene.simp"), "file \"shape\"\n");

        BufferedImage expected = new PageRenderer().renderScene(together).snapshot();
        PageRenderer renderer = new PageRenderer();
        assertThrows(SceneException.class, () -> renderer.renderScene(apart));
        assertEquals(0, Images.differingPixels(expected, renderer.renderScene(apart, ran).snapshot()));
    }

    @Test
    void aBrokenSceneIsACheckedSceneExceptionAtItsLineAndColumn() throws Exception {
        Path scene = Files.writeString(dir.resolve("broken.simp"), "line (0, 0, -1) (1, x, -1)\n");
        SceneException e = assertThrows(SceneException.class, () -> new PageRenderer().renderScene(scene));
        assertEquals(1, e.line());
        assertTrue(e.column() > 0, e.getMessage());
        assertTrue(e.getMessage().startsWith(scene + ":1:" + e.column() + ": expected a number"), e.getMessage());
    }
}

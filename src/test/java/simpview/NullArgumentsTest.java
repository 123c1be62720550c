package simpview;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;
import simpview.compare.Comparison;
import simpview.compare.ComparisonReport;
import simpview.compare.Picture;
import simpview.compare.PngFiles;
import simpview.inspect.InspectedScene;
import simpview.inspect.PixelInspector;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.pages.UnpackedScenes;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.surface.Rgb;

/**
 * A Java caller that hands README.md's "Using simpview from Java" a null
 * where a value belongs is told so where it called, by the parameter's name
 * ("file must not be null"), not by a NullPointerException from deep inside
 * about a local variable, nor pages later (a renderer made with no threads,
 * a context with no folder).
 */
class NullArgumentsTest {

    private static final Path SCENE = PageContext.PROJECT_SCENES.resolve("cube.simp");
    private static final int[] PANEL = new int[Comparison.N * Comparison.N];

    private static void refuses(String parameter, Executable call) {
        NullPointerException e = assertThrows(NullPointerException.class, call);
        assertEquals(parameter + " must not be null", e.getMessage());
    }

    @Test
    void drawingPagesAndScenesNamesTheMissingArgument() {
        refuses("threads", () -> new PageRenderer(null));
        refuses("context", () -> new PageRenderer().renderImage(2, null));
        refuses("context", () -> new PageRenderer().render(4, null));
        refuses("file", () -> new PageRenderer().renderScene(null));
        refuses("workingDir", () -> new PageRenderer().renderScene(SCENE, null));
        refuses("ownScenes", () -> PageContext.of(null));
        refuses("dir", () -> PageContext.defaults().withSimpDir(null));
        refuses("newMonitor", () -> PageContext.defaults().withMonitor(null));
        refuses("rule", () -> PageContext.defaults().withA1Rule(null));
        refuses("kept", () -> PageContext.defaults().withLibrary(null));
        refuses("jar", () -> UnpackedScenes.from(null));
    }

    @Test
    void inspectingNamesTheMissingArgument() {
        refuses("file", () -> InspectedScene.of(null));
        refuses("file", () -> InspectedScene.ownColours(null));
        refuses("near", () -> InspectedScene.cued(SCENE, null, Rgb.BLACK));
        refuses("context", () -> InspectedScene.page(4, null));
        refuses("scene", () -> new PixelInspector().inspect(null, 1, 1));
        refuses("library", () -> new PixelInspector(null, SceneMonitor.NONE));
        refuses("monitor", () -> new PixelInspector(new SceneLibrary(), null));
    }

    @Test
    void comparingNamesTheMissingArgument() throws Exception {
        BufferedImage page = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        Picture picture = Picture.ofPage(page, "a page");
        Comparison comparison = Comparison.of(PANEL, PANEL);
        refuses("file", () -> Picture.read(null));
        refuses("page", () -> Picture.ofPage(null, "a page"));
        refuses("name", () -> Picture.ofPage(page, null));
        refuses("image", () -> Picture.of(null, "a capture"));
        refuses("ours", () -> Comparison.of(null, PANEL));
        refuses("theirs", () -> Comparison.of(PANEL, null));
        refuses("theirs", () -> ComparisonReport.of(null, "page 2", comparison, 8, 99));
        refuses("against", () -> ComparisonReport.of(picture, null, comparison, 8, 99));
        refuses("comparison", () -> ComparisonReport.of(picture, "page 2", null, 8, 99));
        refuses("image", () -> PngFiles.write(null, Path.of("never.png")));
        refuses("file", () -> PngFiles.write(page, null));
    }
}

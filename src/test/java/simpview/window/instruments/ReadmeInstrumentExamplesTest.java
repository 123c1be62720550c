package simpview.window.instruments;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.scene.simp.SceneDrawer;
import simpview.scene.simp.SceneLibrary;
import simpview.surface.PageCanvas;
import simpview.surface.Provenance;
import simpview.testing.CourseFiles;
import simpview.window.render.DrawSettings;
import simpview.window.render.RenderJob;
import simpview.window.render.RenderedView;
import simpview.window.render.SpareImages;
import simpview.window.render.View;

/**
 * The README's examples of what the inspector and the stepping say are what
 * they really say: page 7 drawn as the window draws it, with the record.
 */
class ReadmeInstrumentExamplesTest {

    @Test
    void theInspectorLineTheReadmeQuotesIsTheOneShownForItsPixel() throws Exception {
        Path course = CourseFiles.requireSimpDir();
        PageContext context = PageContext.defaults().withSimpDir(course);
        RenderJob job = new RenderJob(new View.OfPage(7), context, DrawSettings.WINDOW);
        RenderedView seven = job.run(new PageRenderer(), SceneDrawer.SIMP, new SceneLibrary(),
                new Provenance(PageCanvas.PANEL, PageCanvas.PANEL), new SpareImages());
        String readme = Files.readString(Path.of("README.md"));
        // Panel pixel (325, 400): image pixel (50 + 325, 50 + 649 - 400).
        String line = Inspector.describe(seven, 50 + 325, 50 + 649 - 400);
        String owner = line.substring(line.indexOf("drawn by primitive"));
        assertTrue(readme.contains("`" + owner + "`"), "README quotes: " + owner);
        String step = "primitive 2 of " + seven.facts().primitives().size() + ", " + seven.facts().primitives().describe(1);
        assertTrue(readme.contains("`" + step + "`"), "README quotes: " + step);
    }
}

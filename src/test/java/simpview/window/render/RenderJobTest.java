package simpview.window.render;

import simpview.scene.simp.SceneDrawer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.surface.PageCanvas;
import simpview.surface.Provenance;

/** What a finished picture tells the instruments, drawn without a window. */
public class RenderJobTest {

    @TempDir
    Path dir;

    private RenderedView draw(View view, DrawSettings settings) {
        RenderJob job = new RenderJob(view, PageContext.defaults().withSimpDir(dir), settings);
        return job.run(new PageRenderer(), SceneDrawer.SIMP, new simpview.scene.obj.ObjLibrary(), new Provenance(PageCanvas.PANEL, PageCanvas.PANEL));
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
    }
}

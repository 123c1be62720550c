package simpview.inspect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.reference.RandomLitScenes;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.surface.PageCanvas;
import simpview.testing.CourseFiles;

/**
 * For sampled pixels of random scenes, the history's written plus depth-failed
 * entries are the overdraw count, and its depth-failed ones the failure count.
 */
class OverdrawTest {

    @TempDir
    Path dir;

    private final SceneLibrary library = new SceneLibrary();
    private final PixelInspector inspector = new PixelInspector(library, SceneMonitor.NONE);

    @Test
    void historyAndOverdrawAgree() throws Exception {
        int overdrawn = 0;
        for (long seed = 40; seed <= 47; seed++) {
            InspectedScene lit = InspectedScene.of(RandomLitScenes.write(dir, seed));
            InspectedScene cued = InspectedScene.of(RandomCuedScenes.write(dir, seed));
            for (InspectedScene scene : new InspectedScene[] {lit, cued}) {
                Overdraw.Counts both = Overdraw.counts(scene, library);
                int[] counts = both.reached();
                Random random = new Random(seed);
                for (int k = 0; k < 16; k++) {
                    int x = random.nextInt(PageCanvas.PANEL);
                    int y = random.nextInt(PageCanvas.PANEL);
                    PixelReport report = inspector.inspect(scene, x, y);
                    long reached = report.history().stream().filter(e -> e.outcome() == Outcome.WRITTEN
                            || e.outcome() == Outcome.DEPTH_FAILED).count();
                    assertEquals(counts[y * PageCanvas.PANEL + x], reached,
                            scene.file().getFileName() + " (" + x + ", " + y + ")\n" + report.text(true, false));
                    long failed = report.history().stream().filter(e -> e.outcome() == Outcome.DEPTH_FAILED).count();
                    assertEquals(both.failed()[y * PageCanvas.PANEL + x], failed,
                            scene.file().getFileName() + " (" + x + ", " + y + ") failures");
                    if (reached > 1) {
                        overdrawn++;
                    }
                }
            }
        }
        assertTrue(overdrawn > 10, "too few pixels written more than once: " + overdrawn);
    }

    /**
     * A scene that stops at an error is counted as far as the error, as its
     * page is drawn (the page shows what was drawn before it): the two
     * triangles before the bad line overlap at the centre; the one after it
     * is never drawn. A scene none of which can be read is an error still.
     */
    @Test
    void aSceneWithAnErrorIsCountedAsFarAsTheError() throws Exception {
        Path scene = dir.resolve("broken.simp");
        Files.writeString(scene, "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n"
                + "polygon (-50, -50, -20) (50, -50, -20) (0, 50, -20)\n"
                + "rotate Q 5\n"
                + "polygon (-50, -50, -5) (50, -50, -5) (0, 50, -5)\n");
        Overdraw.Counts counts = Overdraw.counts(InspectedScene.of(scene), library);
        int centre = 325 * PageCanvas.PANEL + 325;
        assertEquals(2, counts.reached()[centre]);
        assertEquals(1, counts.failed()[centre]);
        PixelReport report = inspector.inspect(InspectedScene.of(scene), 325, 325);
        assertEquals(2, report.history().size(), "the history goes as far: " + report.text(true, false));
        org.junit.jupiter.api.Assertions.assertThrows(SceneException.class,
                () -> Overdraw.counts(InspectedScene.of(dir.resolve("missing.simp")), library));
    }

    @Test
    void theCoursesPagesCountAsTheirHistories() throws Exception {
        Path a3 = CourseFiles.require("course-simp-a3");
        Path a4 = CourseFiles.require("course-simp-a4");
        for (Path file : new Path[] {a4.resolve("page-d.simp"), a3.resolve("pageI.simp")}) {
            InspectedScene scene = InspectedScene.of(file);
            Overdraw.Counts both = Overdraw.counts(scene, library);
            Random random = new Random(file.getFileName().toString().hashCode());
            List<Integer> reachedPixels = new ArrayList<>();
            for (int i = 0; i < both.reached().length; i++) {
                if (both.reached()[i] > 0) {
                    reachedPixels.add(i);
                }
            }
            int drawn = 0;
            for (int k = 0; k < 7; k++) {
                // Six pixels that some write reached, one anywhere.
                int i = k < 6 ? reachedPixels.get(random.nextInt(reachedPixels.size()))
                        : random.nextInt(both.reached().length);
                int x = i % PageCanvas.PANEL;
                int y = i / PageCanvas.PANEL;
                drawn += both.reached()[i] > 0 ? 1 : 0;
                PixelReport report = inspector.inspect(scene, x, y);
                long reached = report.history().stream().filter(e -> e.outcome() == Outcome.WRITTEN
                        || e.outcome() == Outcome.DEPTH_FAILED).count();
                long failed = report.history().stream().filter(e -> e.outcome() == Outcome.DEPTH_FAILED).count();
                assertEquals(both.reached()[i], reached, file.getFileName() + " (" + x + ", " + y + ")");
                assertEquals(both.failed()[i], failed, file.getFileName() + " (" + x + ", " + y + ") failures");
            }
            assertTrue(drawn >= 6, file.getFileName() + ": too few drawn pixels sampled: " + drawn);
        }
    }
}

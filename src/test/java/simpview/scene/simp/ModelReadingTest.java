package simpview.scene.simp;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.scene.obj.ObjReader;
import simpview.surface.PageCanvas;

/**
 * A lit scene's .obj model of many lines, as a window draws it: the lines read count on while the model is
 * read, and a cancel stops the scene in the middle of the model, not once the model is drawn whole.
 */
class ModelReadingTest {

    /** Squares on a side of the model's grid: its v and f lines together are some three times PROGRESS_LINES. */
    private static final int SIDE = 260;

    @TempDir
    static Path dir;

    /** The scene both tests draw, written once. */
    private static Path scene;

    @BeforeAll
    static void writeScene() throws IOException {
        scene = sceneWithABigModel();
    }

    /** A scene of five commands that draws one model of a grid of SIDE x SIDE squares. */
    private static Path sceneWithABigModel() throws IOException {
        int points = SIDE + 1;
        try (Writer obj = Files.newBufferedWriter(dir.resolve("grid.obj"))) {
            for (int i = 0; i < points; i++) {
                for (int j = 0; j < points; j++) {
                    obj.write("v " + (2.0 * i / SIDE - 1) + " " + (2.0 * j / SIDE - 1) + " 0\n");
                }
            }
            for (int i = 0; i < SIDE; i++) {
                for (int j = 0; j < SIDE; j++) {
                    int a = i * points + j + 1;
                    obj.write("f " + a + " " + (a + points) + " " + (a + points + 1) + "\n");
                    obj.write("f " + a + " " + (a + points + 1) + " " + (a + 1) + "\n");
                }
            }
        }
        return Files.writeString(dir.resolve("grid.simp"), String.join("\n", "ambient 1 1 1",
                "camera -1 -1 1 1 -1 -100", "translate 0 0 -3", "filled", "obj \"grid\"", ""));
    }

    private static void draw(Path scene, SceneMonitor monitor) throws Exception {
        PageCanvas canvas = new PageCanvas();
        canvas.clear();
        ScenePipeline.draw(scene, canvas, ScenePipeline.Options.byCommands(new SceneLibrary()), monitor);
    }

    @Test
    void theLinesReadCountOnThroughTheModel() throws Exception {
        AtomicLong most = new AtomicLong();
        draw(scene, new SceneMonitor() {
            @Override
            public void linesRead(long lines) {
                most.accumulateAndGet(lines, Math::max);
            }
        });
        assertTrue(most.get() > 2 * ObjReader.PROGRESS_LINES,
                "the most lines read told while the scene was drawn: " + most.get());
    }

    @Test
    void aCancelStopsTheSceneInTheMiddleOfTheModel() throws Exception {
        AtomicLong told = new AtomicLong();
        SceneMonitor cancelling = new SceneMonitor() {
            @Override
            public void linesRead(long lines) {
                told.set(lines);
            }

            @Override
            public boolean cancelled() {
                return true;
            }
        };
        assertThrows(SceneCancelledException.class, () -> draw(scene, cancelling));
        assertTrue(told.get() < 2 * ObjReader.PROGRESS_LINES, "stopped at the model's first progress, after line "
                + told.get());
    }
}

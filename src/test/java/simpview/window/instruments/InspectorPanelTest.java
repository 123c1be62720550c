package simpview.window.instruments;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.lang.reflect.InvocationTargetException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.inspect.InspectedScene;
import simpview.scene.simp.SceneLibrary;

/**
 * The inspector panel while stepping: its vertex table is the stepped
 * primitive's, and it says so only when the scene has that primitive (an
 * empty scene, or one saved shorter while stepping, has not: the table is
 * then the pixel's owner's, and no sentence claims otherwise).
 */
class InspectorPanelTest {

    @TempDir
    Path dir;

    private InspectorPanel panel;

    @AfterEach
    void shutDown() {
        if (panel != null) {
            panel.shutdown();
        }
    }

    /** The panel's text once it has answered inspect(scene, 325, 325, note, null, stepped). */
    private String answer(Path scene, int stepped) throws Exception {
        onEdt(() -> {
            if (panel == null) {
                panel = new InspectorPanel(new SceneLibrary());
            }
            panel.inspect(InspectedScene.of(scene), 325, 325, "While stepping.", null, stepped);
        });
        return awaitAnswer();
    }

    /** The panel's text once it has answered its last request. */
    private String awaitAnswer() throws Exception {
        long deadline = System.nanoTime() + 20_000_000_000L;
        AtomicReference<String> text = new AtomicReference<>();
        while (System.nanoTime() < deadline) {
            onEdt(() -> text.set(panel.answered() ? panel.text() : null));
            if (text.get() != null) {
                return text.get();
            }
            Thread.sleep(5); // waiting for the answer this test asserts on
        }
        fail("the panel did not answer in 20 s");
        return null;
    }

    private static void onEdt(Runnable work) throws InterruptedException, InvocationTargetException {
        SwingUtilities.invokeAndWait(work);
    }

    @Test
    void theSteppedPrimitivesVerticesAreNamedOnlyWhenTheSceneHasIt() throws Exception {
        Path scene = dir.resolve("two.simp");
        Files.writeString(scene, "polygon (-90, -90, -100) (90, -90, -100) (0, 90, -100)\n"
                + "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n");

        String first = answer(scene, 0);
        assertTrue(first.startsWith("While stepping. The vertices below are primitive 1's, the one stepped to.\n"), first);
        assertTrue(first.contains("vertices of primitive 1:"), first);

        String beyond = answer(scene, 5); // stepped to 6, then the file saved with two primitives
        assertTrue(beyond.startsWith("While stepping.\n"), beyond);
        assertFalse(beyond.contains("the one stepped to"), beyond);
        assertTrue(beyond.contains("vertices of primitive 2:"), "the owner's table instead: " + beyond);
    }

    /**
     * A new request leaves the last answer in the panel until its own comes:
     * the waiting words, said at once, flashed at every move of the pointer
     * over a page, most replays taking a few milliseconds.
     */
    @Test
    void theLastAnswerStaysUntilTheNextOnesComes() throws Exception {
        Path scene = dir.resolve("one.simp");
        Files.writeString(scene, "polygon (-90, -90, -100) (90, -90, -100) (0, 90, -100)\n");
        String first = answer(scene, 0);
        AtomicReference<String> right = new AtomicReference<>();
        onEdt(() -> {
            panel.inspect(InspectedScene.of(scene), 300, 300, "While stepping.", null, 0);
            right.set(panel.text());
        });
        assertEquals(first, right.get(), "right after the next request");
        String next = awaitAnswer();
        assertTrue(next.contains("(300, 300)") && !next.equals(first), "then the new pixel's answer: " + next);
    }
}

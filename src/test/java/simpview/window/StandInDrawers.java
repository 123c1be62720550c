package simpview.window;

import java.util.List;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.Drawable;

import simpview.scene.simp.SceneDrawer;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import simpview.scene.simp.SceneCancelledException;

/**
 * Stand-ins for the SIMP interpreter, so the window's own machinery
 * (render thread, progress, cancel) can be tested whatever state the
 * interpreter is in. They read the file but understand none of it.
 */
public final class StandInDrawers {

    static final int REPORT_EVERY = 1000;

    private StandInDrawers() {
    }

    /** Reads every line, paints one pixel per line, and takes about 2 ms per 1000 lines. */
    static final SceneDrawer SLOW_READER = (file, canvas, options, monitor) -> {
        Drawable panel = canvas.depthTested();
        long lines = 0;
        try (BufferedReader in = Files.newBufferedReader(file)) {
            while (in.readLine() != null) {
                lines++;
                panel.setPixel((int) (lines % panel.width()), (int) (lines / panel.width() % panel.height()), -100, 0xFFFFFFFF);
                if (lines % REPORT_EVERY == 0) {
                    monitor.linesRead(lines);
                    if (monitor.cancelled()) {
                        throw new SceneCancelledException();
                    }
                    pause();
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        monitor.linesRead(lines);
        return drawn(file, monitor);
    };

    /** Reports progress every few milliseconds and never finishes: only a cancel ends it. */
    static final SceneDrawer UNTIL_CANCELLED = (file, canvas, options, monitor) -> {
        for (long lines = REPORT_EVERY; !monitor.cancelled(); lines += REPORT_EVERY) {
            monitor.linesRead(lines);
            pause();
        }
        throw new SceneCancelledException();
    };

    /** As {@link #UNTIL_CANCELLED}, of a scene that tells it is lit before it reports any progress. */
    static final SceneDrawer LIT_UNTIL_CANCELLED = (file, canvas, options, monitor) -> {
        monitor.turnedLit();
        return UNTIL_CANCELLED.draw(file, canvas, options, monitor);
    };

    /** Draws a white diagonal at the near plane, whatever the file says. */
    static final SceneDrawer DIAGONAL = (file, canvas, options, monitor) -> {
        Drawable panel = canvas.depthTested();
        for (int i = 0; i < panel.width(); i++) {
            panel.setPixel(i, i, 0, 0xFFFFFFFF);
        }
        return drawn(file, monitor);
    };

    /** What a stand-in drew: a depth-cued picture of the one file it read. */
    private static ScenePipeline.Drawn drawn(Path file, SceneMonitor monitor) {
        monitor.reached(List.of(file));
        return new ScenePipeline.Drawn(false, null, true, List.of(file));
    }

    static Path sceneFile(Path dir, String name) throws IOException {
        return Files.writeString(dir.resolve(name), "line (-100, -100, 0) (100, 100, 0)\n");
    }

    private static void pause() {
        try {
            Thread.sleep(2);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new SceneCancelledException();
        }
    }
}

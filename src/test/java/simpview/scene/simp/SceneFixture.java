package simpview.scene.simp;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import simpview.geometry.Vertex;
import simpview.raster.LineRenderer;
import simpview.raster.PolygonRenderer;
import simpview.scene.SceneException;
import simpview.surface.Drawable;

/**
 * Runs scenes written into a folder through the real reader and client, with
 * renderers that only record what they were asked to draw.
 */
final class SceneFixture {

    final Path dir;
    final List<Vertex[]> lines = new ArrayList<>();
    final List<Vertex[]> filled = new ArrayList<>();
    final List<Vertex[]> wire = new ArrayList<>();
    final List<String> warnings = new ArrayList<>();
    SimpClient client;

    SceneFixture(Path dir) {
        this.dir = dir;
    }

    /** Writes name.simp with the given lines. */
    Path write(String name, String... lineTexts) throws IOException {
        Path file = dir.resolve(name + ".simp");
        Files.write(file, (String.join("\n", lineTexts) + "\n").getBytes(StandardCharsets.UTF_8));
        return file;
    }

    /** Runs the scene in name.simp; what was drawn is in lines, filled and wire. */
    SceneFixture run(String name) throws SceneException {
        return run(name, new FileStack());
    }

    SceneFixture run(String name, FileStack files) throws SceneException {
        LineRenderer lineRecorder = (p, q, d) -> lines.add(new Vertex[] {p, q});
        PolygonRenderer filledRecorder = (p, q, r, d) -> filled.add(new Vertex[] {p, q, r});
        PolygonRenderer wireRecorder = (p, q, r, d) -> wire.add(new Vertex[] {p, q, r});
        client = new SimpClient(NOWHERE, lineRecorder, filledRecorder, wireRecorder, files);
        new SimpInterpreter(client, new SceneMonitor() {
            @Override
            public void warning(String message) {
                warnings.add(message);
            }
        }).run(dir.resolve(name + ".simp"));
        return this;
    }

    int drawn() {
        return lines.size() + filled.size() + wire.size();
    }

    /** Runs and returns the error the scene must fail with. */
    SceneException failure(String name) {
        try {
            run(name);
        } catch (SceneException e) {
            return e;
        }
        throw new AssertionError(name + ".simp was expected to fail but drew " + drawn() + " primitives");
    }

    /** A drawable that must never be written: the recording renderers do not touch it. */
    static final Drawable NOWHERE = throwingAtEveryWrite(() -> new AssertionError("recording renderers draw nothing"));

    /** A 650x650 drawable whose every write throws the error {@code error} makes. */
    static Drawable throwingAtEveryWrite(Supplier<Error> error) {
        return new Drawable() {
            @Override
            public int width() {
                return 650;
            }

            @Override
            public int height() {
                return 650;
            }

            @Override
            public void setPixel(int x, int y, double z, int argb) {
                throw error.get();
            }

            @Override
            public int getPixel(int x, int y) {
                return 0;
            }
        };
    }
}

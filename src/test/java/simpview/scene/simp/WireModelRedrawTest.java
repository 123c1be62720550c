package simpview.scene.simp;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;
import simpview.surface.Provenance;
import simpview.testing.CourseFiles;
import simpview.testing.DepthBits;
import simpview.testing.GoldenCase;
import simpview.testing.Images;

/**
 * A wire .obj model drawn again from its kept model, where each edge that
 * two faces share is drawn once (LitGeometry), is the picture drawn as the
 * file was read, every edge drawn: pixels, depths and owners, on one thread
 * and on two. The project's torus, and the course's A3 pageI when present.
 */
class WireModelRedrawTest {

    @TempDir
    Path dir;

    /** What one picture leaves: its pixels, its depths' bits and its owners. */
    private record Drawing(int[] pixels, long[] depths, int[] owners) {
    }

    private static Drawing draw(Path scene, SceneLibrary library, DrawingThreads threads) throws Exception {
        PageCanvas canvas = new PageCanvas();
        canvas.drawWith(threads);
        Provenance owners = new Provenance(PageCanvas.PANEL, PageCanvas.PANEL);
        canvas.recordProvenance(owners);
        canvas.clear();
        ScenePipeline.draw(scene, canvas, ScenePipeline.Options.lit(library), SceneMonitor.NONE);
        return new Drawing(Images.rgb(canvas.image()), DepthBits.of(canvas.zbuffer()), owners.copyOwners());
    }

    @Test
    void aWireModelDrawnAgainFromItsKeptModelIsThePictureDrawnAsTheFileWasRead() throws Exception {
        Files.copy(GoldenCase.ownSimpDir().resolve("torus.obj"), dir.resolve("torus.obj"));
        Path torus = Files.writeString(dir.resolve("wire-torus.simp"), String.join("\n",
                "camera -1 -1 1 1 -1 -100", "ambient 0.2 0.2 0.2", "surface 0.9 0.6 0.2", "wire",
                "{", "translate 0 0 -6", "rotate X 60", "obj \"torus\"", "}",
                "{", "translate 1.5 0 -9", "rotate X 20", "scale 2 2 2", "obj \"torus\"", "}", ""));
        List<Path> scenes = new ArrayList<>(List.of(torus));
        Path a3 = CourseFiles.folder("course-simp-a3");
        if (a3.toFile().isDirectory()) {
            scenes.add(a3.resolve("pageI.simp"));
        }
        for (int threads : new int[] {1, 2}) {
            try (DrawingThreads drawing = DrawingThreads.of(threads)) {
                for (Path scene : scenes) {
                    SceneLibrary library = new SceneLibrary();
                    Drawing read = draw(scene, library, drawing);
                    for (int again = 1; again <= 2; again++) {
                        Drawing kept = draw(scene, library, drawing);
                        String what = scene.getFileName() + " on " + threads + " thread(s), drawn again " + again;
                        assertArrayEquals(read.pixels(), kept.pixels(), what + ": the picture");
                        assertArrayEquals(read.depths(), kept.depths(), what + ": the depths, to the bit");
                        assertArrayEquals(read.owners(), kept.owners(), what + ": the owners");
                    }
                }
            }
        }
    }
}

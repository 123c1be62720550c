package simpview.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import simpview.pages.Assignment2;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;
import simpview.testing.CourseFiles;
import simpview.testing.GoldenCase;
import simpview.surface.DrawingThreads;
import simpview.testing.ThreadCounts;

/**
 * simpview against the independent {@link ReferenceRenderer}, the way unseen
 * scenes are judged: at least 99.9 % of panel pixels match within 3/255 per
 * channel, a pixel also matching when the reference has its colour one pixel
 * away (slack along edges and lines); the margins stay white.
 */
class ReferenceComparisonTest {

    private static final double REQUIRED = 0.999;
    private static final int TOLERANCE = 3;

    @TempDir
    Path dir;

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"page6.simp", "page7.simp", "page8.simp"})
    void courseScenes(String name) throws Exception {
        Path course = CourseFiles.requireSimpDir();
        compare(course.resolve(name), Rgb.WHITE);
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"page4.simp", "page5.simp"})
    void ownScenes(String name) throws Exception {
        compare(GoldenCase.ownSimpDir().resolve(name), name.equals("page4.simp") ? Rgb.GREEN : Assignment2.PAGE5_NEAR);
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void randomScenes(long seed) throws Exception {
        compare(writeRandomScene(seed), new Rgb(0.9, 0.7, 1));
    }

    /** A negative control: a picture that is off (a dimmer near colour) must not pass. */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {4})
    void theComparisonNoticesAWrongPicture(long seed) throws Exception {
        Path scene = writeRandomScene(seed);
        AssertionError failure = assertThrows(AssertionError.class,
                () -> compare(scene, new Rgb(0.8, 0.8, 0.8), Rgb.WHITE));
        assertTrue(failure.getMessage().contains("match the reference"), failure.getMessage());
    }

    /** A random scene in the temporary folder, beside a copy of the project's own cube. */
    private Path writeRandomScene(long seed) throws IOException {
        Path cube = dir.resolve("cube.simp");
        if (!Files.exists(cube)) {
            Files.copy(GoldenCase.ownSimpDir().resolve("cube.simp"), cube);
        }
        Path scene = dir.resolve("random" + seed + ".simp");
        Files.writeString(scene, randomScene(new Random(seed)));
        return scene;
    }

    private static void compare(Path scene, Rgb near) throws IOException, SceneException {
        compare(scene, near, near);
    }

    /** simpview's picture on 1, 2 and 7 threads, each against the reference's. */
    private static void compare(Path scene, Rgb near, Rgb referenceNear) throws IOException, SceneException {
        ReferenceRenderer reference = new ReferenceRenderer(
                new double[] {referenceNear.r(), referenceNear.g(), referenceNear.b()}, new double[] {0, 0, 0});
        reference.render(scene);
        for (int threads : ThreadCounts.ALL) {
            PageCanvas canvas = new PageCanvas();
            try (DrawingThreads drawing = DrawingThreads.of(threads)) {
                ScenePipeline.drawDepthCued(scene, canvas.depthCued(near, Rgb.BLACK), SceneMonitor.NONE, drawing, null);
            }
            compare(scene, threads, canvas, reference);
        }
    }

    private static void compare(Path scene, int threads, PageCanvas canvas, ReferenceRenderer reference) {

        int matching = 0;
        int exact = 0;
        int drawn = 0;
        for (int y = 0; y < ReferenceRenderer.N; y++) {
            for (int x = 0; x < ReferenceRenderer.N; x++) {
                int ours = canvas.panel().getPixel(x, y) & 0xFFFFFF;
                drawn += reference.panel[y * ReferenceRenderer.N + x] != 0 ? 1 : 0;
                exact += ours == reference.panel[y * ReferenceRenderer.N + x] ? 1 : 0;
                matching += matchesNear(ours, reference.panel, x, y) ? 1 : 0;
            }
        }
        int total = ReferenceRenderer.N * ReferenceRenderer.N;
        // Nothing is printed on success: the numbers are in the message when it fails
        // (and the negative control below checks that a wrong picture does).
        String numbers = String.format(Locale.ROOT, "%.4f%% within tolerance, %.4f%% identical; the reference drew %d pixels",
                100.0 * matching / total, 100.0 * exact / total, drawn);
        assertTrue(drawn > total / 100, scene.getFileName() + " on " + threads + " threads: the reference drew only " + drawn
                + " pixels, too few for the comparison to mean much");
        assertTrue(matching >= REQUIRED * total, scene.getFileName() + " on " + threads + " threads: only " + matching + " of " + total
                + " panel pixels match the reference (" + numbers + ")");
        assertMarginsWhite(canvas);
    }

    private static boolean matchesNear(int ours, int[] reference, int x, int y) {
        for (int dy = -1; dy <= 1; dy++) {
            for (int dx = -1; dx <= 1; dx++) {
                int rx = x + dx;
                int ry = y + dy;
                if (rx >= 0 && rx < ReferenceRenderer.N && ry >= 0 && ry < ReferenceRenderer.N
                        && close(ours, reference[ry * ReferenceRenderer.N + rx])) {
                    return true;
                }
            }
        }
        return false;
    }

    private static boolean close(int a, int b) {
        for (int shift = 0; shift <= 16; shift += 8) {
            if (Math.abs((a >> shift & 0xFF) - (b >> shift & 0xFF)) > TOLERANCE) {
                return false;
            }
        }
        return true;
    }

    private static void assertMarginsWhite(PageCanvas canvas) {
        for (int y = 0; y < PageCanvas.SIZE; y++) {
            for (int x = 0; x < PageCanvas.SIZE; x++) {
                if (x < 50 || x >= 700 || y < 50 || y >= 700) {
                    assertEquals(0xFFFFFF, canvas.image().getRGB(x, y) & 0xFFFFFF, "margin " + x + "," + y);
                }
            }
        }
    }

    /**
     * Boxes, loose triangles and lines under random nested transforms, some
     * reaching outside the view volume, with wire and filled styles mixed.
     */
    static String randomScene(Random random) {
        List<String> lines = new ArrayList<>();
        for (int group = 0; group < 12; group++) {
            lines.add("{");
            lines.add(String.format(Locale.ROOT, "translate %.3f, %.3f, %.3f", uniform(random, -110, 110),
                    uniform(random, -110, 110), uniform(random, -230, 20)));
            lines.add(String.format(Locale.ROOT, "rotate %s %.2f", "XYZ".charAt(random.nextInt(3)),
                    uniform(random, -180, 180)));
            lines.add(String.format(Locale.ROOT, "rotate %s %.2f", "XYZ".charAt(random.nextInt(3)),
                    uniform(random, -180, 180)));
            lines.add(String.format(Locale.ROOT, "scale %.3f %.3f %.3f", uniform(random, 5, 60),
                    uniform(random, 5, 60), uniform(random, 5, 60)));
            lines.add(random.nextInt(4) == 0 ? "wire" : "filled");
            switch (random.nextInt(3)) {
                case 0 -> lines.add("file \"cube\"");
                case 1 -> lines.add(String.format(Locale.ROOT, "polygon %s %s %s", point(random), point(random),
                        point(random)));
                default -> lines.add(String.format(Locale.ROOT, "line %s %s", point(random), point(random)));
            }
            lines.add("}");
        }
        return String.join("\n", lines) + "\n";
    }

    private static String point(Random random) {
        return String.format(Locale.ROOT, "(%.4f, %.4f, %.4f)", uniform(random, -1.5, 1.5),
                uniform(random, -1.5, 1.5), uniform(random, -1.5, 1.5));
    }

    private static double uniform(Random random, double lo, double hi) {
        return lo + random.nextDouble() * (hi - lo);
    }
}

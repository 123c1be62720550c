package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.geometry.Vertex;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.pages.ZBufferPage;

/**
 * Page 3's six triangles filled as a student's renderer with a wrong depth test fills them, by a fill of this test's
 * own (pixel centres, y up): told which mistake it is, in the report and in check's.
 */
class DepthTestHintTest {

    private static final int N = 650;

    @TempDir
    Path dir;

    /**
     * Page 3 of seed 361 as a page: each triangle written where {@code wins} says, given its z and the z kept there
     * (NaN where none is).
     */
    private Path drawn(String name, DepthRule wins) throws Exception {
        int[] panel = new int[N * N];
        double[] kept = new double[N * N];
        Arrays.fill(kept, Double.NaN);
        for (Vertex[] t : ZBufferPage.triangles(PageContext.defaults().seed())) {
            int grey = (int) Math.round(t[0].r() * 255);
            for (int y = 0; y < N; y++) {
                for (int x = 0; x < N; x++) {
                    double cx = x + 0.5;
                    double cy = y + 0.5;
                    double e0 = cross(t[0], t[1], cx, cy);
                    double e1 = cross(t[1], t[2], cx, cy);
                    double e2 = cross(t[2], t[0], cx, cy);
                    boolean inside = e0 >= 0 && e1 >= 0 && e2 >= 0 || e0 <= 0 && e1 <= 0 && e2 <= 0;
                    int i = (N - 1 - y) * N + x;
                    if (inside && wins.writes(t[0].z(), kept[i])) {
                        kept[i] = t[0].z();
                        panel[i] = grey << 16 | grey << 8 | grey;
                    }
                }
            }
        }
        int[] rows = new int[750 * 750];
        for (int y = 0; y < 750; y++) {
            for (int x = 0; x < 750; x++) {
                boolean in = x >= 50 && x < 700 && y >= 50 && y < 700;
                rows[y * 750 + x] = in ? panel[(y - 50) * N + x - 50] : 0xFFFFFF;
            }
        }
        BufferedImage page = new BufferedImage(750, 750, BufferedImage.TYPE_INT_RGB);
        page.setRGB(0, 0, 750, 750, rows, 0, 750);
        Path file = dir.resolve(name);
        Files.createDirectories(file.getParent());
        ImageIO.write(page, "png", file.toFile());
        return file;
    }

    private static double cross(Vertex a, Vertex b, double x, double y) {
        return (b.x() - a.x()) * (y - a.y()) - (b.y() - a.y()) * (x - a.x());
    }

    private interface DepthRule {
        boolean writes(double z, double kept);
    }

    @Test
    void theRightFillOfThisTestPassesAndIsToldNothing() throws Exception {
        CliRun run = CliRun.of("compare", drawn("right.png", (z, kept) -> Double.isNaN(kept) || z > kept).toString(),
                "--page", "3");
        assertEquals(ExitCode.OK, run.exitCode(), run.out());
        assertFalse(run.out().contains("hint:"), run.out());
    }

    @Test
    void trianglesDrawnWithoutADepthTestAreToldSo() throws Exception {
        Path picture = drawn("page3.png", (z, kept) -> true);
        CliRun run = CliRun.of("compare", picture.toString(), "--page", "3");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        assertTrue(run.out().contains("FAIL: 75.47 % within 8/255 with slack"), run.out());
        assertTrue(run.out().contains("\nhint: your picture passes as simpview's page 3 (seed 361) drawn without a depth"
                + " test: each triangle covers those drawn before it, whatever its depth (100.00 % by the same rule). "
                + "SPEC's z-buffer"), run.out());
        CliRun check = CliRun.of("check", picture.getParent().toString(), "--pages", "3");
        assertTrue(check.out().contains("\nhint: page3.png (page 3 (seed 361)): your picture passes as simpview's page 3"
                + " (seed 361) drawn without a depth test"), check.out());
        assertTrue(check.err().contains("page3.png: FAIL 75.47 %; looks like page 3 (seed 361) drawn without a depth "
                + "test"), check.err());
    }

    @Test
    void trianglesDrawnWithTheDepthTestTurnedRoundAreToldSo() throws Exception {
        CliRun run = CliRun.of("compare", drawn("page3.png", (z, kept) -> Double.isNaN(kept) || z < kept).toString(),
                "--page", "3");
        assertTrue(run.out().contains("\nhint: your picture passes as simpview's page 3 (seed 361) drawn with its "
                + "depth test turned round: where triangles overlap, the farthest is in front"), run.out());
    }

    /**
     * Page 3 of another seed passes as neither mistake: its triangles lie elsewhere, in simpview's greys, and it is
     * told it was drawn from other random numbers, with the command that lists simpview's.
     */
    @Test
    void pageThreeOfAnotherSeedIsToldItsTrianglesAreNotSimpviews() throws Exception {
        Path picture = dir.resolve("seven.png");
        ImageIO.write(new PageRenderer().renderImage(3, PageContext.defaults().withSeed(7)), "png", picture.toFile());
        CliRun run = CliRun.of("compare", picture.toString(), "--page", "3");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        assertFalse(run.out().contains("depth test"), run.out());
        assertTrue(run.out().contains("\nhint: your triangles are not simpview's, which it draws at random from seed "
                + "361: every pixel of yours is one of the 7 colours of simpview's panel, but of the pixels either "
                + "picture draws, both draw 4.69 % in the same colour. A page drawn from random numbers of your own "
                + "cannot match; to compare your renderer, draw simpview's lines and triangles with their colours, "
                + "which simpview render --page 3 --seed 361 --primitives page3-primitives.txt lists"), run.out());
    }

    /** The painter's-order page is a depth test's mistake, not random numbers: its triangles are where simpview's are. */
    @Test
    void trianglesWithoutADepthTestAreNotCalledRandom() throws Exception {
        CliRun run = CliRun.of("compare", drawn("page3.png", (z, kept) -> true).toString(), "--page", "3");
        assertFalse(run.out().contains("not simpview's"), run.out());
    }
}

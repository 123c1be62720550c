package simpview.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;
import simpview.testing.Images;
import simpview.testing.ThreadCounts;

/**
 * SPEC Part 2, "Depth and interpolation in perspective": the z-buffer takes a
 * write only when its z is strictly nearer (greater) than the stored one, so
 * of two writes at the same depth the first stays. The same primitive drawn
 * twice, red then green, gives the same depths to the bit at every pixel: no
 * green may show. Moved a little nearer, the green one covers the red (so
 * the scene does draw). Every shading mode, filled and wire, lines, a phong
 * polygon under a light (no specular term, ks 0), with and without a camera,
 * drawn by 1, 2 and 7 threads.
 */
class LitEqualDepthTest {

    @TempDir
    Path dir;

    static List<String[]> looks() {
        List<String[]> looks = new ArrayList<>();
        for (String camera : new String[] {"", "camera -1 -1 1 1 -1 -300"}) {
            for (String shading : new String[] {"flat", "gouraud", "phong"}) {
                for (String style : new String[] {"filled", "wire"}) {
                    looks.add(new String[] {camera, shading, style, ""});
                }
            }
            // Lit by a light, phong pixels wait to be lit at the picture's end; its spans take their own depth test.
            looks.add(new String[] {camera, "phong", "filled", "light 0.5 0.5 0.5 1 0"});
        }
        return looks;
    }

    @ParameterizedTest(name = "{0} {1} {2} {3}")
    @MethodSource("looks")
    void ofTwoWritesAtEqualDepthTheFirstStays(String camera, String shading, String style, String light)
            throws Exception {
        for (int threads : ThreadCounts.ALL) {
            int[] same = counts(draw(threads, camera + "\n" + light, shading, style, 0));
            assertTrue(same[0] > 500, "the red primitives draw: " + same[0] + " pixels");
            assertEquals(0, same[1], "green pixels over red ones at the same depth, " + threads + " threads");
            int[] nearer = counts(draw(threads, camera + "\n" + light, shading, style, 0.5));
            assertTrue(nearer[1] > same[0] * 9 / 10, "moved nearer, green covers red: " + nearer[1] + " of "
                    + same[0] + ", " + threads + " threads");
        }
    }

    /**
     * Red, then green: a triangle at z = -100 in its command's shading and
     * style and a line crossing it, each drawn twice, the green ones moved by
     * {@code nearer} toward the eye. The triangle's corners have colours of
     * their own, three shades of red or green, so that its pixels do not all
     * share one kd (a polygon of one kd takes a depth test of its own).
     */
    private PageCanvas draw(int threads, String camera, String shading, String style, double nearer)
            throws IOException, SceneException {
        StringBuilder scene = new StringBuilder(camera).append("\nambient 1 1 1\nsurface 1 1 1 0 8\n").append(shading).append('\n')
                .append(style).append('\n');
        double[] depths = {-100, -100 + nearer};
        String[][] colours = {{"1 0 0", "0.8 0 0", "0.6 0 0"}, {"0 1 0", "0 0.8 0", "0 0.6 0"}};
        for (int k = 0; k < 2; k++) {
            double z = depths[k];
            String[] c = colours[k];
            scene.append("polygon (-61.3, -47.9, ").append(z).append(", ").append(c[0]).append(") (58.1, -39.7, ")
                    .append(z - 30).append(", ").append(c[1]).append(") (-7.3, 66.1, ").append(z + 20).append(", ")
                    .append(c[2]).append(")\n")
                    .append("line (-83.7, 21.9, ").append(z).append(", ").append(c[0]).append(") (77.3, -12.1, ")
                    .append(z - 50).append(", ").append(c[2]).append(")\n");
        }
        Path file = dir.resolve("equal.simp");
        Files.writeString(file, scene);
        PageCanvas canvas = new PageCanvas();
        try (DrawingThreads drawing = DrawingThreads.of(threads)) {
            canvas.drawWith(drawing);
            ScenePipeline.draw(file, canvas, ScenePipeline.Options.lit(new SceneLibrary()), SceneMonitor.NONE);
        }
        return canvas;
    }

    /** Red and green pixels of the panel (of any level); a pixel of both, or of blue, fails. */
    private static int[] counts(PageCanvas canvas) {
        int[] counts = new int[2];
        int m = PageCanvas.MARGIN;
        int n = PageCanvas.PANEL;
        int[] panel = Images.rgb(canvas.image(), m, m, n, n);
        for (int i = 0; i < panel.length; i++) {
            int rgb = panel[i] & 0xFFFFFF;
            boolean red = (rgb & 0xFF0000) != 0;
            boolean green = (rgb & 0x00FF00) != 0;
            if (red && !green && (rgb & 0xFF) == 0) {
                counts[0]++;
            } else if (green && !red && (rgb & 0xFF) == 0) {
                counts[1]++;
            } else if (rgb != 0) {
                fail("panel pixel " + i % n + "," + (n - 1 - i / n) + " is " + Integer.toHexString(rgb));
            }
        }
        return counts;
    }
}

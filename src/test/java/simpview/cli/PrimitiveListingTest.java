package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.geometry.Vertex;
import simpview.pages.ZBufferPage;

/**
 * {@code render --page N --primitives F}: a seeded page's own lines and
 * triangles, which a student's renderer draws to be compared with simpview's
 * picture. Shown by doing just that: the first assignment's random lines,
 * read back from the listing and drawn by a plain DDA written here from
 * SPEC's words, make simpview's DDA panel pixel for pixel.
 */
public class PrimitiveListingTest {

    @TempDir
    Path dir;

    /** The numbers of every primitive line of a listing, '#' lines left out. */
    private static List<double[]> read(String listing) {
        List<double[]> rows = new ArrayList<>();
        for (String line : listing.split("\n")) {
            if (line.startsWith("#") || line.isEmpty()) {
                continue;
            }
            String[] words = line.split(" ");
            double[] numbers = new double[words.length - 1];
            numbers[0] = Integer.parseInt(words[1]);
            for (int i = 2; i < words.length; i++) {
                numbers[i - 1] = Double.parseDouble(words[i]);
            }
            assertEquals(words[0].equals("line") ? 1 + 2 * 6 : 1 + 3 * 6, numbers.length, line);
            rows.add(numbers);
        }
        return rows;
    }

    /** SPEC's DDA: ends rounded half up, one pixel per major step, the minor coordinate added up and rounded. */
    private static void dda(int[] panel, int n, double[] line, int colour) {
        double x0 = Math.floor(line[1] + 0.5);
        double y0 = Math.floor(line[2] + 0.5);
        double x1 = Math.floor(line[7] + 0.5);
        double y1 = Math.floor(line[8] + 0.5);
        boolean xMajor = Math.abs(x1 - x0) >= Math.abs(y1 - y0);
        if (xMajor ? x1 < x0 : y1 < y0) {
            double t = x0;
            x0 = x1;
            x1 = t;
            t = y0;
            y0 = y1;
            y1 = t;
        }
        double steps = xMajor ? x1 - x0 : y1 - y0;
        double slope = steps == 0 ? 0 : (xMajor ? y1 - y0 : x1 - x0) / steps;
        double minor = xMajor ? y0 : x0;
        for (int k = 0; k <= steps; k++) {
            int x = (int) (xMajor ? x0 + k : Math.floor(minor + 0.5));
            int y = (int) (xMajor ? Math.floor(minor + 0.5) : y0 + k);
            panel[(n - 1 - y) * n + x] = colour;
            minor += slope;
        }
    }

    private static int level(double c) {
        return (int) Math.max(0, Math.min(255, Math.floor(c * 255 + 0.5)));
    }

    @Test
    void theRandomLinesDrawnFromTheListingAreSimpviewsDdaPanel() throws Exception {
        Path listing = dir.resolve("lines.txt");
        Path picture = dir.resolve("a1-page3.png");
        CliRun run = CliRun.of("render", "--assignment", "1", "--page", "3", "--seed", "7", "--primitives",
                listing.toString(), "--out", picture.toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        String text = Files.readString(listing);
        assertTrue(text.startsWith("# simpview: the first assignment's page 3, Random lines, seed 7: 120 lines, "
                + "0 triangles\n"), text);
        List<double[]> lines = read(text);
        assertEquals(4 * 30, lines.size(), "the 30 lines in each of the four panels");
        // The colours are whole levels, k / 255, and say so: blended as printed they give simpview's bytes.
        // the header's sentences wrapped at words, as its fixed lines are: none runs on past the width
        String header = text.lines().filter(l -> l.startsWith("#")).collect(Collectors.joining("\n"));
        assertTrue(header.lines().allMatch(l -> l.length() <= PrimitiveListing.WIDTH), header);
        String joined = header.replace("\n# ", " ");
        assertTrue(joined.contains("each colour channel is a whole number of 255ths, k / 255 (the first line's red, "),
                header);
        assertTrue(joined.contains(": k is the byte a pixel the line covers whole gets; the antialiased panel blends "
                + "this colour, c * colour + (1 - c) * old"), header);
        assertTrue(joined.contains("the same lines in each panel, drawn by panel 1: DDA, 2: Bresenham, 3: alternating "
                + "DDA / Bresenham, 4: antialiased (ends rounded first)"), header);
        for (double[] line : lines) {
            for (int channel : new int[] {4, 5, 6, 10, 11, 12}) {
                assertEquals(level(line[channel]) / 255.0, line[channel], "printed as simpview draws it: " + line[channel]);
            }
        }
        int n = 300;
        int[] drawn = new int[n * n];
        for (double[] line : lines) {
            if (line[0] == 1) {
                dda(drawn, n, line, level(line[4]) << 16 | level(line[5]) << 8 | level(line[6]));
            }
        }
        BufferedImage page = ImageIO.read(picture.toFile());
        int differ = 0;
        for (int y = 0; y < n; y++) {
            for (int x = 0; x < n; x++) {
                differ += (page.getRGB(50 + x, 50 + y) & 0xFFFFFF) != drawn[y * n + x] ? 1 : 0;
            }
        }
        assertEquals(0, differ, "pixels of panel 1 (DDA) that the listing's lines, drawn here, do not make");
    }

    @Test
    void theNumbersReadBackAsSimpviewsOwnAndStandardOutputTakesThem() {
        CliRun run = CliRun.of("render", "--page", "3", "--seed", "11", "--primitives", "-");
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        assertTrue(run.out().contains("# one panel: Z-buffer\n"), run.out());
        List<double[]> rows = read(run.out());
        Vertex[][] triangles = ZBufferPage.triangles(11);
        assertEquals(triangles.length, rows.size());
        for (int t = 0; t < triangles.length; t++) {
            for (int k = 0; k < 3; k++) {
                Vertex v = triangles[t][k];
                double[] numbers = {v.x(), v.y(), v.z(), v.r(), v.g(), v.b()};
                for (int i = 0; i < 6; i++) {
                    assertEquals(Double.doubleToLongBits(numbers[i]), Double.doubleToLongBits(rows.get(t)[1 + 6 * k + i]),
                            "triangle " + (t + 1) + " vertex " + (k + 1) + " number " + (i + 1));
                }
            }
        }
    }

    @Test
    void pagesWithoutPrimitivesOfTheirOwnAndOtherCommandsAreUsageErrors() {
        CliRun scene = CliRun.of("render", "--page", "4", "--primitives", dir.resolve("x.txt").toString());
        assertEquals(ExitCode.USAGE_ERROR, scene.exitCode());
        assertTrue(scene.err().contains("--primitives: page 4 draws a scene file ("), scene.err());
        assertFalse(Files.exists(dir.resolve("x.txt")));
        CliRun all = CliRun.of("render", "--all", "--out-dir", dir.toString(), "--primitives", "-");
        assertEquals(ExitCode.USAGE_ERROR, all.exitCode());
        assertTrue(all.err().contains("--primitives goes with --page N"), all.err());
        CliRun scenes = CliRun.of("render", "--scenes", dir.toString(), "--out-dir", dir.toString(), "--primitives", "-");
        assertEquals(ExitCode.USAGE_ERROR, scenes.exitCode());
        assertTrue(scenes.err().contains("--primitives goes with --page N"), scenes.err());
        CliRun none = CliRun.of("render", "--page", "2");
        assertEquals(ExitCode.USAGE_ERROR, none.exitCode(), "neither --out nor --primitives");
        CliRun same = CliRun.of("render", "--page", "2", "--out", dir.resolve("p.png").toString(), "--primitives",
                dir.resolve("p.png").toString());
        assertEquals(ExitCode.USAGE_ERROR, same.exitCode(), "one file named twice: " + same.err());
    }
}

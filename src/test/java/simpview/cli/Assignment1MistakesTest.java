package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.geometry.Vertex;
import simpview.pages.A1Layout;
import simpview.pages.A1Lines;
import simpview.pages.A1Polygons;
import simpview.pages.A1Rule;
import simpview.pages.LineTestPage;
import simpview.pages.PageContext;
import simpview.raster.LineRenderer;
import simpview.surface.Colors;
import simpview.surface.Drawable;
import simpview.surface.PageCanvas;

/**
 * Three common mistakes of the first assignment, each drawn into simpview's own page by a small renderer of this
 * test's, and named by compare and check from the picture: line ends floored, a line drawer wrong in some octants,
 * a fill without the top-left rule.
 */
class Assignment1MistakesTest {

    @TempDir
    Path dir;

    /**
     * Page 1 drawn by simpview's four drawers with each line's ends floored (SPEC rounds them): every panel is told
     * so, and check says it once for the four panels. Only the starburst's ends have fractions; 150 + 135 cos 4
     * degrees is 284.671, which rounds to 285 and floors to 284.
     */
    @Test
    void flooredLineEndsAreNamed() throws Exception {
        A1Lines lines = A1Lines.starburst();
        double[] floored = lines.numbers().clone();
        for (int i = 0; i < lines.count(); i++) {
            for (int at : new int[] {A1Lines.from(i), A1Lines.to(i)}) {
                floored[at] = Math.floor(floored[at]);
                floored[at + 1] = Math.floor(floored[at + 1]);
            }
        }
        PageCanvas canvas = new PageCanvas();
        Drawable[] panels = A1Layout.paint(canvas);
        for (int k = 1; k <= A1Layout.PANELS; k++) {
            LineRenderer drawer = LineTestPage.drawer(k, A1Rule.SPEC); // one a panel: the alternating one alternates
            for (int i = 0; i < lines.count(); i++) {
                drawer.drawLine(floored, A1Lines.from(i), A1Lines.to(i), panels[k - 1]);
            }
        }
        Path subs = Files.createDirectories(dir.resolve("floored"));
        Path page = subs.resolve("a1-page1.png");
        ImageIO.write(canvas.image(), "png", page.toFile());
        CliRun run = CliRun.of("compare", page.toString(), "--assignment", "1", "--page", "1");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        // said once for the four panels, each of which it explains
        assertEquals(1, run.out().lines().filter(l -> l.startsWith("hint: ")).count(), run.out());
        assertTrue(run.out().contains("hint: panels 1-4: your lines' ends look floored, not rounded: simpview's lines "
                + "drawn with each end floored, floor(v), differ from yours at 0 pixels, as SPEC draws them (rounded) at "),
                run.out());
        assertTrue(run.out().contains("(line 2's end (284.671, 159.417): rounded (285, 159), floored (284, 159))"),
                run.out());
        assertFalse(run.out().contains("stop a pixel short"), run.out());
        // check says it once for the four panels too, in the same words
        CliRun check = CliRun.of("check", subs.toString(), "--assignment", "1", "--pages", "1");
        assertEquals(1, check.out().lines().filter(l -> l.startsWith("hint: ")).count(), check.out());
        String alone = run.out().lines().filter(l -> l.startsWith("hint: ")).findFirst().orElseThrow();
        String checked = check.out().lines().filter(l -> l.startsWith("hint: ")).findFirst().orElseThrow();
        assertEquals(checked.substring(checked.indexOf("): ") + 3), alone.substring("hint: panels 1-4: ".length()),
                "the hint alone as check says it");
        assertTrue(check.out().contains("hint: a1-page1.png (A1 page 1 panels 1-4): your lines' ends look floored, not "
                + "rounded: simpview's lines drawn with each end floored, floor(v), differ from yours at 0 pixels, as "
                + "SPEC draws them (rounded) at "), check.out());
        assertTrue(check.out().contains("then draws between the two. The numbers are panel 1's; panels 2-4 look the "
                + "same.\n"), check.out());
        assertTrue(check.err().contains("; panels 1-4 look to floor its lines' ends where SPEC rounds them\n"),
                check.err());
    }

    /**
     * Page 1 with its Bresenham panel drawn right for shallow lines (simpview's own) and wrong for steep ones: a
     * steep line stepped along x as a shallow one is, one pixel a column, leaving gaps. The 44 steep lines of the
     * starburst (48 to 132 and 228 to 312 degrees) differ, the 46 others match.
     */
    @Test
    void aLineDrawerWrongInSomeOctantsIsNamed() throws Exception {
        for (int p = 2; p <= 3; p++) { // simpview's own pages of lines: no hint (page 1: the antialiasing test's)
            Path own = dir.resolve("a1-page" + p + ".png");
            assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", String.valueOf(p), "--out",
                    own.toString()).exitCode());
            CliRun right = CliRun.of("compare", own.toString(), "--assignment", "1", "--page", String.valueOf(p));
            assertEquals(ExitCode.OK, right.exitCode(), right.out());
            assertFalse(right.out().contains("hint:"), right.out());
        }
        A1Lines lines = A1Lines.starburst();
        PageCanvas canvas = new PageCanvas();
        Drawable[] panels = A1Layout.paint(canvas);
        for (int k = 1; k <= A1Layout.PANELS; k++) {
            if (k != 2) {
                LineTestPage.drawPanel(k, A1Rule.SPEC, lines, panels[k - 1], null);
            }
        }
        for (int i = 0; i < lines.count(); i++) {
            long ax = Math.round(Math.floor(lines.start(i).x() + 0.5));
            long ay = Math.round(Math.floor(lines.start(i).y() + 0.5));
            long bx = Math.round(Math.floor(lines.end(i).x() + 0.5));
            long by = Math.round(Math.floor(lines.end(i).y() + 0.5));
            if (Math.abs(by - ay) <= Math.abs(bx - ax)) {
                LineTestPage.drawer(2, A1Rule.SPEC).drawLine(lines.numbers(), A1Lines.from(i), A1Lines.to(i),
                        panels[1]);
                continue;
            }
            for (long x = Math.min(ax, bx); x <= Math.max(ax, bx); x++) { // steep, stepped along x: gaps
                double y = ax == bx ? ay : ay + (double) (by - ay) * (x - ax) / (bx - ax);
                panels[1].setPixel((int) x, (int) Math.floor(y + 0.5), 0, 0xFFFFFFFF);
            }
        }
        Path subs = Files.createDirectories(dir.resolve("octants"));
        Path page = subs.resolve("a1-page1.png");
        ImageIO.write(canvas.image(), "png", page.toFile());
        CliRun run = CliRun.of("compare", page.toString(), "--assignment", "1", "--page", "1");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        String hint = "your lines differ in some directions only: 40 of the 44 lines of octants 2, 3, 6 and 7 (steep "
                + "lines, |dy| > |dx|) differ from simpview's (line 14, (150, 150) to (233, 256)); the 46 lines of "
                + "octants 1, 4, 5 and 8 (shallow lines, |dy| <= |dx|) match (0 pixels of the 2,991 pixels that differ "
                + "lie by them only).";
        assertTrue(run.out().contains("hint: panel 2: " + hint), run.out());
        assertEquals(1, run.out().lines().filter(l -> l.startsWith("hint: ")).count(), run.out());
        CliRun check = CliRun.of("check", subs.toString(), "--assignment", "1", "--pages", "1");
        assertTrue(check.out().contains("hint: a1-page1.png (A1 page 1 panel 2 (Bresenham)): " + hint), check.out());
        assertTrue(check.err().contains("; panel 2 looks to draw the lines of octants 2, 3, 6 and 7 (steep lines, "
                + "|dy| > |dx|) otherwise than simpview, the others alike"), check.err());
    }

    /**
     * Page 4 with its mesh panel filled by "inside or on any edge" (a centre on an edge shared by two triangles
     * drawn by both, the later one's colour showing) and its perturbed mesh by "strictly inside" (drawn by
     * neither: black). The vertices are whole numbers, so a centre (x + 1/2, y + 1/2) lies on an edge exactly when
     * twice the edge's cross product is 0, in integers.
     */
    @Test
    void aFillWithoutTheTopLeftRuleIsNamed() throws Exception {
        Path subs = Files.createDirectories(dir.resolve("fill"));
        for (int p = 5; p >= 4; p--) { // simpview's own pages of polygons: no hint; page 4 is then changed
            Path own = subs.resolve("a1-page" + p + ".png");
            assertEquals(ExitCode.OK, CliRun.of("render", "--assignment", "1", "--page", String.valueOf(p), "--out",
                    own.toString()).exitCode());
            CliRun right = CliRun.of("compare", own.toString(), "--assignment", "1", "--page", String.valueOf(p));
            assertEquals(ExitCode.OK, right.exitCode(), right.out());
            assertFalse(right.out().contains("hint:"), right.out());
        }
        Files.delete(subs.resolve("a1-page5.png"));
        Path page = subs.resolve("a1-page4.png");
        BufferedImage mine = ImageIO.read(page.toFile());
        A1Polygons scenes = new A1Polygons(PageContext.DEFAULT_SEED, A1Rule.SPEC);
        for (int k = 2; k <= 3; k++) {
            double[] scene = scenes.scene(k);
            for (int t = 0; t < scenes.count(k); t++) {
                Vertex[] v = new Vertex[3];
                for (int j = 0; j < 3; j++) {
                    v[j] = Vertex.readFrom(scene, A1Polygons.at(t) + j * Vertex.NUMBERS);
                }
                int colour = k == 2 ? Colors.toByte(v[0].r()) << 16 | Colors.toByte(v[0].g()) << 8
                        | Colors.toByte(v[0].b()) : 0;
                // the triangle's box only: its vertices are whole numbers inside the panel
                int x0 = (int) Math.min(v[0].x(), Math.min(v[1].x(), v[2].x()));
                int x1 = (int) Math.max(v[0].x(), Math.max(v[1].x(), v[2].x()));
                int y0 = (int) Math.min(v[0].y(), Math.min(v[1].y(), v[2].y()));
                int y1 = (int) Math.max(v[0].y(), Math.max(v[1].y(), v[2].y()));
                for (int y = y0; y <= y1; y++) {
                    for (int x = x0; x <= x1; x++) {
                        if (onEdge(v, 2 * x + 1, 2 * y + 1)) {
                            mine.setRGB(A1Layout.left(k) + x, A1Layout.top(k) + A1Layout.PANEL - 1 - y, colour);
                        }
                    }
                }
            }
        }
        ImageIO.write(mine, "png", page.toFile());
        CliRun run = CliRun.of("compare", page.toString(), "--assignment", "1", "--page", "4");
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out());
        // the mesh's 81 diagonals hold 30 centres each: 2,430, each on two triangles' shared edge
        assertTrue(run.out().contains("hint: panel 2: your fill does not keep the top-left rule: 2,430 of the 2,430 "
                + "pixels that differ have their centres exactly on an edge of simpview's triangles (the panel has "
                + "2,430 such pixels), 2,430 of them on an edge two triangles share; yours draws all of them twice, by "
                + "both triangles there ("), run.out());
        assertTrue(run.out().contains("hint: panel 3: your fill does not keep the top-left rule: "), run.out());
        assertTrue(run.out().contains("; yours leaves all of them out: a gap, drawn by neither triangle ("), run.out());
        // two mistakes: each panel's hint of its own
        CliRun check = CliRun.of("check", subs.toString(), "--assignment", "1", "--pages", "4");
        assertTrue(check.out().contains("hint: a1-page4.png (A1 page 4 (seed 361) panel 2): your fill does not keep "),
                check.out());
        assertTrue(check.out().contains("hint: a1-page4.png (A1 page 4 (seed 361) panel 3): your fill does not keep "),
                check.out());
        assertTrue(check.err().contains("; panel 2 looks to fill without the top-left rule: pixels whose centres lie on "
                + "an edge drawn twice; panel 3 looks to fill without the top-left rule: pixels whose centres lie on an "
                + "edge left out"), check.err());
    }

    /**
     * Whether the point (cx / 2, cy / 2) lies in the closed triangle v and on one of its edges: doubled, so that
     * whole-number vertices and pixel centres give exact integers.
     */
    private static boolean onEdge(Vertex[] v, long cx, long cy) {
        long[] side = new long[3];
        for (int e = 0; e < 3; e++) {
            Vertex a = v[e];
            Vertex b = v[(e + 1) % 3];
            long ax = 2 * Math.round(a.x());
            long ay = 2 * Math.round(a.y());
            long bx = 2 * Math.round(b.x());
            long by = 2 * Math.round(b.y());
            side[e] = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
        }
        boolean inside = side[0] >= 0 && side[1] >= 0 && side[2] >= 0 || side[0] <= 0 && side[1] <= 0 && side[2] <= 0;
        return inside && (side[0] == 0 || side[1] == 0 || side[2] == 0)
                && !(side[0] == 0 && side[1] == 0 && side[2] == 0);
    }
}

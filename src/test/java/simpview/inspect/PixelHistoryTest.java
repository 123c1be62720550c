package simpview.inspect;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.reference.RandomLitScenes;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.stage.PrimitiveLog;
import simpview.stage.PrimitiveTrace;
import simpview.surface.PageCanvas;
import simpview.surface.Provenance;
import simpview.surface.Rgb;
import simpview.testing.CourseFiles;

/**
 * The pixel history against the picture as the program draws it (the
 * renderer the pages and the window use, with the window's own record of who
 * drew each pixel): for sampled pixels of random scenes of every kind, the
 * last written entry is the pixel's owner and carries its colour and depth,
 * the explanation's final bytes are the pixel's bytes, and the entries are
 * ordered and consistent (a depth failure names the depth stored then).
 */
class PixelHistoryTest {

    @TempDir
    Path dir;

    private static final SceneLibrary LIBRARY = new SceneLibrary();
    private final PixelInspector inspector = new PixelInspector(LIBRARY, SceneMonitor.NONE);

    @Test
    void litScenesOfEveryKind() throws Exception {
        int written = 0;
        for (long seed = 1; seed <= 12; seed++) {
            Path scene = RandomLitScenes.write(dir, seed);
            written += check(InspectedScene.of(scene), 24, seed);
        }
        assertTrue(written > 100, "too few drawn pixels sampled: " + written);
    }

    @Test
    void depthCuedScenes() throws Exception {
        int written = 0;
        for (long seed = 1; seed <= 8; seed++) {
            Path scene = RandomCuedScenes.write(dir, seed);
            written += check(InspectedScene.cued(scene, new Rgb(0.2, 1, 0.6), new Rgb(0.1, 0, 0.3)), 24, seed);
        }
        assertTrue(written > 100, "too few drawn pixels sampled: " + written);
    }

    @Test
    void ownColours() throws Exception {
        for (long seed = 30; seed <= 31; seed++) {
            Path scene = RandomCuedScenes.write(dir, seed);
            check(InspectedScene.ownColours(scene), 30, seed);
        }
    }

    /** The course's own pages: a depth-cued one three files deep, obj models, every shading mode. */
    @Test
    void coursePages() throws Exception {
        Path simp = CourseFiles.requireSimpDir();
        Path a3 = CourseFiles.require("course-simp-a3");
        Path a4 = CourseFiles.require("course-simp-a4");
        check(InspectedScene.of(simp.resolve("page7.simp")), 10, 7);
        check(InspectedScene.of(a3.resolve("pageI.simp")), 8, 9);
        check(InspectedScene.of(a3.resolve("pageH.simp")), 6, 8);
        for (String page : new String[] {"page-d", "page-a1", "page-a2", "page-b1", "page-c2", "page-g"}) {
            check(InspectedScene.of(a4.resolve(page + ".simp")), 6, page.hashCode());
        }
    }

    /**
     * A triangle the picture skips whole, as hidden behind what is drawn
     * (LitPolygonRasterizer asks the fragment stage before it gives a span),
     * is still in the history, whose replay asks nothing: its fragment at the
     * pixel fails the depth test there, naming the depth before it.
     */
    @Test
    void aTriangleHiddenWholeIsInTheHistory() throws Exception {
        Path scene = dir.resolve("hidden.simp");
        Files.writeString(scene, String.join("\n",
                "camera -1 -1 1 1 -0.1 -200",
                "ambient 0.5 0.5 0.5",
                "phong",
                "polygon (-4, -4, -10) (4, -4, -10) (0, 4, -10)",
                "polygon (-1, -1, -20) (1, -1, -20) (0, 1, -20)",
                ""));
        int centre = PageCanvas.PANEL / 2;
        PixelReport report = inspector.inspect(InspectedScene.of(scene), centre, centre);
        List<HistoryEntry> history = report.history();
        assertEquals(2, history.size(), report.text(true, false));
        assertEquals(Outcome.WRITTEN, history.get(0).outcome());
        assertEquals(Outcome.DEPTH_FAILED, history.get(1).outcome());
        assertEquals(history.get(0).z(), history.get(1).storedDepth(), 0);
        assertEquals(history.get(0).primitive(), report.lastWritten().primitive());
    }

    /** Checks sampled pixels, half of them drawn ones; returns how many drawn pixels were checked. */
    private int check(InspectedScene scene, int samples, long seed) throws SceneException {
        Drawn drawn = draw(scene);
        Random random = new Random(seed);
        List<int[]> pixels = new ArrayList<>();
        List<int[]> owned = new ArrayList<>();
        for (int y = 0; y < PageCanvas.PANEL; y += 3) {
            for (int x = 0; x < PageCanvas.PANEL; x += 3) {
                if (drawn.owners[y * PageCanvas.PANEL + x] != Provenance.BACKGROUND) {
                    owned.add(new int[] {x, y});
                }
            }
        }
        for (int k = 0; k < samples; k++) {
            if (k % 2 == 0 && !owned.isEmpty()) {
                pixels.add(owned.get(random.nextInt(owned.size())));
            } else {
                pixels.add(new int[] {random.nextInt(PageCanvas.PANEL), random.nextInt(PageCanvas.PANEL)});
            }
        }
        int checked = 0;
        for (int[] p : pixels) {
            int x = p[0];
            int y = p[1];
            String where = scene.file().getFileName() + " pixel (" + x + ", " + y + ")";
            PixelReport report = inspector.inspect(scene, x, y);
            int i = y * PageCanvas.PANEL + x;
            assertEquals(drawn.pixels[i], report.argb(), where + ": the replay's picture differs from the drawing");
            assertEquals(drawn.depths[i], report.depth(), 0, where + ": depth");
            HistoryEntry owner = report.lastWritten();
            if (drawn.owners[i] == Provenance.BACKGROUND) {
                assertNull(owner, where + ": the background has no owner, the history says " + describe(report, owner));
                continue;
            }
            checked++;
            assertNotNull(owner, where + ": drawn by primitive " + drawn.owners[i] + " but nothing written in the history");
            assertEquals(drawn.owners[i], owner.primitive(), where + ": owner");
            assertEquals(drawn.pixels[i], owner.argb(), where + ": the last written colour is not the pixel's");
            assertEquals(Double.doubleToLongBits(drawn.depths[i]), Double.doubleToLongBits(owner.z()),
                    where + ": the last written depth is not the pixel's");
            int c = drawn.pixels[i];
            assertArrayEquals(new int[] {c >>> 16 & 0xFF, c >>> 8 & 0xFF, c & 0xFF},
                    report.explanation().bytes("final_rgb"), where + ": the explanation's final bytes");
            assertEquals(drawn.lit, report.lit(), where + ": lit");
            consistent(report, where);
        }
        return checked;
    }

    /** Written entries come in drawing order, each depth failure names the depth stored before it. */
    private static void consistent(PixelReport report, String where) {
        double stored = report.lit() ? Double.NEGATIVE_INFINITY : -200;
        int lastPrimitive = -1;
        for (HistoryEntry e : report.history()) {
            if (e.primitive() != HistoryEntry.NO_NUMBER) {
                assertTrue(e.primitive() >= lastPrimitive, where + ": out of drawing order");
                lastPrimitive = e.primitive();
            }
            if (e.outcome() == Outcome.WRITTEN) {
                assertTrue(e.z() > stored, where + ": written but not nearer than " + stored);
                stored = e.z();
            } else if (e.outcome() == Outcome.DEPTH_FAILED) {
                assertEquals(stored, e.storedDepth(), 0, where + ": stored depth of a failed write");
                assertTrue(!(e.z() > stored), where + ": failed although nearer");
            }
        }
    }

    private static String describe(PixelReport report, HistoryEntry e) {
        return e == null ? "none" : "#" + e.primitive() + " " + report.describe(e);
    }

    /** The picture, depths and owners as the program draws the scene, with the window's record. */
    private record Drawn(int[] pixels, double[] depths, int[] owners, boolean lit) {
    }

    private static Drawn draw(InspectedScene scene) throws SceneException {
        PageCanvas canvas = new PageCanvas();
        Provenance provenance = new Provenance(PageCanvas.PANEL, PageCanvas.PANEL);
        canvas.recordProvenance(provenance);
        PrimitiveLog log = new PrimitiveLog(provenance, -1);
        SceneMonitor monitor = new SceneMonitor() {
            @Override
            public PrimitiveTrace trace() {
                return log;
            }
        };
        ScenePipeline.Drawn drawn = ScenePipeline.draw(scene.file(), canvas, ScenePipeline.Options.byCommands(LIBRARY)
                .withRules(scene.rules()).withCue(scene.near(), scene.far()).withOwnColours(scene.ownColours()), monitor);
        int n = PageCanvas.PANEL * PageCanvas.PANEL;
        int[] pixels = new int[n];
        for (int y = 0; y < PageCanvas.PANEL; y++) {
            for (int x = 0; x < PageCanvas.PANEL; x++) {
                pixels[y * PageCanvas.PANEL + x] = canvas.panel().getPixel(x, y);
            }
        }
        return new Drawn(pixels, canvas.zbuffer().copyDepths(), provenance.copyOwners(), drawn.lit());
    }
}

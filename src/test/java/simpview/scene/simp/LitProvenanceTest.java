package simpview.scene.simp;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import simpview.stage.PrimitiveLog;
import simpview.stage.PrimitiveTrace;
import simpview.scene.obj.ObjLibrary;
import simpview.shading.FragmentStage;
import simpview.surface.Drawable;
import simpview.surface.PageCanvas;
import simpview.surface.Provenance;
import simpview.surface.ProvenanceDrawable;
import simpview.surface.ZBuffer;
import simpview.testing.RecordingDrawable;

/**
 * The instruments on lit scenes, read and drawn for real: every pixel's
 * recorded primitive is the one whose write the fragment stage's depth test
 * kept last (checked against a recording of every write that reached the
 * panel), its logged place is its command's line or its .obj face's line,
 * and stepping to primitive k draws exactly the first k primitives' writes.
 */
class LitProvenanceTest {

    private static final int PANEL = PageCanvas.PANEL;

    @TempDir
    Path dir;

    /** One drawing: what reached the panel, and where each primitive's writes begin. */
    private record Drawing(List<RecordingDrawable.Write> writes, List<Integer> firstWrite) {
    }

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4, 5, 6})
    void everyPixelNamesThePrimitiveWhoseWriteItShows(long seed) throws Exception {
        List<String> places = new ArrayList<>();
        Path scene = randomScene(new Random(seed), places);

        Provenance provenance = new Provenance(PANEL, PANEL);
        PrimitiveLog log = new PrimitiveLog(provenance, -1);
        run(scene, new ProvenanceDrawable(provenance, new RecordingDrawable(PANEL, PANEL)), log);
        Drawing all = record(scene, -1);

        int[] expected = new int[PANEL * PANEL];
        Arrays.fill(expected, Provenance.BACKGROUND);
        for (int k = 0; k < all.firstWrite().size(); k++) {
            int end = k + 1 < all.firstWrite().size() ? all.firstWrite().get(k + 1) : all.writes().size();
            for (int w = all.firstWrite().get(k); w < end; w++) {
                RecordingDrawable.Write write = all.writes().get(w);
                expected[write.y() * PANEL + write.x()] = k;
            }
        }
        assertEquals(all.firstWrite().size(), log.size(), "every rasterized primitive logged");
        int owned = 0;
        for (int y = 0; y < PANEL; y++) {
            for (int x = 0; x < PANEL; x++) {
                int owner = provenance.ownerAt(x, y);
                assertEquals(expected[y * PANEL + x], owner, "pixel (" + x + ", " + y + ")");
                owned += owner >= 0 ? 1 : 0;
            }
        }
        assertTrue(owned > 1000, "something drawn: " + owned);
        // Logged places, in drawing order: the scene's lines and polygons a subsequence of their places,
        // the model's faces at their f lines.
        int at = 0;
        for (int k = 0; k < log.size(); k++) {
            String place = log.file(k).getFileName() + ":" + log.line(k);
            if (place.startsWith("model.obj:")) {
                assertTrue(places.contains(place), "face " + place);
                continue;
            }
            while (at < places.size() && !places.get(at).equals(place)) {
                at++;
            }
            assertTrue(at < places.size(), "primitive " + k + " at " + place + " in drawing order");
            at++;
        }
    }

    @ParameterizedTest
    @ValueSource(longs = {11, 12})
    void steppingToPrimitiveKDrawsTheFirstKPrimitivesWrites(long seed) throws Exception {
        Path scene = randomScene(new Random(seed), new ArrayList<>());
        Drawing all = record(scene, -1);
        int total = all.firstWrite().size();
        assertTrue(total > 10, total + " primitives");
        for (int k : new int[] {1, total / 3, total - 1}) {
            Drawing part = record(scene, k);
            int end = all.firstWrite().get(k);
            assertEquals(end, part.writes().size(), "how many writes the first " + k + " make");
            assertTrue(all.writes().subList(0, end).equals(part.writes()), "the writes of the first " + k);
        }
    }

    @Test
    void theShownCentreIsTheMiddleOfWhatTheViewShows() throws Exception {
        Path scene = Files.writeString(dir.resolve("one.simp"), String.join("\n",
                "camera -1 -1 1 1 -1 -100",
                "polygon (-2, -1, -10) (3, -1, -10) (0, 2, -20)", ""));
        SimpClient client = SimpClient.lit(new FragmentStage(new ZBuffer(PANEL, PANEL), new RecordingDrawable(PANEL, PANEL)),
                new ObjLibrary(), new PrimitiveLog(null, -1));
        new SimpInterpreter(client, SceneMonitor.NONE).run(scene);
        double[] centre = client.shownCentre();
        assertNotNull(centre);
        assertArrayEquals(new double[] {0.5, 0.5, -15}, centre, 1e-12);
    }

    /** Draws the scene onto a recording panel, stopped after {@code limit} primitives (-1: all). */
    private Drawing record(Path scene, int limit) throws Exception {
        RecordingDrawable writes = new RecordingDrawable(PANEL, PANEL);
        List<Integer> firstWrite = new ArrayList<>();
        PrimitiveLog stop = new PrimitiveLog(null, limit);
        PrimitiveTrace boundaries = new PrimitiveTrace() {
            @Override
            public void read(int index, Path file, int line, int kind, double[] p, int at, int stride, int vertices) {
            }

            @Override
            public boolean drawing(int index) {
                if (!stop.drawing(index)) {
                    return false;
                }
                firstWrite.add(writes.writes().size());
                return true;
            }
        };
        run(scene, writes, boundaries);
        return new Drawing(writes.writes(), firstWrite);
    }

    private static void run(Path scene, Drawable panel, PrimitiveTrace trace) throws Exception {
        ZBuffer zbuffer = new ZBuffer(PANEL, PANEL);
        zbuffer.reset(Double.NEGATIVE_INFINITY);
        SimpClient client = SimpClient.lit(new FragmentStage(zbuffer, panel), new ObjLibrary(), trace);
        new SimpInterpreter(client, SceneMonitor.NONE).run(scene);
    }

    /**
     * A camera, lights, every shading mode and style, polygons and lines at
     * random (some outside the view, some through the near plane), and a
     * model of random faces drawn twice.
     */
    private Path randomScene(Random random, List<String> places) throws IOException {
        List<String> model = new ArrayList<>();
        for (int v = 0; v < 12; v++) {
            model.add(String.format(Locale.ROOT, "v %.3f %.3f %.3f", 6 * random.nextGaussian(), 6 * random.nextGaussian(),
                    6 * random.nextGaussian()));
        }
        for (int f = 0; f < 10; f++) {
            model.add("f " + (1 + random.nextInt(12)) + " " + (1 + random.nextInt(12)) + " " + (1 + random.nextInt(12)));
            places.add("model.obj:" + model.size());
        }
        Files.write(dir.resolve("model.obj"), model);
        String name = "lit" + random.nextInt(1000) + ".simp";
        List<String> lines = new ArrayList<>();
        lines.add("ambient 0.2 0.2 0.2");
        lines.add("light 1 1 1 1 0");
        lines.add("camera -1 -1 1 1 -1 -300");
        for (int i = 0; i < 90; i++) {
            int what = random.nextInt(12);
            String line;
            if (what == 0) {
                line = String.format(Locale.ROOT, "rotate %s %.1f", "XYZ".charAt(random.nextInt(3)), 360 * random.nextDouble());
            } else if (what == 1) {
                line = random.nextBoolean() ? "wire" : "filled";
            } else if (what == 2) {
                line = List.of("flat", "gouraud", "phong").get(random.nextInt(3));
            } else if (what == 3) {
                line = String.format(Locale.ROOT, "surface %.2f %.2f %.2f 0.5 10", random.nextDouble(), random.nextDouble(),
                        random.nextDouble());
            } else if (what == 4 && i % 3 == 0) {
                lines.add("{");
                lines.add(String.format(Locale.ROOT, "translate %.1f %.1f %.1f", 30 * random.nextGaussian(),
                        30 * random.nextGaussian(), -60 - 60 * random.nextDouble()));
                lines.add("obj \"model\"");
                line = "}";
            } else {
                line = (random.nextInt(4) == 0 ? "line " + point(random) : "polygon " + point(random) + " " + point(random))
                        + " " + point(random);
                places.add(name + ":" + (lines.size() + 1));
            }
            lines.add(line);
        }
        return Files.write(dir.resolve(name), lines);
    }

    private static String point(Random random) {
        return String.format(Locale.ROOT, "(%.3f, %.3f, %.3f)", -120 + 240 * random.nextDouble(),
                -120 + 240 * random.nextDouble(), -250 * random.nextDouble() + 20);
    }
}

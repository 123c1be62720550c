package simpview.scene.simp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import simpview.geometry.Camera;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import simpview.stage.PrimitiveLog;
import simpview.stage.PrimitiveTrace;
import simpview.surface.Drawable;
import simpview.surface.PageCanvas;
import simpview.surface.Provenance;
import simpview.surface.ProvenanceDrawable;
import simpview.surface.ScissorDrawable;
import simpview.surface.ZBuffer;
import simpview.surface.ZBufferDrawable;
import simpview.testing.RecordingDrawable;

/**
 * Who drew each pixel, on random scenes read and drawn for real: each pixel's
 * recorded primitive is the one whose write the z-buffer kept (checked
 * against a recording of every write that passed the z-buffer), and its
 * logged line is the line of that primitive's command. Read on one thread
 * and, for the read-ahead of large scenes, on two.
 */
class ProvenanceSceneTest {

    @TempDir
    Path dir;

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void everyPixelNamesTheCommandWhoseWriteTheZBufferKept(long seed) throws Exception {
        List<Integer> primitiveLines = new ArrayList<>();
        Path scene = randomScene(new Random(seed), primitiveLines);
        for (long readAheadFrom : new long[] {Long.MAX_VALUE, 0}) {
            check(scene, readAheadFrom, primitiveLines);
        }
    }

    private void check(Path scene, long readAheadFrom, List<Integer> primitiveLines) throws Exception {
        int panel = PageCanvas.PANEL;
        Provenance provenance = new Provenance(panel, panel);
        PrimitiveLog log = new PrimitiveLog(provenance, -1);
        Drawable recorded = new ScissorDrawable(Camera.PARALLEL, new ZBufferDrawable(new ZBuffer(panel, panel),
                new ProvenanceDrawable(provenance, new RecordingDrawable(panel, panel))));
        run(scene, recorded, log, readAheadFrom);

        RecordingDrawable writes = new RecordingDrawable(panel, panel);
        List<Integer> firstWrite = new ArrayList<>();
        PrimitiveTrace boundaries = new PrimitiveTrace() {
            @Override
            public void read(int index, Path file, int line, int kind, double[] p, int at, int stride, int vertices) {
            }

            @Override
            public boolean drawing(int index) {
                firstWrite.add(writes.writes().size());
                return true;
            }
        };
        run(scene, new ScissorDrawable(Camera.PARALLEL, new ZBufferDrawable(new ZBuffer(panel, panel), writes)), boundaries, readAheadFrom);

        int[] expected = new int[panel * panel];
        Arrays.fill(expected, Provenance.BACKGROUND);
        for (int k = 0; k < firstWrite.size(); k++) {
            int end = k + 1 < firstWrite.size() ? firstWrite.get(k + 1) : writes.writes().size();
            for (int w = firstWrite.get(k); w < end; w++) {
                RecordingDrawable.Write write = writes.writes().get(w);
                expected[write.y() * panel + write.x()] = k;
            }
        }
        assertEquals(firstWrite.size(), log.size(), "every drawn primitive logged");
        int owned = 0;
        for (int y = 0; y < panel; y++) {
            for (int x = 0; x < panel; x++) {
                int owner = provenance.ownerAt(x, y);
                assertEquals(expected[y * panel + x], owner, "pixel (" + x + ", " + y + ")");
                if (owner >= 0) {
                    owned++;
                    assertTrue(primitiveLines.contains(log.line(owner)), "logged line " + log.line(owner));
                }
            }
        }
        assertTrue(owned > 0, "something drawn");
        for (int k = 0; k < log.size(); k++) {
            assertEquals(scene, log.file(k));
        }
        // Culled primitives are not numbered: the logged lines are a subsequence of the commands' lines.
        int at = 0;
        for (int k = 0; k < log.size(); k++) {
            while (at < primitiveLines.size() && primitiveLines.get(at) != log.line(k)) {
                at++;
            }
            assertTrue(at < primitiveLines.size(), "primitive " + k + "'s line in drawing order");
            at++;
        }
    }

    private static void run(Path scene, Drawable target, PrimitiveTrace trace, long readAheadFrom) throws Exception {
        SimpClient client = SimpClient.depthCued(target, trace);
        new SimpInterpreter(client, SceneMonitor.NONE, readAheadFrom).run(scene);
    }

    /** Transforms, styles and primitives at random, some of them outside the view (culled). */
    private Path randomScene(Random random, List<Integer> primitiveLines) throws IOException {
        List<String> lines = new ArrayList<>();
        int braces = 0;
        for (int i = 0; i < 120; i++) {
            int what = random.nextInt(10);
            String line;
            if (what == 0) {
                line = "{";
                braces++;
            } else if (what == 1 && braces > 0) {
                line = "}";
                braces--;
            } else if (what == 2) {
                line = String.format(Locale.ROOT, "rotate %s %.1f", "XYZ".charAt(random.nextInt(3)), 360 * random.nextDouble());
            } else if (what == 3) {
                line = String.format(Locale.ROOT, "translate %.2f %.2f %.2f", 40 * random.nextGaussian(),
                        40 * random.nextGaussian(), -20 * random.nextDouble());
            } else if (what == 4) {
                line = random.nextBoolean() ? "wire" : "filled";
            } else {
                line = (random.nextInt(4) == 0 ? "line " + point(random) : "polygon " + point(random) + " " + point(random))
                        + " " + point(random);
                primitiveLines.add(lines.size() + 1);
            }
            lines.add(line);
        }
        return Files.write(dir.resolve("random" + random.nextInt(1000) + ".simp"), lines);
    }

    private static String point(Random random) {
        return String.format(Locale.ROOT, "(%.3f, %.3f, %.3f)", -120 + 240 * random.nextDouble(),
                -120 + 240 * random.nextDouble(), -230 + 260 * random.nextDouble());
    }
}

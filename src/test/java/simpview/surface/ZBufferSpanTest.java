package simpview.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import simpview.testing.RecordingDrawable;

/**
 * {@link ZBufferDrawable}'s span path (runs of winners, each passed on as one
 * span) writes exactly the pixels, in the same order, with the same depth
 * bits and colours, as a plain depth test of every pixel written here
 * (sharing no code with it): over layers laid front to back over whole rows,
 * back to front, at equal depths, with NaN and infinite depths and slopes,
 * spans reaching past both sides, short and long. A shortcut in the span
 * path (skipping pixels known to be hidden, as the segment floors tried for
 * issue 22 did) is held to this.
 */
class ZBufferSpanTest {

    private static final int WIDTH = 101;
    private static final int HEIGHT = 12;
    private static final double FAR = -200;

    /** The plain depth test: every pixel's depth {@code z + (x - xBase) * dz} against the stored one. */
    private static final class PlainDepthTest {
        final double[] depth = new double[WIDTH * HEIGHT];
        final List<RecordingDrawable.Write> writes = new ArrayList<>();

        PlainDepthTest() {
            Arrays.fill(depth, FAR);
        }

        void fill(Span s) {
            if (s.y < 0 || s.y >= HEIGHT) {
                return;
            }
            for (int x = Math.max(s.x0, 0); x < Math.min(s.x1, WIDTH); x++) {
                double z = s.z + (x - s.xBase) * s.dz;
                int i = s.y * WIDTH + x;
                if (z > depth[i]) {
                    depth[i] = z;
                    writes.add(new RecordingDrawable.Write(x, s.y, z, s.argbAt(x)));
                }
            }
        }
    }

    @Test
    void frontToBackLayersOverWholeRowsAreHiddenExactly() {
        List<Span> spans = new ArrayList<>();
        for (int layer = 0; layer < 6; layer++) {
            for (int y = 0; y < HEIGHT; y++) {
                // Each layer farther than the last in the middle, nearer at one end: some pixels still win.
                spans.add(span(y, -3, WIDTH + 4, 0, -20 - 30 * layer, layer % 2 == 0 ? 0.05 : -0.05, 40 * layer));
            }
        }
        check(spans);
    }

    @Test
    void randomSpansAtAnyDepthWriteWhatThePlainTestWrites() {
        Random random = new Random(22);
        List<Span> spans = new ArrayList<>();
        for (int n = 0; n < 4000; n++) {
            int y = random.nextInt(HEIGHT + 2) - 1;
            int length = random.nextInt(4) == 0 ? 1 + random.nextInt(23) : 24 + random.nextInt(90);
            int x0 = random.nextInt(WIDTH + 20) - 15;
            int xBase = x0 + random.nextInt(9) - 4;
            double z = -200 + 200 * random.nextDouble();
            double dz = random.nextInt(5) == 0 ? 0 : (random.nextDouble() - 0.5) * 4;
            switch (random.nextInt(60)) {
                case 0 -> z = Double.NaN;
                case 1 -> dz = Double.NaN;
                case 2 -> dz = Double.POSITIVE_INFINITY;
                case 3 -> dz = Double.NEGATIVE_INFINITY;
                case 4 -> z = Double.POSITIVE_INFINITY;
                case 5 -> z = -0.0;
                case 6 -> z = Math.rint(z); // equal depths: the first write stays
                default -> {
                }
            }
            spans.add(span(y, x0, x0 + length, xBase, z, dz, random.nextInt(256)));
        }
        check(spans);
    }

    @Test
    void afterAResetAFartherSpanWinsAgain() {
        ZBuffer zbuffer = new ZBuffer(WIDTH, HEIGHT);
        RecordingDrawable under = new RecordingDrawable(WIDTH, HEIGHT);
        ZBufferDrawable tested = new ZBufferDrawable(zbuffer, under);
        tested.fillSpan(span(3, 0, WIDTH, 0, -10, 0, 200)); // near: row 3 at -10
        zbuffer.reset(FAR);
        tested.fillSpan(span(3, 0, WIDTH, 0, -150, 0, 100)); // far, but nearer than the reset depths
        assertEquals(2 * WIDTH, under.writes().size(), "after a reset every pixel of a farther span wins again");
        for (int x = 0; x < WIDTH; x++) {
            assertEquals(-150.0, zbuffer.depthAt(x, 3));
        }
    }

    private static void check(List<Span> spans) {
        ZBuffer zbuffer = new ZBuffer(WIDTH, HEIGHT);
        RecordingDrawable under = new RecordingDrawable(WIDTH, HEIGHT);
        ZBufferDrawable tested = new ZBufferDrawable(zbuffer, under);
        PlainDepthTest plain = new PlainDepthTest();
        for (Span s : spans) {
            plain.fill(copy(s));
            tested.fillSpan(s);
        }
        List<RecordingDrawable.Write> got = under.writes();
        assertEquals(plain.writes.size(), got.size(), "writes");
        for (int i = 0; i < got.size(); i++) {
            RecordingDrawable.Write want = plain.writes.get(i);
            RecordingDrawable.Write write = got.get(i);
            assertEquals(want.x(), write.x(), "write " + i + ": x");
            assertEquals(want.y(), write.y(), "write " + i + ": y");
            assertEquals(Double.doubleToRawLongBits(want.z()), Double.doubleToRawLongBits(write.z()),
                    "write " + i + ": depth bits");
            assertEquals(want.argb(), write.argb(), "write " + i + ": colour");
        }
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                assertEquals(Double.doubleToRawLongBits(plain.depth[y * WIDTH + x]),
                        Double.doubleToRawLongBits(zbuffer.depthAt(x, y)), "depth at " + x + ", " + y);
            }
        }
    }

    private static Span span(int y, int x0, int x1, int xBase, double z, double dz, int level) {
        Span s = new Span();
        s.y = y;
        s.x0 = x0;
        s.x1 = x1;
        s.xBase = xBase;
        s.z = z;
        s.dz = dz;
        s.r = level;
        s.g = level / 2.0;
        s.b = 255 - level;
        s.dr = 0.25;
        return s;
    }

    private static Span copy(Span s) {
        Span c = span(s.y, s.x0, s.x1, s.xBase, s.z, s.dz, 0);
        c.r = s.r;
        c.g = s.g;
        c.b = s.b;
        c.dr = s.dr;
        c.dg = s.dg;
        c.db = s.db;
        return c;
    }
}

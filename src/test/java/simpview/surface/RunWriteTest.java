package simpview.surface;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.util.List;
import java.util.Random;
import java.util.function.Function;
import java.util.function.Supplier;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import simpview.geometry.Camera;
import simpview.testing.RecordingDrawable;

/**
 * {@link Drawable#setRun} means what that many {@link Drawable#setPixel}
 * calls mean, through every drawable and decorator: the same picture, the
 * same depths kept, the same provenance, and the same writes reaching the end
 * of the chain, in the same order. Runs start and end anywhere, inside, across
 * and beyond the edges, on rows inside and outside.
 */
class RunWriteTest {

    private static final int SIZE = 40;
    private static final int IMAGE = SIZE + 20;

    /** A chain over an image, with what it keeps besides the picture. */
    private record Chain(Drawable top, BufferedImage image, Provenance provenance, ZBuffer zbuffer) {
    }

    private static final List<Supplier<Chain>> CHAINS = List.of(
            () -> image(d -> d, null, null),
            () -> panel(d -> d, null, null),
            () -> panel(d -> new ProvenanceDrawable(owners(), d), owners(), null),
            () -> panel(d -> new ZBufferDrawable(zbuffer(), new ProvenanceDrawable(owners(), d)), owners(), zbuffer()),
            () -> panel(d -> new ScissorDrawable(Camera.PARALLEL, new ZBufferDrawable(zbuffer(), d)), null, zbuffer()),
            () -> panel(d -> new DepthCueDrawable(new Rgb(1, 1, 1), new Rgb(0, 0, 0.5), Camera.PARALLEL, d), null, null),
            () -> panel(d -> new ProvenanceDrawable(owners(), new Halving(d)), owners(), null));

    // The one provenance record and z-buffer a chain being built shares (the chains are built one at a time).
    private static Provenance sharedOwners;
    private static ZBuffer sharedDepths;

    private static Provenance owners() {
        return sharedOwners;
    }

    private static ZBuffer zbuffer() {
        return sharedDepths;
    }

    private static Chain image(Function<Drawable, Drawable> wrap, Provenance p, ZBuffer z) {
        BufferedImage image = new BufferedImage(SIZE, SIZE, BufferedImage.TYPE_INT_RGB);
        return new Chain(wrap.apply(new ImageDrawable(image)), image, p, z);
    }

    private static Chain panel(Function<Drawable, Drawable> wrap, Provenance p, ZBuffer z) {
        BufferedImage image = new BufferedImage(IMAGE, IMAGE, BufferedImage.TYPE_INT_RGB);
        return new Chain(wrap.apply(new PanelDrawable(new ImageDrawable(image), 10, 7, SIZE)), image, p, z);
    }

    /** Builds chain c afresh, with its own provenance and z-buffer. */
    private static Chain build(int c) {
        sharedOwners = new Provenance(SIZE, SIZE);
        sharedDepths = new ZBuffer(SIZE, SIZE);
        sharedDepths.reset(-200);
        sharedOwners.begin(3);
        return CHAINS.get(c).get();
    }

    @Property(tries = 200, seed = "1202012")
    void aRunDrawsWhatItsPixelsDrawThroughEveryChain(@ForAll long seed) {
        for (int c = 0; c < CHAINS.size(); c++) {
            Random random = new Random(seed);
            Chain byRun = build(c);
            Chain byPixel = build(c);
            int runs = 1 + random.nextInt(30);
            for (int k = 0; k < runs; k++) {
                int y = random.nextInt(SIZE + 6) - 3;
                int x = random.nextInt(SIZE + 20) - 10;
                int count = random.nextInt(SIZE + 10);
                int at = random.nextInt(5);
                double[] depths = new double[at + count];
                int[] colours = new int[at + count];
                for (int i = 0; i < depths.length; i++) {
                    depths[i] = -random.nextDouble() * 220;
                    colours[i] = 0xFF000000 | random.nextInt(1 << 24);
                }
                int primitive = random.nextInt(9);
                begin(byRun, primitive);
                begin(byPixel, primitive);
                byRun.top().setRun(x, y, count, depths, colours, at);
                for (int i = 0; i < count; i++) {
                    byPixel.top().setPixel(x + i, y, depths[at + i], colours[at + i]);
                }
            }
            assertSame(c, byRun, byPixel);
        }
    }

    @Property(tries = 100, seed = "1202013")
    void theWritesThatReachTheEndAreTheSameInTheSameOrder(@ForAll long seed) {
        Random random = new Random(seed);
        RecordingDrawable byRun = new RecordingDrawable(IMAGE, IMAGE);
        RecordingDrawable byPixel = new RecordingDrawable(IMAGE, IMAGE);
        Drawable runs = new PanelDrawable(byRun, 10, 7, SIZE);
        Drawable pixels = new PanelDrawable(byPixel, 10, 7, SIZE);
        for (int k = 0; k < 20; k++) {
            int y = random.nextInt(SIZE + 6) - 3;
            int x = random.nextInt(SIZE + 20) - 10;
            int count = random.nextInt(SIZE + 10);
            double[] depths = new double[count];
            int[] colours = new int[count];
            for (int i = 0; i < count; i++) {
                depths[i] = -random.nextDouble() * 200;
                colours[i] = random.nextInt();
            }
            runs.setRun(x, y, count, depths, colours, 0);
            for (int i = 0; i < count; i++) {
                pixels.setPixel(x + i, y, depths[i], colours[i]);
            }
        }
        assertEquals(byPixel.writes(), byRun.writes());
    }

    private static void begin(Chain chain, int primitive) {
        if (chain.provenance() != null) {
            chain.provenance().begin(primitive);
        }
    }

    private static void assertSame(int c, Chain byRun, Chain byPixel) {
        assertArrayEquals(pixels(byPixel.image()), pixels(byRun.image()), "chain " + c + ": the picture");
        if (byRun.provenance() != null) {
            assertArrayEquals(byPixel.provenance().copyOwners(), byRun.provenance().copyOwners(),
                    "chain " + c + ": the provenance");
        }
        if (byRun.zbuffer() != null) {
            assertArrayEquals(byPixel.zbuffer().copyDepths(), byRun.zbuffer().copyDepths(), "chain " + c + ": the depths");
        }
    }

    private static int[] pixels(BufferedImage image) {
        return ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
    }

    /** A decorator that changes setPixel only (it writes each pixel's colour halved): a run must go through it. */
    private static final class Halving extends DrawableDecorator {
        Halving(Drawable delegate) {
            super(delegate);
        }

        @Override
        public void setPixel(int x, int y, double z, int argb) {
            delegate.setPixel(x, y, z, 0xFF000000 | (argb >>> 1 & 0x7F7F7F));
        }
    }
}

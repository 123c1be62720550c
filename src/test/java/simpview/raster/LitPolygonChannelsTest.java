package simpview.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A lit polygon's channels are interpolated only as far as its sink reads
 * them (FragmentSink.channelsRead): the channels read are the same to the
 * bit as when every channel is, and the rest are never written.
 */
class LitPolygonChannelsTest {

    private static final int CHANNELS = FragmentLayout.PHONG_CHANNELS;

    /** A sink that reads the first {@code read} channels and keeps every span's numbers. */
    private static final class Spans implements FragmentSink {
        final int read;
        final List<double[]> kept = new ArrayList<>();

        Spans(int read) {
            this.read = read;
        }

        @Override
        public void span(int y, int from, int to, double q0, double dq, double[] v0, double[] dv) {
            double[] numbers = new double[4 + 2 * CHANNELS];
            numbers[0] = y;
            numbers[1] = from;
            numbers[2] = to;
            numbers[3] = q0;
            System.arraycopy(v0, 0, numbers, 4, CHANNELS);
            System.arraycopy(dv, 0, numbers, 4 + CHANNELS, CHANNELS);
            kept.add(numbers);
        }

        @Override
        public void pixel(int x, int y, double q, double[] v) {
            throw new AssertionError("a polygon gives spans");
        }

        @Override
        public int channelsRead(int channels) {
            return read;
        }
    }

    /** A triangle of nine channels, each its own plane. */
    private static double[] triangle() {
        int stride = FragmentLayout.stride(CHANNELS);
        double[] v = new double[3 * stride];
        double[][] corners = {{10.3, 12.7}, {90.1, 30.4}, {40.6, 88.2}};
        for (int k = 0; k < 3; k++) {
            v[k * stride + FragmentLayout.X] = corners[k][0];
            v[k * stride + FragmentLayout.Y] = corners[k][1];
            v[k * stride + FragmentLayout.Q] = 0.5 + 0.1 * k;
            for (int c = 0; c < CHANNELS; c++) {
                v[k * stride + FragmentLayout.CHANNEL + c] = 1 + c + 0.37 * k * (c + 1);
            }
        }
        return v;
    }

    @Test
    void theChannelsReadAreTheBitsOfAllAndTheRestAreNotWritten() {
        Spans all = new Spans(CHANNELS);
        new LitPolygonRasterizer().fill(triangle(), 3, CHANNELS, 128, 128, all);
        Spans colour = new Spans(FragmentLayout.COLOUR_CHANNELS);
        new LitPolygonRasterizer().fill(triangle(), 3, CHANNELS, 128, 128, colour);
        assertTrue(all.kept.size() > 50, "the triangle covers rows");
        assertEquals(all.kept.size(), colour.kept.size());
        for (int i = 0; i < all.kept.size(); i++) {
            double[] a = all.kept.get(i);
            double[] c = colour.kept.get(i);
            int read = FragmentLayout.COLOUR_CHANNELS;
            assertEquals(Arrays.toString(Arrays.copyOf(a, 4 + read)), Arrays.toString(Arrays.copyOf(c, 4 + read)),
                    "span " + i + ": its row, ends, q and the values read");
            assertEquals(Arrays.toString(Arrays.copyOfRange(a, 4 + CHANNELS, 4 + CHANNELS + read)),
                    Arrays.toString(Arrays.copyOfRange(c, 4 + CHANNELS, 4 + CHANNELS + read)), "span " + i + "'s slopes");
            for (int ch = read; ch < CHANNELS; ch++) {
                assertTrue(a[4 + ch] != 0, "every channel of all is interpolated");
                assertEquals(0, c[4 + ch], "channel " + ch + " is not read, so never written");
                assertEquals(0, c[4 + CHANNELS + ch]);
            }
        }
    }
}

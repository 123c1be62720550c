package simpview.raster;

/**
 * How a lit scene's vertex in panel space is laid out, from the geometry
 * stage that projects it, through the lit rasterizers, to the fragment stage
 * that resolves it: {@link #X} and {@link #Y} (panel), {@link #Q} (1/w), then
 * the channels from {@link #CHANNEL} on, each an attribute multiplied by q.
 *
 * <p>Channels, counted from {@link #CHANNEL}: {@link #Z}, {@link #R},
 * {@link #G}, {@link #B} for every primitive (R, G, B the final unfogged
 * colour, or kd under phong), and for phong also the camera-space point's x
 * and y ({@link #PX}, {@link #PY}; its z is Z) and the normal ({@link #NX},
 * {@link #NY}, {@link #NZ}).
 */
public final class FragmentLayout {

    public static final int X = 0;
    public static final int Y = 1;
    public static final int Q = 2;
    /** Where the channels start in a vertex. */
    public static final int CHANNEL = 3;

    // Channel numbers.
    public static final int Z = 0;
    public static final int R = 1;
    public static final int G = 2;
    public static final int B = 3;
    public static final int PX = 4;
    public static final int PY = 5;
    public static final int NX = 6;
    public static final int NY = 7;
    public static final int NZ = 8;
    /** Channels of a primitive whose colour is known before rasterization. */
    public static final int COLOUR_CHANNELS = 4;
    /** Channels of a phong-shaded polygon. */
    public static final int PHONG_CHANNELS = 9;

    private FragmentLayout() {
    }

    /** Numbers per vertex with this many channels. */
    public static int stride(int channels) {
        return CHANNEL + channels;
    }
}

package simpview.shading;

/**
 * A batch of points waiting to be lit together, as a phong span's visible
 * pixels are: each with its camera-space position P, its normal N (any
 * length) and its kd; {@link Lighting#shade(LitPoints)} writes each point's
 * colour. A batch is lit step by step, each step over every point, in
 * loops simple enough for the compiler to run on several points at once
 * (packed square roots and divisions), where one point at a time waits for
 * each result in turn.
 *
 * <p>Primitive arrays of a fixed capacity, made once and reused for every
 * batch; nothing is allocated after construction. Not for two threads.
 */
public final class LitPoints {

    // The points, as given.
    final double[] px;
    final double[] py;
    final double[] pz;
    final double[] nx;
    final double[] ny;
    final double[] nz;
    final double[] kdRed;
    final double[] kdGreen;
    final double[] kdBlue;
    // The lit colours.
    final double[] red;
    final double[] green;
    final double[] blue;

    // BatchLighting's scratch, per point. For the point: 1 / |N|, 1 / |E|,
    // V . N. For the light being added: N . L, |L|, 1 / |L|, cos, the
    // highlight's base V . L (then max(0, V . R) at most 1, then its
    // squares), its power and the attenuation.
    final double[] inverseNormal;
    final double[] inverseEye;
    final double[] vn;
    final double[] dot;
    final double[] distance;
    final double[] inverseDistance;
    final double[] cosine;
    final double[] highlight;
    final double[] raised;
    final double[] attenuation;
    /**
     * The point's lengths added up for the length test (BatchLighting.LENGTHS):
     * infinite or NaN, and the point is lit alone, into aloneColour, once the
     * steps are done.
     */
    final double[] lengths;
    final double[] aloneColour = new double[3];

    int count;
    /**
     * True when whoever filled the batch expects no light to reach any of its
     * points (FragmentStage's guess, from the polygon they lie on):
     * BatchLighting then only makes sure of it, point by point, and lights
     * alone each point a light does reach. A guess either way: the colours
     * are the same bits.
     */
    boolean unlit;
    /**
     * True when every point's colour came out +0 in each channel: set by
     * BatchLighting for a batch guessed unlit that no light reaches, under
     * an ambient light of zeros (SIMP's start), and cleared by it
     * otherwise. Whoever fills the batch clears it before any shader lights
     * it, and may then skip what makes black black again (fog towards black,
     * the levels): FragmentStage's pack.
     */
    boolean black;

    /** An empty batch that holds up to {@code capacity} points. */
    public LitPoints(int capacity) {
        if (capacity < 1) {
            throw new IllegalArgumentException("capacity " + capacity);
        }
        px = new double[capacity];
        py = new double[capacity];
        pz = new double[capacity];
        nx = new double[capacity];
        ny = new double[capacity];
        nz = new double[capacity];
        kdRed = new double[capacity];
        kdGreen = new double[capacity];
        kdBlue = new double[capacity];
        red = new double[capacity];
        green = new double[capacity];
        blue = new double[capacity];
        inverseNormal = new double[capacity];
        inverseEye = new double[capacity];
        vn = new double[capacity];
        dot = new double[capacity];
        distance = new double[capacity];
        inverseDistance = new double[capacity];
        cosine = new double[capacity];
        highlight = new double[capacity];
        raised = new double[capacity];
        attenuation = new double[capacity];
        lengths = new double[capacity];
    }

    public int capacity() {
        return px.length;
    }

    /** How many points the batch holds. */
    public int count() {
        return count;
    }

    /** Empties the batch. */
    public void clear() {
        count = 0;
    }

    /**
     * Adds the point P = (px, py, pz) with normal N and diffuse colour kd.
     *
     * @throws IllegalStateException if the batch is full
     */
    public void add(double x, double y, double z, double normalX, double normalY, double normalZ,
            double kr, double kg, double kb) {
        int i = count;
        if (i == px.length) {
            throw new IllegalStateException("the batch holds " + px.length + " points");
        }
        px[i] = x;
        py[i] = y;
        pz[i] = z;
        nx[i] = normalX;
        ny[i] = normalY;
        nz[i] = normalZ;
        kdRed[i] = kr;
        kdGreen[i] = kg;
        kdBlue[i] = kb;
        count = i + 1;
    }

    /** Point i's lit red, once the batch is lit. */
    public double red(int i) {
        return red[checked(i)];
    }

    public double green(int i) {
        return green[checked(i)];
    }

    public double blue(int i) {
        return blue[checked(i)];
    }

    private int checked(int i) {
        if (i < 0 || i >= count) {
            throw new IndexOutOfBoundsException("point " + i + " of " + count);
        }
        return i;
    }
}

package simpview.surface;

/**
 * A run of pixels {@code x0 <= x < x1} on row {@code y} whose depth and colour
 * are linear in x. The attributes are given at the centre of pixel
 * {@code xBase} together with their change per pixel, and every stage
 * evaluates them the same way, {@code value + (x - xBase) * slope}, so a
 * decorator that narrows [x0, x1) sees exactly the values the whole span had.
 *
 * <p>Colour channels are in byte levels (0 to 255, not yet rounded).
 * One Span is reused for every row a renderer draws: it is mutable on purpose,
 * and a decorator that changes a field puts it back before returning, except
 * the colour, which the renderer refills for every span.
 */
public final class Span {

    public int y;
    public int x0;
    public int x1;
    public int xBase;
    public double z;
    public double dz;
    public double r;
    public double dr;
    public double g;
    public double dg;
    public double b;
    public double db;
    /**
     * Room for the image's levels of this span's pixels ({@link ImageDrawable}),
     * grown as needed: a Span is one renderer's, on one thread, and so is this.
     */
    double[] levels = new double[0];

    public double zAt(int x) {
        return z + (x - xBase) * dz;
    }

    public int argbAt(int x) {
        int k = x - xBase;
        return Colors.packLevels(r + k * dr, g + k * dg, b + k * db);
    }
}

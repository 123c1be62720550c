package simpview.surface;

/** A colour with channels in [0, 1]. */
public record Rgb(double r, double g, double b) {

    public static final Rgb WHITE = new Rgb(1, 1, 1);
    public static final Rgb BLACK = new Rgb(0, 0, 0);
    public static final Rgb GREEN = new Rgb(0, 1, 0);

    public int argb() {
        return Colors.pack(r, g, b);
    }
}

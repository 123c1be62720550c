package simpview.shading;

/**
 * The {@code surface} command's state: the diffuse colour kd = (r, g, b) of
 * every vertex without a colour of its own, the specular coefficient ks and
 * the specular exponent p. A scene starts with {@link #START}.
 */
public record Material(double r, double g, double b, double ks, double p) {

    /** kd = (1, 1, 1), ks = 0.3, p = 8, as SPEC says a scene starts. */
    public static final Material START = new Material(1, 1, 1, 0.3, 8);

    /** The 3-number {@code surface r g b}: a new kd, ks and p as they were. */
    public Material withColour(double red, double green, double blue) {
        return new Material(red, green, blue, ks, p);
    }
}

package simpview.shading;

import java.util.Arrays;

/**
 * The point lights of a scene, in camera space, in the order their {@code light}
 * commands came. A primitive is lit by the lights defined before its command:
 * the interpreter remembers {@link #count()} at that command and hands it to
 * {@link Lighting#prepare} as the light count.
 *
 * <p>Light i is at (x, y, z), of intensity (red, green, blue), attenuated by
 * 1 / (a + b d) at distance d. The numbers are kept in one flat array
 * ({@value #STRIDE} per light) that the shading loop reads directly. Not
 * thread-safe: add the lights before shading with them.
 */
public final class Lights {

    /**
     * Numbers per light in {@link #data}: x, y, z, red, green, blue, a, b, and
     * 1 / a, which is the attenuation of a light with b = 0 at every distance.
     */
    static final int STRIDE = 9;
    static final int X = 0, Y = 1, Z = 2, RED = 3, GREEN = 4, BLUE = 5, A = 6, B = 7, INVERSE_A = 8;

    private double[] data = new double[4 * STRIDE];
    private int count;

    /** Adds a light after the others; the list grows as needed. */
    public void add(double x, double y, double z, double red, double green, double blue, double a, double b) {
        int at = count * STRIDE;
        if (at + STRIDE > data.length) {
            data = Arrays.copyOf(data, 2 * data.length);
        }
        data[at + X] = x;
        data[at + Y] = y;
        data[at + Z] = z;
        data[at + RED] = red;
        data[at + GREEN] = green;
        data[at + BLUE] = blue;
        data[at + A] = a;
        data[at + B] = b;
        data[at + INVERSE_A] = 1 / a;
        count++;
    }

    /** How many lights there are so far. */
    public int count() {
        return count;
    }

    /**
     * Moves light i to a new position, e.g. a light given before the camera,
     * a world position, when the camera's world-to-camera matrix becomes known.
     */
    public void moveTo(int i, double x, double y, double z) {
        int at = index(i);
        data[at + X] = x;
        data[at + Y] = y;
        data[at + Z] = z;
    }

    /** A copy of the lights as they are now, apart from later changes to these. */
    public Lights copy() {
        Lights c = new Lights();
        c.data = data.clone();
        c.count = count;
        return c;
    }

    /** Forgets every light (a new picture of the scene starts with none). */
    public void clear() {
        count = 0;
    }

    public double x(int i) {
        return data[index(i) + X];
    }

    public double y(int i) {
        return data[index(i) + Y];
    }

    public double z(int i) {
        return data[index(i) + Z];
    }

    public double red(int i) {
        return data[index(i) + RED];
    }

    public double green(int i) {
        return data[index(i) + GREEN];
    }

    public double blue(int i) {
        return data[index(i) + BLUE];
    }

    public double a(int i) {
        return data[index(i) + A];
    }

    public double b(int i) {
        return data[index(i) + B];
    }

    /** The flat numbers, {@link #STRIDE} per light; the array is replaced when the list grows. */
    double[] data() {
        return data;
    }

    private int index(int i) {
        if (i < 0 || i >= count) {
            throw new IndexOutOfBoundsException("light " + i + " of " + count);
        }
        return i * STRIDE;
    }
}

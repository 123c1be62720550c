package simpview.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.util.Arrays;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.DoubleRange;
import org.junit.jupiter.api.Test;
import simpview.geometry.Vertex;
import simpview.surface.Colors;
import simpview.surface.ImageDrawable;

/** The handout's slab-and-disc antialiasing, against the areas worked out by hand and by numbers. */
class AntialiasedLineRendererTest {

    private static final double R = Math.sqrt(2) / 2;

    /** The disc's share inside {@code |t| <= 1/2}, by summing thin strips of the disc (no formula shared). */
    private static double numericCoverage(double distance) {
        int strips = 200_000;
        double inside = 0;
        double total = 0;
        for (int i = 0; i < strips; i++) {
            double t = -R + (i + 0.5) * 2 * R / strips;
            double chord = 2 * Math.sqrt(R * R - t * t);
            total += chord;
            if (Math.abs(t + distance) <= 0.5) {
                inside += chord;
            }
        }
        return inside / total;
    }

    @Test
    void coverageMatchesTheDiscsShareInsideTheSlab() {
        for (double d = 0; d <= 1.3; d += 0.05) {
            assertEquals(numericCoverage(d), AntialiasedLineRenderer.coverage(d), 1e-4, "distance " + d);
        }
        // By hand: on the line each edge cuts a cap at h = 1/2, area r^2 acos(h/r) - h sqrt(r^2 - h^2)
        // = pi/8 - 1/4, so 1 - 2 (pi/8 - 1/4) / (pi/2) = 1/2 + 1/pi = 0.8183.
        assertEquals(1 - 2 * (Math.PI / 8 - 0.25) / (Math.PI / 2), AntialiasedLineRenderer.coverage(0), 1e-12);
        assertEquals(0, AntialiasedLineRenderer.coverage(0.5 + R), 0);
        assertEquals(AntialiasedLineRenderer.coverage(0.3), AntialiasedLineRenderer.coverage(-0.3), 0);
    }

    /** The handout's closed form with Math.acos, written again here: one minus both caps over the disc. */
    private static double closedForm(double distance) {
        double d = Math.abs(distance);
        double inside = Math.PI * R * R;
        for (double h : new double[] {0.5 - d, 0.5 + d}) {
            if (h <= -R) {
                inside -= Math.PI * R * R;
            } else if (h < R) {
                inside -= R * R * Math.acos(h / R) - h * Math.sqrt(R * R - h * h);
            }
        }
        return Math.max(0, inside / (Math.PI * R * R));
    }

    /** simpview's coverage (no Math.acos on its way) is the closed form's within 1e-13, everywhere. */
    @Test
    void coverageIsTheClosedFormsToTheLastBits() {
        double worst = 0;
        for (int i = 0; i <= 130_000; i++) {
            double d = i * 1e-5 + (i % 7) * 1e-7;
            worst = Math.max(worst, Math.abs(AntialiasedLineRenderer.coverage(d) - closedForm(d)));
        }
        assertTrue(worst < 1e-13, "worst difference " + worst);
    }

    /**
     * A white line on black, every pixel against a reference worked out here:
     * the rounded ends, pixels whose centre lies along the segment or within
     * half a pixel past an end, each the byte of its closed-form coverage.
     */
    @Test
    void everyPixelOfALineIsItsClosedFormCoverage() {
        double[][] lines = {{20.4, 30.2, 270.6, 141.7}, {150, 150, 150 + 135 * Math.cos(1.3), 150 + 135 * Math.sin(1.3)},
            {250, 20, 40, 280}, {10, 200, 290, 200}, {100, 10, 100, 290}, {7, 7, 8, 9}};
        for (double[] line : lines) {
            ImageDrawable image = new ImageDrawable(new BufferedImage(300, 300, BufferedImage.TYPE_INT_RGB));
            new AntialiasedLineRenderer().drawLine(Vertex.of(line[0], line[1], 0).withColor(1, 1, 1),
                    Vertex.of(line[2], line[3], 0).withColor(1, 1, 1), image);
            double ax = Math.floor(line[0] + 0.5);
            double ay = Math.floor(line[1] + 0.5);
            double bx = Math.floor(line[2] + 0.5);
            double by = Math.floor(line[3] + 0.5);
            double length = Math.hypot(bx - ax, by - ay);
            for (int y = 0; y < 300; y++) {
                for (int x = 0; x < 300; x++) {
                    double along = ((x - ax) * (bx - ax) + (y - ay) * (by - ay)) / length;
                    double distance = Math.abs((x - ax) * (by - ay) - (y - ay) * (bx - ax)) / length;
                    boolean near = along >= -0.5 && along <= length + 0.5 && distance < 1.3;
                    int expected = near ? Colors.toByte(closedForm(distance)) : 0;
                    int got = Colors.red(image.getPixel(x, y));
                    if (got != expected) {
                        assertEquals(expected, got, x + "," + y + " of " + Arrays.toString(line));
                    }
                }
            }
        }
    }

    @Property(tries = 300, seed = "1202009")
    void coverageIsAShare(@ForAll @DoubleRange(min = -3, max = 3) double d) {
        double c = AntialiasedLineRenderer.coverage(d);
        assertTrue(c >= 0 && c <= 1, "coverage " + c + " at " + d);
    }

    /**
     * Across a line, perpendicular to it, the coverages add up to its width (1)
     * over the spacing of the pixels crossed: a column of a line at angle a to
     * its major axis sums to about 1 / cos a: within 4 % on the mean of its
     * columns (one column alone is off by up to 6 %, by where its pixel
     * centres fall; at 45 degrees every column samples the same places and
     * sums to 0.818 + 2 x 0.316 = 1.451 against sqrt 2).
     */
    @Property(tries = 60, seed = "1202010")
    void aCrossSectionSumsToAboutTheWidth(@ForAll @DoubleRange(min = 0, max = 45) double degrees) {
        double a = Math.toRadians(degrees);
        double x0 = 20;
        double y0 = 100;
        double x1 = Math.floor(x0 + 200 * Math.cos(a) + 0.5);
        double y1 = Math.floor(y0 + 200 * Math.sin(a) + 0.5);
        double angle = Math.atan2(y1 - y0, x1 - x0);
        double[] sum = new double[1];
        AntialiasedLineRenderer aa = new AntialiasedLineRenderer();
        ImageDrawable image = new ImageDrawable(new BufferedImage(300, 300, BufferedImage.TYPE_INT_RGB));
        aa.drawLine(Vertex.of(x0, y0, 0).withColor(1, 1, 1), Vertex.of(x1, y1, 0).withColor(1, 1, 1), image);
        // Each column samples the profile at its own phase; over many columns the mean is the integral.
        int columns = 0;
        for (int column = (int) x0 + 20; column <= (int) x1 - 20; column++, columns++) {
            for (int y = 0; y < 300; y++) {
                sum[0] += Colors.red(image.getPixel(column, y)) / 255.0;
            }
        }
        double expected = 1 / Math.cos(angle);
        assertEquals(expected, sum[0] / columns, 0.04 * expected, degrees + " degrees");
    }

    @Test
    void aHorizontalLineHasItsThreeRowsAndHalfAPixelPastEachEnd() {
        BufferedImage picture = new BufferedImage(20, 20, BufferedImage.TYPE_INT_RGB);
        ImageDrawable image = new ImageDrawable(picture);
        new AntialiasedLineRenderer().drawLine(new Vertex(5, 10, 0, 1, 1, 1), new Vertex(14, 10, 0, 1, 1, 1), image);
        int centre = Colors.toByte(AntialiasedLineRenderer.coverage(0));
        int side = Colors.toByte(AntialiasedLineRenderer.coverage(1));
        for (int x = 0; x < 20; x++) {
            boolean on = x >= 5 && x <= 14;
            assertEquals(on ? centre : 0, Colors.red(image.getPixel(x, 10)), "row 10, column " + x);
            assertEquals(on ? side : 0, Colors.red(image.getPixel(x, 9)), "row 9, column " + x);
            assertEquals(on ? side : 0, Colors.red(image.getPixel(x, 11)), "row 11, column " + x);
            assertEquals(0, Colors.red(image.getPixel(x, 8)));
        }
        assertEquals(209, centre);
        assertEquals(23, side);
    }

    /** A write with coverage c over a colour blends c * colour + (1 - c) * old per channel. */
    @Test
    void coverageBlendsOverWhatIsThere() {
        BufferedImage picture = new BufferedImage(20, 20, BufferedImage.TYPE_INT_RGB);
        ImageDrawable image = new ImageDrawable(picture);
        image.fillRect(0, 0, 20, 20, 0xFF0000FF);
        new AntialiasedLineRenderer().drawLine(new Vertex(2, 10, 0, 1, 0, 0), new Vertex(17, 10, 0, 1, 0, 0), image);
        double c = AntialiasedLineRenderer.coverage(0);
        assertEquals(Colors.pack(c, 0, 1 - c), image.getPixel(8, 10));
        double s = AntialiasedLineRenderer.coverage(1);
        assertEquals(Colors.pack(s, 0, 1 - s), image.getPixel(8, 9));
    }

    @Test
    void bothDirectionsDrawTheSamePixels() {
        ImageDrawable a = new ImageDrawable(new BufferedImage(100, 100, BufferedImage.TYPE_INT_RGB));
        ImageDrawable b = new ImageDrawable(new BufferedImage(100, 100, BufferedImage.TYPE_INT_RGB));
        new AntialiasedLineRenderer().drawLine(Vertex.of(10.3, 20.6, 0).withColor(1, 1, 1), Vertex.of(80, 61, 0).withColor(1, 1, 1), a);
        new AntialiasedLineRenderer().drawLine(Vertex.of(80, 61, 0).withColor(1, 1, 1), Vertex.of(10.3, 20.6, 0).withColor(1, 1, 1), b);
        for (int y = 0; y < 100; y++) {
            for (int x = 0; x < 100; x++) {
                assertEquals(a.getPixel(x, y), b.getPixel(x, y), x + "," + y);
            }
        }
    }

    @Test
    void aOnePixelLineIsItsPixelAndTheTwoBesideItOnItsMinorAxis() {
        ImageDrawable image = new ImageDrawable(new BufferedImage(10, 10, BufferedImage.TYPE_INT_RGB));
        new AntialiasedLineRenderer().drawLine(Vertex.of(4.2, 4.3, 0).withColor(1, 1, 1), Vertex.of(3.8, 4.1, 0).withColor(1, 1, 1), image);
        assertEquals(209, Colors.red(image.getPixel(4, 4)));
        assertEquals(23, Colors.red(image.getPixel(4, 3)));
        assertEquals(23, Colors.red(image.getPixel(4, 5)));
        assertEquals(0, Colors.red(image.getPixel(3, 4)));
    }
}

package simpview.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;
import simpview.geometry.Vertex;
import simpview.surface.Colors;
import simpview.testing.CountingDrawable;

class DdaLineRendererTest {

    private final DdaLineRenderer dda = new DdaLineRenderer();

    @Test
    void endpointsGetTheirOwnColourAndTheMidpointTheAverage() {
        CountingDrawable d = new CountingDrawable(200, 200);
        dda.drawLine(new Vertex(10.5, 20.5, -10, 1, 0, 0), new Vertex(110.5, 20.5, -50, 0, 0, 1), d);
        assertEquals(Colors.pack(1, 0, 0), d.getPixel(10, 20));
        assertEquals(Colors.pack(0, 0, 1), d.getPixel(110, 20));
        assertEquals(-10, d.depth(10, 20));
        assertEquals(-50, d.depth(110, 20));
        // Halfway: t = 0.5 exactly, round(127.5) = 128 for both channels.
        assertEquals(0xFF800080, d.getPixel(60, 20));
        assertEquals(-30, d.depth(60, 20), 1e-12);
        assertEquals(101, d.writes());
    }

    /**
     * Octant 1 of a line from (100, 100) to (107, 103) (pixel centres) gives rows
     * round(3k/7) = 0 0 1 1 2 2 3 3; no step is a tie, so every other octant is
     * that pattern reflected and swapped.
     */
    @ParameterizedTest(name = "signs ({0}, {1}), swapped {2}")
    @CsvSource({"1,1,false", "1,1,true", "-1,1,false", "-1,1,true",
        "-1,-1,false", "-1,-1,true", "1,-1,false", "1,-1,true"})
    void everyOctantHitsTheExpectedPixels(int sx, int sy, boolean swap) {
        int[] minor = {0, 0, 1, 1, 2, 2, 3, 3};
        Set<String> expected = new HashSet<>();
        for (int k = 0; k < minor.length; k++) {
            int u = swap ? minor[k] : k;
            int v = swap ? k : minor[k];
            expected.add((100 + sx * u) + "," + (100 + sy * v));
        }
        int endX = swap ? 3 : 7;
        int endY = swap ? 7 : 3;
        CountingDrawable d = new CountingDrawable(200, 200);
        dda.drawLine(Vertex.of(100.5, 100.5, -1), Vertex.of(100.5 + sx * endX, 100.5 + sy * endY, -1), d);
        Set<String> drawn = new HashSet<>();
        for (int y = 0; y < 200; y++) {
            for (int x = 0; x < 200; x++) {
                if (d.count(x, y) > 0) {
                    drawn.add(x + "," + y);
                }
            }
        }
        assertEquals(expected, drawn);
        assertEquals(8, d.writes(), "one write per step, no pixel twice");
    }

    @Test
    void eachColumnOfAShallowLineIsWithinHalfAPixelOfTheTrueLine() {
        CountingDrawable d = new CountingDrawable(300, 300);
        double x0 = 3.5;
        double y0 = 7.5;
        double x1 = 250.5;
        double y1 = 101.5;
        dda.drawLine(Vertex.of(x0, y0, 0), Vertex.of(x1, y1, 0), d);
        for (int x = 3; x <= 250; x++) {
            double trueY = y0 + (y1 - y0) * (x + 0.5 - x0) / (x1 - x0);
            int hits = 0;
            for (int y = 0; y < 300; y++) {
                if (d.count(x, y) > 0) {
                    hits++;
                    assertTrue(Math.abs(y + 0.5 - trueY) <= 0.5, "column " + x + " row " + y + " vs " + trueY);
                }
            }
            assertEquals(1, hits, "column " + x);
        }
    }

    @Test
    void aLineInsideOnePixelDrawsThatPixelOnce() {
        CountingDrawable d = new CountingDrawable(10, 10);
        dda.drawLine(new Vertex(4.2, 4.7, -3, 0, 1, 0), new Vertex(4.9, 4.1, -3, 0, 1, 0), d);
        assertEquals(1, d.writes());
        assertEquals(Colors.pack(0, 1, 0), d.getPixel(4, 4));
    }

    @Test
    void aLineFarBeyondTheSurfaceOnlyVisitsStepsOnIt() {
        CountingDrawable d = new CountingDrawable(650, 650);
        dda.drawLine(Vertex.of(-1e12, 300.5, 0), Vertex.of(1e12, 300.5, 0), d);
        assertEquals(650, d.writes());
        assertEquals(0, d.strays());
    }

    @Test
    void nonFiniteEndpointsDrawNothing() {
        CountingDrawable d = new CountingDrawable(10, 10);
        dda.drawLine(Vertex.of(Double.NaN, 1, 0), Vertex.of(5, 5, 0), d);
        dda.drawLine(Vertex.of(1, 1, 0), Vertex.of(Double.POSITIVE_INFINITY, 5, 0), d);
        assertEquals(0, d.writes());
    }
}

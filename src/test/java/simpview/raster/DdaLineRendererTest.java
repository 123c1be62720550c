package simpview.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import simpview.geometry.Vertex;
import simpview.raster.LineExpectations.Tie;
import simpview.surface.Colors;
import simpview.testing.CountingDrawable;
import simpview.testing.RecordingDrawable;

/** The DDA against SPEC Part 1's line rule, worked out exactly in {@link LineExpectations}. */
class DdaLineRendererTest {

    private final DdaLineRenderer dda = new DdaLineRenderer();

    @Test
    void endpointsGetTheirOwnColourAndTheMidpointTheAverage() {
        CountingDrawable d = new CountingDrawable(200, 200);
        dda.drawLine(new Vertex(10, 20, -10, 1, 0, 0), new Vertex(110, 20, -50, 0, 0, 1), d);
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
     * A line at one depth, z = -100 at both ends, is -100 at every pixel, as a
     * filled triangle at that depth is: the depth cue then gives 0.5, and
     * round(127.5) = 128 all along. The lerp {@code (1 - t) * a + t * b}
     * gave -100.00000000000001 at some steps, so the line came out 127 and
     * 128 by turns. The same for a channel both ends share.
     */
    @Test
    void aValueBothEndsShareIsEveryPixelsValue() {
        RecordingDrawable d = new RecordingDrawable(650, 650);
        dda.drawLine(new Vertex(0, 0.5, -100, 0.5, 0.2, 0.5), new Vertex(649, 0.5, -100, 0.5, 0.7, 0.5), d);
        assertEquals(650, d.writes().size());
        for (RecordingDrawable.Write w : d.writes()) {
            assertEquals(-100.0, w.z(), "z at x = " + w.x());
            assertEquals(128, (w.argb() >> 16) & 0xFF, "red at x = " + w.x());
            assertEquals(128, w.argb() & 0xFF, "blue at x = " + w.x());
        }
    }

    /** Drawn from the end with the smaller x, the colour runs from that end's, whichever end is given first. */
    @Test
    void aLineGivenRightToLeftIsDrawnFromItsLeftEndWithTheSameColours() {
        RecordingDrawable forward = new RecordingDrawable(50, 50);
        RecordingDrawable backward = new RecordingDrawable(50, 50);
        Vertex left = new Vertex(3, 4, -10, 1, 0, 0);
        Vertex right = new Vertex(40, 17, -90, 0, 1, 0);
        dda.drawLine(left, right, forward);
        dda.drawLine(right, left, backward);
        assertEquals(forward.writes(), backward.writes());
        assertEquals(new RecordingDrawable.Write(3, 4, -10, Colors.pack(1, 0, 0)), backward.writes().get(0));
    }

    /** Endpoints are rounded to the nearest pixel, floor(v + 0.5): 10.5 is pixel 11, 10.49 is pixel 10. */
    @Test
    void endpointsAreRoundedHalfUp() {
        assertEquals(List.of("11,10", "12,10", "13,10"), LineExpectations.drawn(dda, 10.5, 10.2, 12.7, 9.5, 20));
        assertEquals(List.of("10,10", "11,10", "12,10"), LineExpectations.drawn(dda, 10.49, 10.49, 12.49, 10.49, 20));
        assertEquals(List.of("0,0"), LineExpectations.drawn(dda, -0.5, -0.5, 0.49, 0.3, 20));
    }

    /** The same 7:3 line in all eight octants, from both ends: the exact rounded rows, start first. */
    @ParameterizedTest(name = "to ({0}, {1}), reversed {2}")
    @CsvSource({"7,3,false", "3,7,false", "-3,7,false", "-7,3,false", "-7,-3,false", "-3,-7,false",
        "3,-7,false", "7,-3,false", "7,3,true", "3,7,true", "-3,7,true", "-7,3,true", "-7,-3,true",
        "-3,-7,true", "3,-7,true", "7,-3,true"})
    void everyOctantFromEitherEndHitsTheExactPixels(int dx, int dy, boolean reversed) {
        int x0 = 100;
        int y0 = 100;
        List<String> expected = LineExpectations.pixels(x0, y0, x0 + dx, y0 + dy, Tie.HALF_UP);
        List<String> drawn = reversed
                ? LineExpectations.drawn(dda, x0 + dx, y0 + dy, x0, y0, 200)
                : LineExpectations.drawn(dda, x0, y0, x0 + dx, y0 + dy, 200);
        assertEquals(expected, drawn);
        assertTrue(drawn.contains(x0 + "," + y0) && drawn.contains((x0 + dx) + "," + (y0 + dy)), "both ends");
    }

    @Test
    void horizontalVerticalAndDiagonalLines() {
        assertEquals(List.of("2,5", "3,5", "4,5", "5,5"), LineExpectations.drawn(dda, 5, 5, 2, 5, 10));
        assertEquals(List.of("5,2", "5,3", "5,4"), LineExpectations.drawn(dda, 5, 4, 5, 2, 10));
        assertEquals(List.of("1,1", "2,2", "3,3", "4,4"), LineExpectations.drawn(dda, 4, 4, 1, 1, 10));
        // |dx| = |dy| is x-major: drawn from the smaller x, y going down.
        assertEquals(List.of("1,4", "2,3", "3,2", "4,1"), LineExpectations.drawn(dda, 4, 1, 1, 4, 10));
    }

    @Test
    void aLineInsideOnePixelDrawsThatPixelOnce() {
        CountingDrawable d = new CountingDrawable(10, 10);
        dda.drawLine(new Vertex(4.2, 4.3, -3, 0, 1, 0), new Vertex(4.4, 3.9, -3, 0, 1, 0), d);
        assertEquals(1, d.writes());
        assertEquals(Colors.pack(0, 1, 0), d.getPixel(4, 4));
    }

    /**
     * Ties: the minor coordinate is rounded half up, toward +minor, whichever
     * way the line goes. A 2:1 line from (0, 0) reaches minor 0.5 at its
     * middle step and goes up; a 2:-1 line reaches -0.5 and stays at 0.
     */
    @Test
    void aTieRoundsTowardPlusMinor() {
        assertEquals(List.of("0,0", "1,1", "2,1"), LineExpectations.drawn(dda, 0, 0, 2, 1, 10));
        assertEquals(List.of("0,5", "1,5", "2,4"), LineExpectations.drawn(dda, 0, 5, 2, 4, 10));
        assertEquals(List.of("0,0", "1,1", "1,2"), LineExpectations.drawn(dda, 0, 0, 1, 2, 10));
        assertEquals(List.of("5,0", "5,1", "4,2"), LineExpectations.drawn(dda, 5, 0, 4, 2, 10));
    }

    /**
     * On random lines without an exact tie the adding DDA lights exactly the
     * exact rounding's pixels (its sums are off by far less than the distance
     * to the next half).
     */
    @Test
    void randomLinesWithoutTiesMatchTheExactRounding() {
        Random random = new Random(23);
        int checked = 0;
        while (checked < 2000) {
            int x0 = random.nextInt(300);
            int y0 = random.nextInt(300);
            int x1 = random.nextInt(300);
            int y1 = random.nextInt(300);
            if (LineExpectations.hasTie(x0, y0, x1, y1)) {
                continue;
            }
            assertEquals(LineExpectations.pixels(x0, y0, x1, y1, Tie.HALF_UP),
                    LineExpectations.drawn(dda, x0, y0, x1, y1, 300), x0 + "," + y0 + " to " + x1 + "," + y1);
            checked++;
        }
    }

    /** A line clipped by the surface lights the same pixels as the whole one, where they are on it. */
    @Test
    void aClippedLineMatchesTheWholeOne() {
        List<String> whole = LineExpectations.drawn(dda, -40, -13, 90, 71, 400);
        RecordingDrawable small = new RecordingDrawable(50, 50);
        dda.drawLine(Vertex.of(-40, -13, -1), Vertex.of(90, 71, -1), small);
        List<String> part = small.writes().stream().map(w -> w.x() + "," + w.y()).toList();
        List<String> expected = whole.stream().filter(p -> {
            String[] xy = p.split(",");
            int x = Integer.parseInt(xy[0]);
            int y = Integer.parseInt(xy[1]);
            return x < 50 && y < 50;
        }).toList();
        // The 400x400 drawing drops the pixels at negative coordinates too.
        assertEquals(expected, part);
        assertEquals(0, small.strays());
    }

    @Test
    void aLineFarBeyondTheSurfaceOnlyVisitsStepsOnIt() {
        CountingDrawable d = new CountingDrawable(650, 650);
        dda.drawLine(Vertex.of(-1e12, 300, 0), Vertex.of(1e12, 300, 0), d);
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

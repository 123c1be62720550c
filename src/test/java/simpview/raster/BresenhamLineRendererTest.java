package simpview.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
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

/** Bresenham's line against the exact rounding of {@link LineExpectations}, and beside the DDA. */
class BresenhamLineRendererTest {

    private final BresenhamLineRenderer bresenham = new BresenhamLineRenderer();
    private final DdaLineRenderer dda = new DdaLineRenderer();

    @ParameterizedTest(name = "to ({0}, {1}), reversed {2}")
    @CsvSource({"7,3,false", "3,7,false", "-3,7,false", "-7,3,false", "-7,-3,false", "-3,-7,false",
        "3,-7,false", "7,-3,false", "7,3,true", "3,7,true", "-3,7,true", "-7,3,true", "-7,-3,true",
        "-3,-7,true", "3,-7,true", "7,-3,true"})
    void everyOctantFromEitherEndHitsTheExactPixels(int dx, int dy, boolean reversed) {
        List<String> expected = LineExpectations.pixels(100, 100, 100 + dx, 100 + dy, Tie.AWAY_FROM_START);
        List<String> drawn = reversed
                ? LineExpectations.drawn(bresenham, 100 + dx, 100 + dy, 100, 100, 200)
                : LineExpectations.drawn(bresenham, 100, 100, 100 + dx, 100 + dy, 200);
        assertEquals(expected, drawn);
    }

    @Test
    void horizontalVerticalDiagonalAndOnePixelLines() {
        assertEquals(List.of("2,5", "3,5", "4,5", "5,5"), LineExpectations.drawn(bresenham, 5, 5, 2, 5, 10));
        assertEquals(List.of("5,2", "5,3", "5,4"), LineExpectations.drawn(bresenham, 5, 4, 5, 2, 10));
        assertEquals(List.of("1,1", "2,2", "3,3", "4,4"), LineExpectations.drawn(bresenham, 4, 4, 1, 1, 10));
        assertEquals(List.of("1,4", "2,3", "3,2", "4,1"), LineExpectations.drawn(bresenham, 4, 1, 1, 4, 10));
        assertEquals(List.of("4,4"), LineExpectations.drawn(bresenham, 4.2, 4.3, 3.6, 4.4, 10));
    }

    /** Endpoints rounded as the DDA rounds them, so both draw from and to the same pixels. */
    @Test
    void endpointsAreRoundedAsForTheDda() {
        assertEquals(List.of("11,10", "12,10", "13,10"), LineExpectations.drawn(bresenham, 10.5, 10.2, 12.7, 9.5, 20));
    }

    @Test
    void endpointsGetTheirOwnColourAndDepth() {
        CountingDrawable d = new CountingDrawable(200, 200);
        bresenham.drawLine(new Vertex(110, 40, -50, 0, 0, 1), new Vertex(10, 20, -10, 1, 0, 0), d);
        assertEquals(Colors.pack(1, 0, 0), d.getPixel(10, 20));
        assertEquals(Colors.pack(0, 0, 1), d.getPixel(110, 40));
        assertEquals(-10, d.depth(10, 20));
        assertEquals(-50, d.depth(110, 40));
        assertEquals(101, d.writes());
    }

    /**
     * The tie rule: at an exact tie Bresenham steps the minor coordinate
     * (away from the start's side). On a 2:1 line rising from (0, 0) the middle
     * step is a tie: both go to row 1 (the DDA by rounding half up). On the
     * falling 2:-1 line from (0, 5) Bresenham steps down to row 4 where the
     * DDA's 4.5 rounds up to 5.
     */
    @Test
    void atATieBresenhamStepsAndDiffersFromTheDdaOnFallingLines() {
        assertEquals(List.of("0,0", "1,1", "2,1"), LineExpectations.drawn(bresenham, 0, 0, 2, 1, 10));
        assertEquals(LineExpectations.drawn(dda, 0, 0, 2, 1, 10), LineExpectations.drawn(bresenham, 0, 0, 2, 1, 10));
        assertEquals(List.of("0,5", "1,4", "2,4"), LineExpectations.drawn(bresenham, 0, 5, 2, 4, 10));
        assertEquals(List.of("0,5", "1,5", "2,4"), LineExpectations.drawn(dda, 0, 5, 2, 4, 10));
        // y-major: the same, x rising or falling from the smaller-y end.
        assertEquals(List.of("0,0", "1,1", "1,2"), LineExpectations.drawn(bresenham, 0, 0, 1, 2, 10));
        assertEquals(List.of("5,0", "4,1", "4,2"), LineExpectations.drawn(bresenham, 5, 0, 4, 2, 10));
    }

    /**
     * Where the rule says the two must agree: every line without an exact tie.
     * Where they may differ: at ties, where Bresenham steps (exactly) and
     * the DDA's added-up minor coordinate lands on the half or a last bit
     * either side of it, then rounded half up.
     */
    @Test
    void theDdaAndBresenhamAgreeExceptAtTies() {
        Random random = new Random(19);
        int differing = 0;
        for (int n = 0; n < 4000; n++) {
            int x0 = random.nextInt(300);
            int y0 = random.nextInt(300);
            int x1 = random.nextInt(300);
            int y1 = random.nextInt(300);
            List<String> a = LineExpectations.drawn(dda, x0, y0, x1, y1, 300);
            List<String> b = LineExpectations.drawn(bresenham, x0, y0, x1, y1, 300);
            String line = x0 + "," + y0 + " to " + x1 + "," + y1;
            if (!LineExpectations.hasTie(x0, y0, x1, y1)) {
                assertEquals(a, b, line);
            } else {
                assertEquals(LineExpectations.pixels(x0, y0, x1, y1, Tie.AWAY_FROM_START), b, line);
                differing += a.equals(b) ? 0 : 1;
            }
        }
        assertTrue(differing > 0, "some line with a tie shows the difference");
    }

    @Test
    void aClippedLineMatchesTheWholeOne() {
        List<String> whole = LineExpectations.drawn(bresenham, -40, -13, 90, 71, 400);
        RecordingDrawable small = new RecordingDrawable(50, 50);
        bresenham.drawLine(Vertex.of(-40, -13, -1), Vertex.of(90, 71, -1), small);
        List<String> part = small.writes().stream().map(w -> w.x() + "," + w.y()).toList();
        assertEquals(whole.stream().filter(p -> Integer.parseInt(p.split(",")[0]) < 50
                && Integer.parseInt(p.split(",")[1]) < 50).toList(), part);
    }

    @Test
    void aLineFarBeyondTheSurfaceOnlyVisitsPixelsOnIt() {
        CountingDrawable d = new CountingDrawable(650, 650);
        bresenham.drawLine(Vertex.of(-1e12, -3e11, 0), Vertex.of(1e12, 3e11 + 1, 0), d);
        assertTrue(d.writes() <= 650);
        assertEquals(0, d.strays());
        CountingDrawable e = new CountingDrawable(10, 10);
        bresenham.drawLine(Vertex.of(Double.NaN, 1, 0), Vertex.of(5, 5, 0), e);
        bresenham.drawLine(Vertex.of(1e300, 1, 0), Vertex.of(5, 5, 0), e);
        assertFalse(e.writes() > 0);
    }

    /** A long line's pixels beyond the surface are skipped by the closed form, matching the steps it stands for. */
    @Test
    void skippingAheadMatchesSteppingThere() {
        List<String> whole = LineExpectations.drawn(bresenham, 0, 0, 2999, 1234, 3000);
        RecordingDrawable window = new RecordingDrawable(3000, 300);
        bresenham.drawLine(Vertex.of(-2000, -100, -1), Vertex.of(999, 1134, -1), window);
        // The same line moved by (-2000, -100): where it crosses rows 0..299 it must be the same pixels, moved.
        List<String> moved = whole.stream().map(p -> {
            String[] xy = p.split(",");
            return (Integer.parseInt(xy[0]) - 2000) + "," + (Integer.parseInt(xy[1]) - 100);
        }).filter(p -> {
            String[] xy = p.split(",");
            int x = Integer.parseInt(xy[0]);
            int y = Integer.parseInt(xy[1]);
            return x >= 0 && y >= 0 && y < 300;
        }).toList();
        assertEquals(moved, window.writes().stream().map(w -> w.x() + "," + w.y()).toList());
    }

}

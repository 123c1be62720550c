package simpview.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
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

/**
 * Bresenham's line against the exact roundings of {@link LineExpectations},
 * and beside the DDA: SPEC Part 3's ({@code bresenham}, the integer algorithm
 * on the rounded ends) and the course's program's ({@code course}, the
 * decisions on the ends' given minor coordinates).
 */
class BresenhamLineRendererTest {

    private final BresenhamLineRenderer bresenham = new BresenhamLineRenderer();
    private final BresenhamLineRenderer course = BresenhamLineRenderer.throughGivenMinor();
    private final DdaLineRenderer dda = new DdaLineRenderer();

    private static double round(double v) {
        return Math.floor(v + 0.5);
    }

    @ParameterizedTest(name = "to ({0}, {1}), reversed {2}")
    @CsvSource({"7,3,false", "3,7,false", "-3,7,false", "-7,3,false", "-7,-3,false", "-3,-7,false",
        "3,-7,false", "7,-3,false", "7,3,true", "3,7,true", "-3,7,true", "-7,3,true", "-7,-3,true",
        "-3,-7,true", "3,-7,true", "7,-3,true", "6,3,false", "-6,-3,true", "3,-6,false", "-3,6,true"})
    void everyOctantFromEitherEndHitsTheExactPixels(int dx, int dy, boolean reversed) {
        List<String> expected = LineExpectations.pixels(100, 100, 100 + dx, 100 + dy, Tie.TOWARD_START);
        List<String> drawn = reversed
                ? LineExpectations.drawn(bresenham, 100 + dx, 100 + dy, 100, 100, 200)
                : LineExpectations.drawn(bresenham, 100, 100, 100 + dx, 100 + dy, 200);
        assertEquals(expected, drawn);
        assertEquals(LineExpectations.bresenham(100, 100, 100 + dx, 100 + dy), drawn);
        // On integer ends the two rules are one walk.
        assertEquals(drawn, reversed
                ? LineExpectations.drawn(course, 100 + dx, 100 + dy, 100, 100, 200)
                : LineExpectations.drawn(course, 100, 100, 100 + dx, 100 + dy, 200));
    }

    @Test
    void horizontalVerticalDiagonalAndOnePixelLines() {
        assertEquals(List.of("2,5", "3,5", "4,5", "5,5"), LineExpectations.drawn(bresenham, 5, 5, 2, 5, 10));
        assertEquals(List.of("5,2", "5,3", "5,4"), LineExpectations.drawn(bresenham, 5, 4, 5, 2, 10));
        assertEquals(List.of("1,1", "2,2", "3,3", "4,4"), LineExpectations.drawn(bresenham, 4, 4, 1, 1, 10));
        assertEquals(List.of("1,4", "2,3", "3,2", "4,1"), LineExpectations.drawn(bresenham, 4, 1, 1, 4, 10));
        assertEquals(List.of("4,4"), LineExpectations.drawn(bresenham, 4.2, 4.3, 3.6, 4.4, 10));
        assertEquals(List.of("4,4"), LineExpectations.drawn(course, 4.2, 4.3, 3.6, 4.4, 10));
    }

    /**
     * SPEC's rule rounds every end first: from (0, 0) to (11, 3.4) it is the
     * integer algorithm from (0, 0) to (11, 3), pixel for pixel the DDA's
     * there (3 k / 11 is never a half: no tie), where the course's rule, on
     * the given slope 3.4 / 11, is a row higher at x = 5 (1.55 against 1.36)
     * and at x = 9 (2.78 against 2.45).
     */
    @Test
    void specsRuleRoundsEveryEndFirst() {
        List<String> drawn = LineExpectations.drawn(bresenham, 0, 0, 11, 3.4, 20);
        assertEquals(LineExpectations.bresenham(0, 0, 11, 3), drawn);
        assertEquals(LineExpectations.drawn(dda, 0, 0, 11, 3.4, 20), drawn);
        assertEquals(LineExpectations.drawn(bresenham, 0, 0, 11, 3, 20), drawn);
        assertEquals("5,1", drawn.get(5));
        assertEquals("5,2", LineExpectations.drawn(course, 0, 0, 11, 3.4, 20).get(5));
        assertEquals("9,2", drawn.get(9));
        assertEquals("9,3", LineExpectations.drawn(course, 0, 0, 11, 3.4, 20).get(9));
        assertEquals(LineExpectations.drawn(bresenham, 10.5, 10.2, 12.7, 9.5, 20),
                LineExpectations.drawn(bresenham, 11, 10, 13, 10, 20));
    }

    /**
     * The course's program's rule rounds the ends' major coordinates (the
     * DDA's pixel count and start end), not their minor ones: from (0, 0) to
     * (10, 3.4) it follows the slope 0.34 and steps at x = 8 (2.72) where the
     * DDA and SPEC's rule, on the rounded (10, 3), keep (2.4).
     */
    @Test
    void theCoursesRuleTakesTheMinorCoordinatesAsGiven() {
        List<String> drawn = LineExpectations.drawn(course, 0, 0, 10, 3.4, 20);
        assertEquals(List.of("0,0", "1,0", "2,1", "3,1", "4,1", "5,2", "6,2", "7,2", "8,3", "9,3", "10,3"), drawn);
        List<String> byDda = LineExpectations.drawn(dda, 0, 0, 10, 3.4, 20);
        assertEquals("8,2", byDda.get(8));
        assertEquals(drawn.subList(0, 8), byDda.subList(0, 8));
        assertEquals("8,2", LineExpectations.drawn(bresenham, 0, 0, 10, 3.4, 20).get(8));
        assertEquals(List.of("11,10", "12,10", "13,10"), LineExpectations.drawn(course, 10.5, 10.2, 12.7, 9.5, 20));
    }

    /**
     * The course's 92-degree spoke, (150, 150) to (145.289, 284.918): on the
     * line through the given ends it moves from column 146 to 145 at row 279,
     * as in the course's page 1 panel 2; through the rounded (145, 285), as
     * the DDA and SPEC's rule go, at row 272.
     */
    @Test
    void theCoursesNinetyTwoDegreeSpoke() {
        double ex = 150 + 135 * Math.cos(Math.toRadians(92));
        double ey = 150 + 135 * Math.sin(Math.toRadians(92));
        List<String> bySpec = LineExpectations.drawn(bresenham, 150, 150, ex, ey, 300);
        assertEquals("146,271", bySpec.get(271 - 150));
        assertEquals("145,272", bySpec.get(272 - 150));
        List<String> drawn = LineExpectations.drawn(course, 150, 150, ex, ey, 300);
        assertEquals("146,278", drawn.get(278 - 150));
        assertEquals("145,279", drawn.get(279 - 150));
        List<String> byDda = LineExpectations.drawn(dda, 150, 150, ex, ey, 300);
        assertEquals("146,271", byDda.get(271 - 150));
        assertEquals("145,272", byDda.get(272 - 150));
        assertEquals(LineExpectations.bresenham(150, 150, ex, ey), drawn);
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
     * The tie rule, the course's page 1 panel 2's (its 60-degree spoke, whose
     * end is x = 217.5: five exact ties, all kept): at an exact tie Bresenham
     * keeps the minor coordinate, on the start's side. On a 2:1 line rising
     * from (0, 0) it keeps row 0 where the DDA rounds 0.5 up to 1; on the
     * falling 2:-1 line from (0, 5) both keep row 5.
     */
    @Test
    void atATieBresenhamKeepsAndDiffersFromTheDdaOnRisingLines() {
        assertEquals(List.of("0,0", "1,0", "2,1"), LineExpectations.drawn(bresenham, 0, 0, 2, 1, 10));
        assertEquals(List.of("0,0", "1,1", "2,1"), LineExpectations.drawn(dda, 0, 0, 2, 1, 10));
        assertEquals(List.of("0,5", "1,5", "2,4"), LineExpectations.drawn(bresenham, 0, 5, 2, 4, 10));
        assertEquals(LineExpectations.drawn(dda, 0, 5, 2, 4, 10), LineExpectations.drawn(bresenham, 0, 5, 2, 4, 10));
        // y-major: the same, x rising or falling from the smaller-y end.
        assertEquals(List.of("0,0", "0,1", "1,2"), LineExpectations.drawn(bresenham, 0, 0, 1, 2, 10));
        assertEquals(List.of("5,0", "5,1", "4,2"), LineExpectations.drawn(bresenham, 5, 0, 4, 2, 10));
    }

    /**
     * Under the course's rule an end whose minor coordinate lies exactly
     * half-way is a tie too: (0, 0) to (10, 2.5) ends at (10, 2), not at the
     * rounded (10, 3) where the DDA and SPEC's rule end; as the course's
     * 60-degree spoke ends at (217, 267).
     */
    @Test
    void anEndHalfWayBetweenTwoPixelsIsKeptOnTheStartsSide() {
        assertEquals("10,3", LineExpectations.drawn(bresenham, 0, 0, 10, 2.5, 20).get(10));
        List<String> drawn = LineExpectations.drawn(course, 0, 0, 10, 2.5, 20);
        assertEquals("10,2", drawn.get(10));
        assertEquals("10,3", LineExpectations.drawn(dda, 0, 0, 10, 2.5, 20).get(10));
        assertEquals(LineExpectations.bresenham(0, 0, 10, 2.5), drawn);
    }

    /**
     * Ends on an eighth-pixel grid (so every decision is exact in doubles, and
     * ties are frequent), in every octant, from either end, some steeper than
     * their rounded octant: the exact reference, pixel for pixel.
     */
    @Test
    void anyEndsHitTheExactPixels() {
        Random random = new Random(23);
        int ties = 0;
        for (int n = 0; n < 3000; n++) {
            double x0 = random.nextInt(8 * 60) / 8.0;
            double y0 = random.nextInt(8 * 60) / 8.0;
            double x1 = random.nextInt(8 * 60) / 8.0;
            double y1 = random.nextInt(8 * 60) / 8.0;
            List<String> expected = LineExpectations.bresenham(x0, y0, x1, y1);
            assertEquals(expected, LineExpectations.drawn(course, x0, y0, x1, y1, 64),
                    x0 + "," + y0 + " to " + x1 + "," + y1);
            assertEquals(LineExpectations.bresenham(round(x0), round(y0), round(x1), round(y1)),
                    LineExpectations.drawn(bresenham, x0, y0, x1, y1, 64), "SPEC's, " + x0 + "," + y0 + " to " + x1 + "," + y1);
            ties += LineExpectations.drawn(dda, x0, y0, x1, y1, 64).equals(expected) ? 0 : 1;
        }
        assertTrue(ties > 100, "the DDA differs on " + ties + " of them");
    }

    /**
     * Where the rule says the two must agree: every line on integer ends
     * without an exact tie. Where they may differ: at ties, where Bresenham
     * keeps (exactly) and the DDA's added-up minor coordinate lands on the
     * half or a last bit either side of it, then rounded half up; and on
     * other ends (above).
     */
    @Test
    void theDdaAndBresenhamAgreeOnIntegerEndsExceptAtTies() {
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
                assertEquals(LineExpectations.pixels(x0, y0, x1, y1, Tie.TOWARD_START), b, line);
                differing += a.equals(b) ? 0 : 1;
            }
        }
        assertTrue(differing > 0, "some line with a tie shows the difference");
    }

    @Test
    void aClippedLineMatchesTheWholeOne() {
        for (double[] ends : new double[][] {{-40, -13, 90, 71}, {-40.375, -13.25, 90.125, 70.625}}) {
            List<String> whole = LineExpectations.drawn(bresenham, ends[0], ends[1], ends[2], ends[3], 400);
            RecordingDrawable small = new RecordingDrawable(50, 50);
            bresenham.drawLine(Vertex.of(ends[0], ends[1], -1), Vertex.of(ends[2], ends[3], -1), small);
            List<String> part = small.writes().stream().map(w -> w.x() + "," + w.y()).toList();
            assertEquals(whole.stream().filter(p -> Integer.parseInt(p.split(",")[0]) < 50
                    && Integer.parseInt(p.split(",")[1]) < 50).toList(), part);
        }
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
        bresenham.drawLine(Vertex.of(0x1p51, 1, 0), Vertex.of(5, 5, 0), e);
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

    /** More hidden steps than the walk takes one by one: it jumps, onto the exact pixels, ties included. */
    @Test
    void jumpingFarAheadLandsOnTheExactPixels() {
        double x0 = -3_000_000.375;
        double y0 = 0.25;
        double x1 = 2999.625;
        double y1 = 750_600.5;
        for (BresenhamLineRenderer walk : List.of(course, bresenham)) {
            RecordingDrawable window = new RecordingDrawable(3000, 760_000);
            walk.drawLine(Vertex.of(x0, y0, -1), Vertex.of(x1, y1, -1), window);
            List<String> drawn = window.writes().stream().map(w -> w.x() + "," + w.y()).toList();
            assertEquals(3000, drawn.size());
            for (int x = 0; x < 3000; x += 1) {
                String expected = walk == course ? LineExpectations.bresenhamAt(x0, y0, x1, y1, x)
                        : LineExpectations.bresenhamAt(round(x0), round(y0), round(x1), round(y1), x);
                assertEquals(expected, drawn.get(x), "x " + x);
            }
            assertNotEquals(drawn.get(0), drawn.get(2999));
        }
    }
}

package simpview.raster;

import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.ArrayList;
import java.util.List;
import simpview.geometry.Vertex;
import simpview.testing.RecordingDrawable;

/**
 * What a line on integer endpoints must light, worked out exactly (integer
 * arithmetic, no doubles): from the smaller-x end of an x-major line (|dx| >=
 * |dy|) or the smaller-y end of a y-major one, at step k the minor coordinate
 * is the start's plus k dy / dx rounded to the nearest integer, a tie going
 * toward +minor ("half up") or toward the start's minor ("half toward start").
 */
final class LineExpectations {

    /** How an exact tie k dy / dx = n + 1/2 is rounded. */
    enum Tie { HALF_UP, AWAY_FROM_START, TOWARD_START }

    private LineExpectations() {
    }

    /** The pixels, in drawing order, as "x,y". */
    static List<String> pixels(int x0, int y0, int x1, int y1, Tie tie) {
        boolean xMajor = Math.abs(x1 - x0) >= Math.abs(y1 - y0);
        boolean swap = xMajor ? x1 < x0 : y1 < y0;
        int ax = swap ? x1 : x0;
        int ay = swap ? y1 : y0;
        int bx = swap ? x0 : x1;
        int by = swap ? y0 : y1;
        long steps = xMajor ? bx - ax : by - ay;
        long rise = xMajor ? by - ay : bx - ax;
        List<String> out = new ArrayList<>();
        for (long k = 0; k <= steps; k++) {
            long offset = steps == 0 ? 0 : rounded(k * rise, steps, tie);
            long x = xMajor ? ax + k : ax + offset;
            long y = xMajor ? ay + offset : ay + k;
            out.add(x + "," + y);
        }
        return out;
    }

    /** Whether some step of the line falls exactly on a tie. */
    static boolean hasTie(int x0, int y0, int x1, int y1) {
        long dx = Math.abs(x1 - x0);
        long dy = Math.abs(y1 - y0);
        long steps = Math.max(dx, dy);
        long rise = Math.min(dx, dy);
        for (long k = 0; k <= steps; k++) {
            if (steps != 0 && (2 * k * rise) % (2 * steps) == steps) {
                return true;
            }
        }
        return false;
    }

    /** num / den (den > 0) to the nearest integer, ties by the rule. */
    private static long rounded(long num, long den, Tie tie) {
        long twice = Math.floorDiv(2 * num + den, 2 * den); // floor(q + 1/2): half up
        boolean isTie = Math.floorMod(2 * num, 2 * den) == den;
        if (!isTie) {
            return twice;
        }
        return switch (tie) {
            case HALF_UP -> twice;
            case AWAY_FROM_START -> num >= 0 ? twice : twice - 1;
            case TOWARD_START -> num >= 0 ? twice - 1 : twice;
        };
    }

    /**
     * Bresenham's pixels on any endpoints, worked out exactly (decimal
     * arithmetic on the doubles' exact values): the ends' major coordinates
     * rounded half up, from the smaller one; the start pixel's minor
     * coordinate rounded half up; at step k the minor coordinate of the line
     * through the ends' given minor coordinates, {@code b0 + k (b1 - b0) / n},
     * rounded to the nearest integer, a tie toward the start's side, and
     * held to the last pixel's or one beyond it (a midpoint walk never steps
     * back, nor by two: that matters only where the given ends are steeper
     * than the rounded ones' octant). The major axis is the rounded ends'
     * longer one.
     */
    static List<String> bresenham(double x0, double y0, double x1, double y1) {
        Ends ends = Ends.of(x0, y0, x1, y1);
        long startPixel = ends.b0.add(new BigDecimal("0.5")).setScale(0, RoundingMode.FLOOR).longValueExact();
        List<String> out = new ArrayList<>();
        long minor = startPixel;
        for (long k = 0; k <= ends.n; k++) {
            if (k > 0) {
                long nearest = ends.nearest(k);
                minor = ends.rising() ? Math.min(minor + 1, Math.max(minor, nearest))
                        : Math.max(minor - 1, Math.min(minor, nearest));
            }
            out.add(ends.pixel(ends.a0 + k, minor));
        }
        return out;
    }

    /**
     * Bresenham's pixel at major coordinate {@code major} of a line whose given
     * ends are no steeper than the rounded ones' octant (so nothing holds it
     * back): the nearest integer to the line's minor coordinate there, a tie
     * toward the start; as "x,y". For lines too long to list.
     */
    static String bresenhamAt(double x0, double y0, double x1, double y1, long major) {
        Ends ends = Ends.of(x0, y0, x1, y1);
        return ends.pixel(major, ends.nearest(major - ends.a0));
    }

    /**
     * A line's ends as Bresenham's references see them: the ends rounded
     * half up; the major axis the rounded ends' longer one, from the smaller
     * rounded major coordinate a0 over n steps; the minor coordinates b0 and
     * b1 as given, exactly.
     */
    private record Ends(boolean xMajor, long a0, long n, BigDecimal b0, BigDecimal b1) {

        static Ends of(double x0, double y0, double x1, double y1) {
            long rx0 = (long) Math.floor(x0 + 0.5);
            long ry0 = (long) Math.floor(y0 + 0.5);
            long rx1 = (long) Math.floor(x1 + 0.5);
            long ry1 = (long) Math.floor(y1 + 0.5);
            boolean xMajor = Math.abs(rx1 - rx0) >= Math.abs(ry1 - ry0);
            boolean swap = xMajor ? rx1 < rx0 : ry1 < ry0;
            long a0 = xMajor ? (swap ? rx1 : rx0) : (swap ? ry1 : ry0);
            long n = Math.abs(xMajor ? rx1 - rx0 : ry1 - ry0);
            BigDecimal b0 = new BigDecimal(xMajor ? (swap ? y1 : y0) : (swap ? x1 : x0));
            BigDecimal b1 = new BigDecimal(xMajor ? (swap ? y0 : y1) : (swap ? x0 : x1));
            return new Ends(xMajor, a0, n, b0, b1);
        }

        boolean rising() {
            return b1.compareTo(b0) >= 0;
        }

        /**
         * The integer nearest the line's minor coordinate at step k,
         * {@code b0 + k (b1 - b0) / n}, exactly, a tie toward the start: rising,
         * ceil(v - 1/2); falling, floor(v + 1/2).
         */
        long nearest(long k) {
            BigDecimal bigN = BigDecimal.valueOf(n);
            // n times the line's minor coordinate at step k.
            BigDecimal at = b0.multiply(bigN).add(b1.subtract(b0).multiply(BigDecimal.valueOf(k)));
            BigDecimal halfN = new BigDecimal("0.5").multiply(bigN);
            return rising() ? at.subtract(halfN).divide(bigN, 0, RoundingMode.CEILING).longValueExact()
                    : at.add(halfN).divide(bigN, 0, RoundingMode.FLOOR).longValueExact();
        }

        /** Pixel (major, minor) as "x,y". */
        String pixel(long major, long minor) {
            return xMajor ? major + "," + minor : minor + "," + major;
        }
    }

    /** What the renderer wrote, in order, as "x,y". */
    static List<String> drawn(LineRenderer renderer, double x0, double y0, double x1, double y1, int size) {
        RecordingDrawable d = new RecordingDrawable(size, size);
        renderer.drawLine(Vertex.of(x0, y0, -1), Vertex.of(x1, y1, -1), d);
        List<String> out = new ArrayList<>();
        for (RecordingDrawable.Write w : d.writes()) {
            out.add(w.x() + "," + w.y());
        }
        return out;
    }
}

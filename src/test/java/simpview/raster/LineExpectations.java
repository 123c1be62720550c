package simpview.raster;

import java.util.ArrayList;
import java.util.List;
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

    /** What the renderer wrote, in order, as "x,y". */
    static List<String> drawn(LineRenderer renderer, double x0, double y0, double x1, double y1, int size) {
        RecordingDrawable d = new RecordingDrawable(size, size);
        renderer.drawLine(simpview.geometry.Vertex.of(x0, y0, -1), simpview.geometry.Vertex.of(x1, y1, -1), d);
        List<String> out = new ArrayList<>();
        for (RecordingDrawable.Write w : d.writes()) {
            out.add(w.x() + "," + w.y());
        }
        return out;
    }
}

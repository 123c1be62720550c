package simpview.robustness;

import java.math.BigDecimal;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.Tuple;
import simpview.geometry.Vertex;

/** Generators of hostile panel-space geometry, and exact arithmetic to judge it by. */
final class Hostile {

    private Hostile() {
    }

    /**
     * A coordinate for a drawable about {@code size} pixels across: mostly
     * near it (plain, on pixel centres, on pixel corners), often huge (up to
     * +-1e12), now and then a value at an int boundary, a tiny one, -0 or a
     * non-finite one.
     */
    static Arbitrary<Double> coordinate(int size) {
        return Arbitraries.frequencyOf(
                Tuple.of(30, Arbitraries.doubles().between(-size / 4.0, size * 1.25).ofScale(6)),
                Tuple.of(10, Arbitraries.integers().between(-size / 4, size * 5 / 4).map(i -> i + 0.5)),
                Tuple.of(10, Arbitraries.integers().between(-size / 4, size * 5 / 4).map(i -> (double) i)),
                Tuple.of(20, Arbitraries.doubles().between(-1e12, 1e12)),
                Tuple.of(6, Arbitraries.of(1e12, -1e12, 1e9, -1e9, 2147483647.5, -2147483648.5, 4294967296.0,
                        0.0, -0.0, Double.MIN_VALUE, -1e-300, 0.4999999999999999, 0.5000000000000001)),
                Tuple.of(4, Arbitraries.of(Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY)));
    }

    /** A depth: mostly inside the view volume, sometimes just outside it, huge, or not finite. */
    static Arbitrary<Double> depth() {
        return Arbitraries.frequencyOf(
                Tuple.of(60, Arbitraries.doubles().between(-200, 0).ofScale(6)),
                Tuple.of(20, Arbitraries.doubles().between(-260, 60)),
                Tuple.of(10, Arbitraries.of(0.0, -0.0, -200.0, 1e-9, -200.0000001, 1e12, -1e12)),
                Tuple.of(5, Arbitraries.doubles().between(-1e300, 1e300)),
                Tuple.of(5, Arbitraries.of(Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY)));
    }

    /** A colour channel: mostly in [0, 1], sometimes out of range or not finite. */
    static Arbitrary<Double> channel() {
        return Arbitraries.frequencyOf(
                Tuple.of(85, Arbitraries.doubles().between(0, 1).ofScale(6)),
                Tuple.of(10, Arbitraries.doubles().between(-5, 5)),
                Tuple.of(5, Arbitraries.of(Double.NaN, Double.POSITIVE_INFINITY, -1e300)));
    }

    static Arbitrary<Vertex> vertex(int size) {
        return Combinators.combine(coordinate(size), coordinate(size), depth(), channel(), channel(), channel())
                .as(Vertex::new);
    }

    /**
     * Three vertices: unrelated, or with a repeated vertex, collinear, with a
     * horizontal or vertical edge, or all inside one pixel.
     */
    static Arbitrary<Vertex[]> triangle(int size) {
        Arbitrary<Vertex> v = vertex(size);
        Arbitrary<Vertex[]> free = Combinators.combine(v, v, v).as((a, b, c) -> new Vertex[] {a, b, c});
        Arbitrary<Vertex[]> repeated = Combinators.combine(v, v).as((a, b) -> new Vertex[] {a, b, a});
        Arbitrary<Vertex[]> collinear = Combinators.combine(v, v, Arbitraries.doubles().between(-3, 3))
                .as((a, b, t) -> new Vertex[] {a, b, a.withPosition(a.x() + t * (b.x() - a.x()),
                        a.y() + t * (b.y() - a.y()), a.z())});
        Arbitrary<Vertex[]> horizontal = Combinators.combine(v, v, v)
                .as((a, b, c) -> new Vertex[] {a, b.withPosition(b.x(), a.y(), b.z()), c});
        Arbitrary<Vertex[]> vertical = Combinators.combine(v, v, v)
                .as((a, b, c) -> new Vertex[] {a, b.withPosition(a.x(), b.y(), b.z()), c});
        Arbitrary<Double> inPixel = Arbitraries.doubles().between(0, 0.999).ofScale(6);
        Arbitrary<Vertex[]> subPixel = Combinators.combine(v, inPixel, inPixel, inPixel, inPixel, inPixel, inPixel)
                .as((a, x1, y1, x2, y2, x3, y3) -> {
                    double bx = Math.floor(a.x());
                    double by = Math.floor(a.y());
                    return new Vertex[] {a.withPosition(bx + x1, by + y1, a.z()),
                        a.withPosition(bx + x2, by + y2, a.z()), a.withPosition(bx + x3, by + y3, a.z())};
                });
        return Arbitraries.frequencyOf(Tuple.of(40, free), Tuple.of(10, repeated), Tuple.of(15, collinear),
                Tuple.of(10, horizontal), Tuple.of(10, vertical), Tuple.of(15, subPixel));
    }

    static boolean finite(Vertex... vs) {
        for (Vertex v : vs) {
            if (!v.isFinite()) {
                return false;
            }
        }
        return true;
    }

    /** The exact sign of the cross product (b - a) x (p - a); all inputs finite. */
    static int orientation(double ax, double ay, double bx, double by, double px, double py) {
        BigDecimal abx = new BigDecimal(bx).subtract(new BigDecimal(ax));
        BigDecimal aby = new BigDecimal(by).subtract(new BigDecimal(ay));
        BigDecimal apx = new BigDecimal(px).subtract(new BigDecimal(ax));
        BigDecimal apy = new BigDecimal(py).subtract(new BigDecimal(ay));
        return abx.multiply(apy).subtract(aby.multiply(apx)).signum();
    }

    static int orientation(Vertex a, Vertex b, double px, double py) {
        return orientation(a.x(), a.y(), b.x(), b.y(), px, py);
    }

    /**
     * Whether the point lies inside the triangle by the top-left rule, decided
     * exactly: strictly inside, or on an edge whose interior lies to the right
     * or below, i.e. the point moved right by an infinitesimal and down by a
     * far smaller one lies strictly inside. False for a degenerate triangle.
     */
    static boolean coversExactly(Vertex p1, Vertex p2, Vertex p3, double px, double py) {
        int winding = orientation(p1, p2, p3.x(), p3.y());
        if (winding == 0) {
            return false;
        }
        Vertex[] t = winding > 0 ? new Vertex[] {p1, p2, p3} : new Vertex[] {p1, p3, p2};
        for (int e = 0; e < 3; e++) {
            Vertex a = t[e];
            Vertex b = t[(e + 1) % 3];
            int side = orientation(a, b, px, py);
            if (side < 0) {
                return false;
            }
            if (side == 0) {
                double dx = b.x() - a.x();
                double dy = b.y() - a.y();
                boolean topLeft = dy < 0 || (dy == 0 && dx < 0);
                if (!topLeft) {
                    return false;
                }
            }
        }
        return true;
    }
}

package simpview.geometry;

import java.util.Arrays;

/**
 * An immutable 4x4 matrix acting on column vectors (p' = M p). SIMP's
 * transformations compose on the right, {@code ctm = ctm.times(m)}, so the
 * last transformation named in a file is the first applied to a point.
 */
public final class Matrix4 {

    private static final Matrix4 IDENTITY = new Matrix4(new double[] {
        1, 0, 0, 0,
        0, 1, 0, 0,
        0, 0, 1, 0,
        0, 0, 0, 1});

    /** Row-major: m[4 * row + column]. */
    private final double[] m;

    private Matrix4(double[] rowMajor) {
        this.m = rowMajor;
    }

    public static Matrix4 identity() {
        return IDENTITY;
    }

    public static Matrix4 translation(double tx, double ty, double tz) {
        return new Matrix4(new double[] {
            1, 0, 0, tx,
            0, 1, 0, ty,
            0, 0, 1, tz,
            0, 0, 0, 1});
    }

    public static Matrix4 scaling(double sx, double sy, double sz) {
        return new Matrix4(new double[] {
            sx, 0, 0, 0,
            0, sy, 0, 0,
            0, 0, sz, 0,
            0, 0, 0, 1});
    }

    /**
     * Right-handed rotation: counter-clockwise when looking from +axis toward
     * the origin. Quarter turns are exact, so an axis-aligned cube stays
     * axis-aligned to the last bit instead of picking up 6e-17 slivers; other
     * angles use StrictMath so a scene renders to the same bits on every JVM.
     */
    public static Matrix4 rotation(Axis axis, double degrees) {
        if (Math.abs(degrees) >= WHOLE_DEGREES_ONLY) {
            // so large an angle holds no fraction of a degree, and toRadians of it keeps nothing of where it
            // points: it turns as its remainder mod 360 (exact) does. No smaller angle is touched, so every
            // rotation a scene could sensibly hold keeps its bits
            degrees %= 360;
        }
        double c = exactCos(degrees);
        double s = exactSin(degrees);
        double[] r = switch (axis) {
            case X -> new double[] {
                1, 0, 0, 0,
                0, c, -s, 0,
                0, s, c, 0,
                0, 0, 0, 1};
            case Y -> new double[] {
                c, 0, s, 0,
                0, 1, 0, 0,
                -s, 0, c, 0,
                0, 0, 0, 1};
            case Z -> new double[] {
                c, -s, 0, 0,
                s, c, 0, 0,
                0, 0, 1, 0,
                0, 0, 0, 1};
        };
        return new Matrix4(r);
    }

    private static double exactCos(double degrees) {
        // the quarter turn a quarter ahead, from the exact remainder: degrees + 90 rounds away the 90 of a huge
        // angle (1e300 + 90 == 1e300), which made a cosine of 0 beside a sine of 0
        double quarter = quarterTurn(degrees % 360 + 90);
        return Double.isNaN(quarter) ? StrictMath.cos(StrictMath.toRadians(degrees)) : quarter;
    }

    private static double exactSin(double degrees) {
        double quarter = quarterTurn(degrees);
        return Double.isNaN(quarter) ? StrictMath.sin(StrictMath.toRadians(degrees)) : quarter;
    }

    /** From 2^52 degrees up, a double holds whole degrees only (its ulp is 1 or more). */
    private static final double WHOLE_DEGREES_ONLY = 0x1p52;

    /** sin of a whole number of quarter turns, exactly; NaN for any other angle. */
    private static double quarterTurn(double degrees) {
        double d = degrees % 360;
        if (d < 0) {
            d += 360;
        }
        if (d == 0 || d == 180) {
            return 0;
        }
        if (d == 90) {
            return 1;
        }
        return d == 270 ? -1 : Double.NaN;
    }

    /** this * other. */
    public Matrix4 times(Matrix4 other) {
        double[] a = m;
        double[] b = other.m;
        double[] p = new double[16];
        for (int row = 0; row < 4; row++) {
            for (int col = 0; col < 4; col++) {
                p[4 * row + col] = a[4 * row] * b[col]
                        + a[4 * row + 1] * b[4 + col]
                        + a[4 * row + 2] * b[8 + col]
                        + a[4 * row + 3] * b[12 + col];
            }
        }
        return new Matrix4(p);
    }

    /** What {@link #invert} gives for a matrix whose inverse holds numbers beyond the doubles. */
    private static final double[] OVERFLOWS = new double[0];

    /**
     * The inverse, by Gauss-Jordan elimination with partial pivoting; null
     * when this matrix cannot be inverted (a zero pivot, or a result that is
     * not finite: see {@link #inverseOverflows}).
     */
    public Matrix4 inverse() {
        double[] inv = invert();
        return inv == null || inv == OVERFLOWS ? null : new Matrix4(inv);
    }

    /**
     * True when this matrix has no {@link #inverse} because the inverse's
     * numbers are beyond the doubles (a scale of 1e-310 inverts to 1e310),
     * not because it is singular (a scale of 0): a message tells which.
     */
    public boolean inverseOverflows() {
        return invert() == OVERFLOWS;
    }

    /** The inverse's entries, row-major; null for a zero pivot, {@link #OVERFLOWS} for a result that is not finite. */
    private double[] invert() {
        double[] a = m.clone();
        double[] inv = IDENTITY.m.clone();
        for (int col = 0; col < 4; col++) {
            int pivot = col;
            for (int row = col + 1; row < 4; row++) {
                if (Math.abs(a[4 * row + col]) > Math.abs(a[4 * pivot + col])) {
                    pivot = row;
                }
            }
            double p = a[4 * pivot + col];
            if (p == 0) {
                return null;
            }
            if (!Double.isFinite(p)) {
                return OVERFLOWS;
            }
            swapRows(a, col, pivot);
            swapRows(inv, col, pivot);
            for (int k = 0; k < 4; k++) {
                a[4 * col + k] /= p;
                inv[4 * col + k] /= p;
            }
            for (int row = 0; row < 4; row++) {
                double f = a[4 * row + col];
                if (row != col && f != 0) {
                    for (int k = 0; k < 4; k++) {
                        a[4 * row + k] -= f * a[4 * col + k];
                        inv[4 * row + k] -= f * inv[4 * col + k];
                    }
                }
            }
        }
        for (double v : inv) {
            if (!Double.isFinite(v)) {
                return OVERFLOWS;
            }
        }
        return inv;
    }

    private static void swapRows(double[] a, int r, int s) {
        if (r != s) {
            for (int k = 0; k < 4; k++) {
                double t = a[4 * r + k];
                a[4 * r + k] = a[4 * s + k];
                a[4 * s + k] = t;
            }
        }
    }

    /**
     * The matrix that takes normals along with this one's points: the inverse
     * transpose of the upper-left 3x3 part, with no translation. Where that
     * part is singular (a scale of 0 flattened the object) the cofactor
     * matrix stands in: the same directions wherever they are defined.
     */
    public Matrix4 normalTransform() {
        double a = m[0], b = m[1], c = m[2];
        double d = m[4], e = m[5], f = m[6];
        double g = m[8], h = m[9], i = m[10];
        // Cofactors: the inverse transpose is cof / det.
        double c00 = e * i - f * h, c01 = f * g - d * i, c02 = d * h - e * g;
        double c10 = c * h - b * i, c11 = a * i - c * g, c12 = b * g - a * h;
        double c20 = b * f - c * e, c21 = c * d - a * f, c22 = a * e - b * d;
        double det = a * c00 + b * c01 + c * c02;
        double s = det != 0 && Double.isFinite(1 / det) ? 1 / det : 1;
        return new Matrix4(new double[] {
            s * c00, s * c01, s * c02, 0,
            s * c10, s * c11, s * c12, 0,
            s * c20, s * c21, s * c22, 0,
            0, 0, 0, 1});
    }

    /** Transforms the point (w = 1) and keeps the vertex's colour. */
    public Vertex apply(Vertex v) {
        return v.withPosition(applyX(v.x(), v.y(), v.z()), applyY(v.x(), v.y(), v.z()),
                applyZ(v.x(), v.y(), v.z()));
    }

    public double applyX(double x, double y, double z) {
        return m[0] * x + m[1] * y + m[2] * z + m[3];
    }

    public double applyY(double x, double y, double z) {
        return m[4] * x + m[5] * y + m[6] * z + m[7];
    }

    public double applyZ(double x, double y, double z) {
        return m[8] * x + m[9] * y + m[10] * z + m[11];
    }

    /** True when every entry is a finite number: neither infinite nor NaN. */
    public boolean isFinite() {
        for (double v : m) {
            if (!Double.isFinite(v)) {
                return false;
            }
        }
        return true;
    }

    /**
     * The first entry, row by row, that is infinite or NaN, for a message;
     * call only when not {@link #isFinite()}. An Infinity is named before a
     * NaN, which an Infinity made (Infinity minus Infinity, or times 0).
     */
    public double firstNonFinite() {
        boolean nan = false;
        for (double v : m) {
            if (Double.isInfinite(v)) {
                return v;
            }
            nan |= Double.isNaN(v);
        }
        if (!nan) {
            throw new IllegalStateException("every entry is finite: " + this);
        }
        return Double.NaN;
    }

    public double get(int row, int column) {
        return m[4 * row + column];
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Matrix4 other && Arrays.equals(m, other.m);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(m);
    }

    @Override
    public String toString() {
        StringBuilder sb = new StringBuilder("Matrix4[");
        for (int row = 0; row < 4; row++) {
            sb.append(row == 0 ? "" : "; ");
            for (int col = 0; col < 4; col++) {
                sb.append(col == 0 ? "" : " ").append(m[4 * row + col]);
            }
        }
        return sb.append(']').toString();
    }
}

package simpview.reference;

/**
 * The reference's own 4x4 matrices (row-major double[4][4], points as
 * columns) and 3-vectors (double[3]), written the textbook way. Nothing here
 * comes from simpview.
 */
final class RefMatrix {

    private RefMatrix() {
    }

    static double[][] identity() {
        return scale(1, 1, 1);
    }

    static double[][] scale(double sx, double sy, double sz) {
        return new double[][] {{sx, 0, 0, 0}, {0, sy, 0, 0}, {0, 0, sz, 0}, {0, 0, 0, 1}};
    }

    static double[][] translate(double tx, double ty, double tz) {
        return new double[][] {{1, 0, 0, tx}, {0, 1, 0, ty}, {0, 0, 1, tz}, {0, 0, 0, 1}};
    }

    /** Counter-clockwise looking from +axis toward the origin. */
    static double[][] rotate(char axis, double degrees) {
        double c = Math.cos(Math.toRadians(degrees));
        double s = Math.sin(Math.toRadians(degrees));
        return switch (axis) {
            case 'X' -> new double[][] {{1, 0, 0, 0}, {0, c, -s, 0}, {0, s, c, 0}, {0, 0, 0, 1}};
            case 'Y' -> new double[][] {{c, 0, s, 0}, {0, 1, 0, 0}, {-s, 0, c, 0}, {0, 0, 0, 1}};
            case 'Z' -> new double[][] {{c, -s, 0, 0}, {s, c, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
            default -> throw new IllegalArgumentException("reference: bad axis " + axis);
        };
    }

    static double[][] times(double[][] a, double[][] b) {
        double[][] p = new double[4][4];
        for (int r = 0; r < 4; r++) {
            for (int c = 0; c < 4; c++) {
                for (int k = 0; k < 4; k++) {
                    p[r][c] += a[r][k] * b[k][c];
                }
            }
        }
        return p;
    }

    static double[] point(double[][] m, double[] p) {
        double[] out = new double[3];
        for (int r = 0; r < 3; r++) {
            out[r] = m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2] + m[r][3];
        }
        return out;
    }

    /** Gauss-Jordan elimination with partial pivoting; null when singular. */
    static double[][] inverse(double[][] m) {
        double[][] a = new double[4][8];
        for (int r = 0; r < 4; r++) {
            System.arraycopy(m[r], 0, a[r], 0, 4);
            a[r][4 + r] = 1;
        }
        for (int col = 0; col < 4; col++) {
            int pivot = col;
            for (int r = col + 1; r < 4; r++) {
                if (Math.abs(a[r][col]) > Math.abs(a[pivot][col])) {
                    pivot = r;
                }
            }
            if (Math.abs(a[pivot][col]) < 1e-12) {
                return null;
            }
            double[] t = a[col];
            a[col] = a[pivot];
            a[pivot] = t;
            double d = a[col][col];
            for (int c = 0; c < 8; c++) {
                a[col][c] /= d;
            }
            for (int r = 0; r < 4; r++) {
                if (r != col && a[r][col] != 0) {
                    double f = a[r][col];
                    for (int c = 0; c < 8; c++) {
                        a[r][c] -= f * a[col][c];
                    }
                }
            }
        }
        double[][] inv = new double[4][4];
        for (int r = 0; r < 4; r++) {
            System.arraycopy(a[r], 4, inv[r], 0, 4);
        }
        return inv;
    }

    /** The inverse transpose of m's upper-left 3x3, by cofactors (the adjugate's transpose over the determinant). */
    static double[][] normalMatrix(double[][] m) {
        double[][] cof = new double[3][3];
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                int r1 = (r + 1) % 3;
                int r2 = (r + 2) % 3;
                int c1 = (c + 1) % 3;
                int c2 = (c + 2) % 3;
                cof[r][c] = m[r1][c1] * m[r2][c2] - m[r1][c2] * m[r2][c1];
            }
        }
        double det = m[0][0] * cof[0][0] + m[0][1] * cof[0][1] + m[0][2] * cof[0][2];
        for (double[] row : cof) {
            for (int c = 0; c < 3; c++) {
                row[c] /= det;
            }
        }
        return cof;
    }

    static double[] times3(double[][] m, double[] v) {
        return new double[] {
            m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
            m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
            m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
    }

    static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    static double[] minus(double[] a, double[] b) {
        return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }

    static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    static double length(double[] v) {
        return Math.sqrt(dot(v, v));
    }

    /** v made unit length; the zero vector stays zero. */
    static double[] unit(double[] v) {
        double len = length(v);
        return len == 0 ? new double[3] : new double[] {v[0] / len, v[1] / len, v[2] / len};
    }
}

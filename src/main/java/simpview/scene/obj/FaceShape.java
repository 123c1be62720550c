package simpview.scene.obj;

import java.math.BigDecimal;

/**
 * Two shapes of a face of four vertices or more that SPEC draws otherwise
 * than its outline suggests, for the reader's warnings: its first three
 * vertices on one line (SPEC's face normal, (p2 - p1) x (p3 - p1), is then
 * zero or made of rounding errors), and a face whose fan from its first vertex
 * (how SPEC fills a face) covers more or other than its outline: only some
 * faces that are not convex, as the fan from a vertex that sees the whole
 * face is exact (a quad only when it is flat: a twisted one's fan is the
 * course's own way).
 * Positions are three doubles a vertex; a face is its vertices' indices.
 * Both tests hold under any affine map, so the model's own coordinates tell
 * what the camera's would; a quad's flatness is measured in them.
 */
final class FaceShape {

    /**
     * How far out of its plane a quad may be and still be named for its fan, against its edges from the first
     * vertex: |u . (v x w)| at most this times |u| |v| |w|. The course's own dummy.obj holds ten quads whose
     * fan is not their outline, twisted out of plane (0.007 of that product), drawn as the course draws them;
     * a flat dart or arrowhead is a face a student made, and its fan shows the mistake. A quad written with
     * six decimals, as exporters write them, is flat to well within this.
     */
    private static final double FLAT_QUAD = 1e-4;

    /** How small, against the product of their lengths, a cross product of two edges counts as none. */
    private static final double IN_LINE = 1e-9;

    private FaceShape() {
    }

    /**
     * Whether the face of vertices refs[0] to refs[n - 1] has no area: they all lie on one line, or all coincide,
     * exactly, as the doubles given are. No tolerance: a sliver however thin against its length has an area, and
     * seen close enough it fills pixels. Each vertex is held against the line from the first to the first other
     * one ({@link #inLine}). A vertex or a difference of two beyond the doubles names nothing: such a face is drawn
     * or refused as such.
     */
    static boolean noArea(double[] p, int[] refs, int n) {
        int a = 3 * refs[0];
        int other = -1;
        int otherAt = n;
        for (int k = 1; k < n; k++) {
            int b = 3 * refs[k];
            boolean apart = false;
            for (int i = 0; i < 3; i++) {
                double d = p[b + i] - p[a + i];
                if (!Double.isFinite(d)) {
                    return false;
                }
                apart |= d != 0;
            }
            if (apart && other < 0) {
                other = b;
                otherAt = k;
            }
        }
        if (other < 0) {
            return true; // every vertex where the first is
        }
        // those before it are where the first vertex is, on any line through it
        for (int k = otherAt + 1; k < n; k++) {
            if (!inLine(p, a, other, 3 * refs[k])) {
                return false;
            }
        }
        return true;
    }

    /**
     * How much a cross product's component computed in doubles may differ from the exact one, against the sum of
     * its two products' sizes: a few roundings of the differences, the products and their difference, with room.
     */
    private static final double ROUNDING = 1e-14;

    /** Below this, a product of doubles may have lost its relative precision to underflow. */
    private static final double NORMAL = 1e-280;

    /**
     * Whether the points at p[a], p[b], p[c] (each three doubles) lie on one line, exactly: (b - a) x (c - a) is
     * zero. Computed in doubles where that tells for certain that it is not, or where every difference and
     * product in it is exact (then a component is zero exactly when its two products are equal: model
     * coordinates on a grid, such as integers, whose faces in line would otherwise each take the decimals, 60 %
     * of reading a model of five million such faces); else exactly, in decimals.
     */
    private static boolean inLine(double[] p, int a, int b, int c) {
        double ux = p[b] - p[a];
        double uy = p[b + 1] - p[a + 1];
        double uz = p[b + 2] - p[a + 2];
        double vx = p[c] - p[a];
        double vy = p[c + 1] - p[a + 1];
        double vz = p[c + 2] - p[a + 2];
        if (surelyNotZero(uy * vz, uz * vy) || surelyNotZero(uz * vx, ux * vz) || surelyNotZero(ux * vy, uy * vx)) {
            return false;
        }
        if (exactDifference(p[b], p[a], ux) && exactDifference(p[b + 1], p[a + 1], uy)
                && exactDifference(p[b + 2], p[a + 2], uz) && exactDifference(p[c], p[a], vx)
                && exactDifference(p[c + 1], p[a + 1], vy) && exactDifference(p[c + 2], p[a + 2], vz)
                && exactProduct(uy, vz) && exactProduct(uz, vy) && exactProduct(uz, vx) && exactProduct(ux, vz)
                && exactProduct(ux, vy) && exactProduct(uy, vx)) {
            return uy * vz == uz * vy && uz * vx == ux * vz && ux * vy == uy * vx;
        }
        BigDecimal[] u = new BigDecimal[3];
        BigDecimal[] v = new BigDecimal[3];
        for (int i = 0; i < 3; i++) {
            BigDecimal first = new BigDecimal(p[a + i]);
            u[i] = new BigDecimal(p[b + i]).subtract(first);
            v[i] = new BigDecimal(p[c + i]).subtract(first);
        }
        for (int i = 0; i < 3; i++) {
            int j = (i + 1) % 3;
            int k = (i + 2) % 3;
            if (u[j].multiply(v[k]).compareTo(u[k].multiply(v[j])) != 0) {
                return false;
            }
        }
        return true;
    }

    /**
     * Whether {@code d}, the double x - y (both finite, d finite), is x - y exactly: the rounding error of the
     * subtraction, found exactly by Knuth's TwoSum (which holds for any finite operands and sum), is zero.
     */
    static boolean exactDifference(double x, double y, double d) {
        double minusY = -y;
        double yPart = d - x;
        double xPart = d - yPart;
        return (x - xPart) + (minusY - yPart) == 0;
    }

    /**
     * Whether the double u * v is the product exactly: one of them is zero, or the fused u * v - (u * v), which
     * is the product's rounding error exactly when the product is well above underflow, is zero.
     */
    static boolean exactProduct(double u, double v) {
        if (u == 0 || v == 0) {
            return true;
        }
        double product = u * v;
        return Math.abs(product) >= SAFE_PRODUCT && Math.abs(product) <= Double.MAX_VALUE
                && Math.fma(u, v, -product) == 0;
    }

    /**
     * Above this, a product's rounding error is a double itself (a multiple of 2^-1074 for products of at least
     * 2^-969), so the fused multiply-add returns it exactly: zero only when there is none.
     */
    private static final double SAFE_PRODUCT = 0x1p-960;

    /** Whether {@code s - t}, both products of rounded differences, is surely not zero exactly. */
    private static boolean surelyNotZero(double s, double t) {
        double difference = Math.abs(s - t);
        return difference > NORMAL && difference > ROUNDING * (Math.abs(s) + Math.abs(t));
    }

    /** Whether vertices refs[0], refs[1], refs[2] lie on one line (or two of them coincide). */
    static boolean firstThreeInLine(double[] p, int[] refs) {
        int a = 3 * refs[0];
        int b = 3 * refs[1];
        int c = 3 * refs[2];
        double ux = p[b] - p[a];
        double uy = p[b + 1] - p[a + 1];
        double uz = p[b + 2] - p[a + 2];
        double vx = p[c] - p[a];
        double vy = p[c + 1] - p[a + 1];
        double vz = p[c + 2] - p[a + 2];
        double cx = uy * vz - uz * vy;
        double cy = uz * vx - ux * vz;
        double cz = ux * vy - uy * vx;
        double cross = cx * cx + cy * cy + cz * cz;
        double lengths = (ux * ux + uy * uy + uz * uz) * (vx * vx + vy * vy + vz * vz);
        return cross <= IN_LINE * IN_LINE * lengths;
    }

    /**
     * Whether the reader names the face of n vertices for its fan ({@link #fanMisdraws}): a face of five
     * vertices or more, or a flat quad ({@link #quadNamedForFan}); a triangle is its own fan.
     */
    static boolean namedForFan(double[] p, int[] refs, int n) {
        if (n == 4) {
            return quadNamedForFan(p, refs);
        }
        return n >= 5 && fanMisdraws(p, refs, n);
    }

    /**
     * Whether the quad refs[0] to refs[3] is named for its fan. With u, v and w its edges from the first vertex,
     * its fan triangles (0, 1, 2) and (0, 2, 3) have the normals u x v and v x w. When they turn the same way
     * (a positive dot product) they make up a flat quad's outline exactly: settled at once, as most quads are,
     * without {@link #fanMisdraws}. Otherwise the quad is named only when it is flat to within
     * {@link #FLAT_QUAD} (|u . (v x w)|, the volume its edges span) and its fan misdraws.
     */
    private static boolean quadNamedForFan(double[] p, int[] refs) {
        int o = 3 * refs[0];
        int a = 3 * refs[1];
        int b = 3 * refs[2];
        int c = 3 * refs[3];
        double ux = p[a] - p[o];
        double uy = p[a + 1] - p[o + 1];
        double uz = p[a + 2] - p[o + 2];
        double vx = p[b] - p[o];
        double vy = p[b + 1] - p[o + 1];
        double vz = p[b + 2] - p[o + 2];
        double wx = p[c] - p[o];
        double wy = p[c + 1] - p[o + 1];
        double wz = p[c + 2] - p[o + 2];
        double firstX = uy * vz - uz * vy;
        double firstY = uz * vx - ux * vz;
        double firstZ = ux * vy - uy * vx;
        double secondX = vy * wz - vz * wy;
        double secondY = vz * wx - vx * wz;
        double secondZ = vx * wy - vy * wx;
        if (firstX * secondX + firstY * secondY + firstZ * secondZ > 0) {
            return false;
        }
        double volume = ux * secondX + uy * secondY + uz * secondZ;
        double lengths = Math.sqrt((ux * ux + uy * uy + uz * uz) * (vx * vx + vy * vy + vz * vz))
                * Math.sqrt(wx * wx + wy * wy + wz * wz);
        return Math.abs(volume) <= FLAT_QUAD * lengths && fanMisdraws(p, refs, 4);
    }

    /**
     * Whether SPEC's fan from the first vertex fills otherwise than the face's outline: some fan triangle
     * (refs[0], refs[i], refs[i + 1]) turns against the face (Newell's normal, the sum over its edges), so it
     * covers what lies outside the outline (a star or an L fanned from a corner that does not see the whole
     * face), or the fan triangles wind round the first vertex more than once, so they overlap (a pentagram
     * in one stroke). Otherwise the triangles are disjoint and their union is exactly what the outline
     * encloses: their signed areas add up to the outline's winding number everywhere, and with none negative
     * and none overlapping that is 1 inside and 0 outside. So an L fanned from its outer corner or its notch
     * is not named, though it is not convex. A face with no area (Newell's normal nil) is not named either.
     */
    static boolean fanMisdraws(double[] p, int[] refs, int n) {
        double nx = 0;
        double ny = 0;
        double nz = 0;
        for (int i = 0; i < n; i++) {
            int a = 3 * refs[i];
            int b = 3 * refs[(i + 1) % n];
            nx += (p[a + 1] - p[b + 1]) * (p[a + 2] + p[b + 2]);
            ny += (p[a + 2] - p[b + 2]) * (p[a] + p[b]);
            nz += (p[a] - p[b]) * (p[a + 1] + p[b + 1]);
        }
        double normal = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (!(normal > 0)) {
            return false;
        }
        int o = 3 * refs[0];
        double swept = 0; // the fan triangles' angles at the first vertex, added up
        for (int i = 1; i + 1 < n; i++) {
            int b = 3 * refs[i];
            int c = 3 * refs[i + 1];
            double ux = p[b] - p[o];
            double uy = p[b + 1] - p[o + 1];
            double uz = p[b + 2] - p[o + 2];
            double vx = p[c] - p[o];
            double vy = p[c + 1] - p[o + 1];
            double vz = p[c + 2] - p[o + 2];
            // twice the triangle's area along the face's unit normal: negative when it turns against the face
            double along = ((uy * vz - uz * vy) * nx + (uz * vx - ux * vz) * ny + (ux * vy - uy * vx) * nz) / normal;
            double scale = Math.sqrt((ux * ux + uy * uy + uz * uz) * (vx * vx + vy * vy + vz * vz));
            if (along < -IN_LINE * scale) {
                return true;
            }
            if (along > IN_LINE * scale) { // a triangle of no area covers nothing and turns nothing
                swept += Math.atan2(along, ux * vx + uy * vy + uz * vz);
            }
        }
        return swept > 2 * Math.PI * (1 + IN_LINE); // once round the first vertex and more: overlapping
    }
}

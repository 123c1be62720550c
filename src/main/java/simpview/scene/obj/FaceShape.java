package simpview.scene.obj;

/**
 * Two shapes of a face of four vertices or more that SPEC draws otherwise
 * than its outline suggests, for the reader's warnings: its first three
 * vertices on one line (SPEC's face normal, (p2 - p1) x (p3 - p1), is then
 * zero or made of rounding errors), and a face that is not convex (SPEC fills
 * it as a fan from its first vertex, which covers more than its outline).
 * Positions are three doubles a vertex; a face is its vertices' indices.
 * Both tests hold under any affine map, so the model's own coordinates tell
 * what the camera's would.
 */
final class FaceShape {

    /**
     * The fewest vertices of a face that the reader warns of as not convex. The course's own dummy.obj holds
     * ten quads that are not convex (a vertex turned the other way, out of plane by 5 % of their size), drawn
     * as the course draws them; a star or an L-shape of five vertices or more is a face a student made, and
     * its fan shows the mistake.
     */
    static final int FEWEST_TO_FLAG_CONCAVE = 5;

    /** How small, against the product of their lengths, a cross product of two edges counts as none. */
    private static final double IN_LINE = 1e-9;

    private FaceShape() {
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
     * Whether the face of n vertices refs[0..n) has an area (Newell's normal, the sum over its edges, is not
     * nil) and is not convex: it turns the other way at some vertex, or it turns one way all round more than
     * once (a pentagram drawn in one stroke, its edges crossing).
     */
    static boolean concave(double[] p, int[] refs, int n) {
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
        double turned = 0; // the turns' angles, added up: 2 pi once round a convex face
        for (int i = 0; i < n; i++) {
            int a = 3 * refs[(i + n - 1) % n];
            int b = 3 * refs[i];
            int c = 3 * refs[(i + 1) % n];
            double ux = p[b] - p[a];
            double uy = p[b + 1] - p[a + 1];
            double uz = p[b + 2] - p[a + 2];
            double vx = p[c] - p[b];
            double vy = p[c + 1] - p[b + 1];
            double vz = p[c + 2] - p[b + 2];
            double turn = (uy * vz - uz * vy) * nx + (uz * vx - ux * vz) * ny + (ux * vy - uy * vx) * nz;
            double scale = Math.sqrt((ux * ux + uy * uy + uz * uz) * (vx * vx + vy * vy + vz * vz)) * normal;
            if (turn < -IN_LINE * scale) {
                return true;
            }
            turned += Math.atan2(turn / normal, ux * vx + uy * vy + uz * vz);
        }
        return turned > 3 * Math.PI; // twice round (4 pi) or more: not once round (2 pi)
    }
}

package simpview.scene.obj;

/**
 * Whether a model is inside out, for the reader's warning: measured face by
 * face as the file is read, told once at its end.
 *
 * <p>A face's front is the side from which its vertices run counter-clockwise
 * (SPEC): its winding's normal, Newell's sum over its edges (for a triangle
 * (p2 - p1) x (p3 - p1), and of the right sign for any face that has an
 * area). Two ways a model lights black, or by the ambient light alone, under
 * point lights outside it:
 * <ul>
 * <li>its {@code vn} normals, which light a face where it has them, point
 * against its faces' fronts: counted over the faces whose every vertex has
 * one, each face's normals (made unit length and summed) held against its
 * winding's normal;</li>
 * <li>its faces' fronts face its inside: each face's winding normal held
 * against the way from the model's centre to the face's centre, weighted by
 * the face's area and its distance from that centre (the share of the signed
 * volume's terms that are negative). The centre is the mean of the vertices
 * above the first face: exporters write every {@code v} line before the
 * {@code f} lines, and a file that goes on defining vertices after its first
 * face is measured from the centre of its first ones.</li>
 * </ul>
 *
 * <p>A model is said to be inside out only when that is clearly most of it:
 * nine faces in ten with normals against their fronts, or nine tenths of the
 * weight of the faces' fronts facing inward, of a model that has an inside
 * (its winding normals summing to half their lengths or less: a box without
 * its lid, a bowl; a flat model, a single face, has none); of a closed model (its winding
 * normals summing to nothing: every edge walked once each way), whose signed
 * volume is its whole answer, three fifths, as a model with arms and legs
 * measured from one centre has faces on both sides of it (the course's
 * dummy.obj has 37 % inward as it is, 63 % turned inside out). The course's
 * own models measure 0 % inward and no normal against its face.
 */
final class Orientation {

    /** The share, of faces with normals or of the inward weight, that is clearly most of a model. */
    static final double MOST = 0.9;
    /** The inward weight that is clearly most of a closed model. */
    static final double MOST_OF_A_CLOSED_MODEL = 0.6;
    /** How small, against the sum of their lengths, the sum of the winding normals of a closed model is. */
    private static final double CLOSED = 1e-6;
    /**
     * How small, against the sum of their lengths, the sum of the winding normals of a model with an inside
     * is: a box without its lid 0.2, a bowl 0.5; a flat model, which has no inside, 1.
     */
    private static final double HAS_AN_INSIDE = 0.5;
    /** How small, against the sizes at hand, a face's distance from the centre, or its facing, counts as none. */
    private static final double CLEAR = 1e-9;

    private boolean centred;
    private double cx;
    private double cy;
    private double cz;
    /** The weights of the faces whose fronts face away from the centre, and of those that face it. */
    private double outward;
    private double inward;
    /** The first face (its line) whose front faces the centre. */
    private int firstInward;
    /** The sum of the faces' winding normals, and of their lengths. */
    private double sumX;
    private double sumY;
    private double sumZ;
    private double lengths;
    private int faces;
    /** Faces whose every vertex has a normal; those whose normals point against their front, and along it. */
    private int facesWithNormals;
    private int against;
    private int along;
    /** The first face (its line) whose normals point against its front. */
    private int firstAgainst;

    /**
     * One face of n vertices, refs into {@code p} (three numbers a vertex, {@code vertexCount} of them so
     * far), its normals' refs into {@code normals} (-1 where a vertex has none), from line {@code line}.
     */
    void face(double[] p, int vertexCount, double[] normals, int[] refs, int[] normalRefs, int n,
            boolean everyNormal, int line) {
        if (!centred) {
            centre(p, vertexCount);
        }
        faces++;
        double nx = 0;
        double ny = 0;
        double nz = 0;
        double mx = 0;
        double my = 0;
        double mz = 0;
        for (int k = 0; k < n; k++) {
            int a = 3 * refs[k];
            int b = 3 * refs[k + 1 == n ? 0 : k + 1];
            nx += (p[a + 1] - p[b + 1]) * (p[a + 2] + p[b + 2]);
            ny += (p[a + 2] - p[b + 2]) * (p[a] + p[b]);
            nz += (p[a] - p[b]) * (p[a + 1] + p[b + 1]);
            mx += p[a];
            my += p[a + 1];
            mz += p[a + 2];
        }
        double length = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (!(length > 0) || !Double.isFinite(length)) {
            return; // no area (the reader warns of it), or beyond the doubles: no front to judge
        }
        sumX += nx;
        sumY += ny;
        sumZ += nz;
        lengths += length;
        double dx = mx / n - cx;
        double dy = my / n - cy;
        double dz = mz / n - cz;
        double away = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double facing = nx * dx + ny * dy + nz * dz;
        double size = Math.abs(cx) + Math.abs(cy) + Math.abs(cz) + Math.sqrt(length);
        // a face about the centre itself, or edge on to it, faces neither way (rounding errors would say one)
        boolean clear = away > CLEAR * size && Math.abs(facing) > CLEAR * length * away;
        if (clear && facing > 0) {
            outward += facing;
        } else if (clear) {
            inward -= facing;
            if (firstInward == 0) {
                firstInward = line;
            }
        }
        if (everyNormal) {
            facesWithNormals++;
            judgeNormals(normals, normalRefs, n, nx, ny, nz, line);
        }
    }

    /** The centre the faces are measured from: the mean of the vertices defined so far. */
    private void centre(double[] p, int vertexCount) {
        for (int i = 0; i < 3 * vertexCount; i += 3) {
            cx += p[i];
            cy += p[i + 1];
            cz += p[i + 2];
        }
        cx /= Math.max(1, vertexCount);
        cy /= Math.max(1, vertexCount);
        cz /= Math.max(1, vertexCount);
        centred = true;
    }

    /** Holds a face's normals, each made unit length and then summed, against its winding normal (nx, ny, nz). */
    private void judgeNormals(double[] normals, int[] normalRefs, int n, double nx, double ny, double nz, int line) {
        double sx = 0;
        double sy = 0;
        double sz = 0;
        for (int k = 0; k < n; k++) {
            int i = 3 * normalRefs[k];
            double x = normals[i];
            double y = normals[i + 1];
            double z = normals[i + 2];
            double l = Math.sqrt(x * x + y * y + z * z);
            if (l > 0 && Double.isFinite(l)) {
                sx += x / l;
                sy += y / l;
                sz += z / l;
            }
        }
        double d = sx * nx + sy * ny + sz * nz;
        if (d < 0) {
            if (against++ == 0) {
                firstAgainst = line;
            }
        } else if (d > 0) {
            along++;
        }
    }

    /** Whether the model has an inside, and most of its faces' fronts clearly face it. */
    private boolean frontsInward() {
        double total = inward + outward;
        double sum = Math.sqrt(sumX * sumX + sumY * sumY + sumZ * sumZ);
        if (!(total > 0) || !(sum <= HAS_AN_INSIDE * lengths)) {
            return false;
        }
        double most = sum <= CLOSED * lengths ? MOST_OF_A_CLOSED_MODEL : MOST;
        return inward >= most * total;
    }

    /** Whether most of the faces their normals light clearly have them against their fronts. */
    private boolean normalsAgainst() {
        return against > 0 && against >= MOST * (against + along);
    }

    /** Whether most of the faces clearly have their normals along their fronts. */
    private boolean normalsAlong() {
        return along > 0 && along >= MOST * (against + along);
    }

    /** "92 %": a share of the inward weight, never rounded up to 100 % nor down to 0 %. */
    private String inwardShare() {
        double share = 100 * inward / (inward + outward);
        long shown = Math.round(share);
        return (shown == 100 && share < 100 ? 99 : shown == 0 && share > 0 ? 1 : shown) + " %";
    }

    /** The warning for a model that is inside out, naming file {@code name}; null when it is not clearly so. */
    String warning(String name) {
        String dark = "so point lights outside it light nothing there: it shows black, or the ambient light alone";
        boolean byNormals = 2L * facesWithNormals >= faces && facesWithNormals > 0;
        boolean inside = frontsInward();
        if (byNormals && normalsAgainst() && !inside) {
            // normals against fronts that face outward (or that no centre judges): the normals point inward
            return name + ":" + firstAgainst + ": the model is inside out: its vn normals point against the front of "
                    + against + " of the " + count(against + along, "face") + " whose vertices all have one (this"
                    + " face the first), the side from which a face's vertices run counter-clockwise, and SPEC"
                    + " lights a face by its normals, " + dark + ": negate the vn lines (vn x y z becomes"
                    + " vn -x -y -z)" + (frontsOutward() ? "" : ", or, if it is the faces that are listed clockwise"
                    + " as seen from outside, reverse the order of each f line's vertices instead");
        }
        if (byNormals && normalsAlong() && inside) {
            return name + ":" + firstInward + ": the model is inside out: its faces are listed clockwise as seen from"
                    + " outside (the fronts of " + inwardShare() + " of its surface, weighted by distance from its"
                    + " centre, face inward; this face the first), and its vn normals point inward with them, "
                    + dark + ": reverse the order of each f line's vertices and negate the vn lines (vn x y z becomes"
                    + " vn -x -y -z)";
        }
        if (!byNormals && inside) {
            return name + ":" + firstInward + ": the model is inside out: its faces are listed clockwise as seen from"
                    + " outside (the fronts of " + inwardShare() + " of its surface, weighted by distance from its"
                    + " centre, face inward; this face the first), and a face without vn normals is lit on its front,"
                    + " the side from which its vertices run counter-clockwise, " + dark + ": reverse the order of each"
                    + " f line's vertices (f 1 2 3 becomes f 3 2 1)";
        }
        return null;
    }

    /** Whether the model has an inside, and most of its faces' fronts clearly face away from it. */
    private boolean frontsOutward() {
        double total = inward + outward;
        double sum = Math.sqrt(sumX * sumX + sumY * sumY + sumZ * sumZ);
        return total > 0 && sum <= HAS_AN_INSIDE * lengths && outward >= MOST * total;
    }

    private static String count(int n, String what) {
        return n + " " + what + (n == 1 ? "" : "s");
    }
}

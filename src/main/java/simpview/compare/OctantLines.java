package simpview.compare;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import simpview.pages.A1Lines;

/**
 * A first-assignment line panel whose lines differ from simpview's in some directions only: a line drawer
 * written for one octant and carried to the others by swapping x and y (steep lines) or stepping by -1 (lines
 * going left or down), one of those branches wrong. Measured line by line: a line's own pixels (within a pixel of
 * it and of no other line) that differ beyond the tolerance, and lines grouped by the octant of their direction
 * from the first end to the second, as given (octant 1 from 0 up to 45 degrees, counterclockwise, x right, y up).
 * Said when in each octant either most lines differ or nearly none does, some octants of each kind, and the
 * pixels that differ lie by lines of the octants that differ.
 *
 * @param differingOctants the octants (1 to 8) whose lines differ, in order
 * @param matchingOctants those whose lines match
 * @param differingLines how many lines of the differing octants differ
 * @param linesThere how many lines those octants have
 * @param matchingLines how many lines the matching octants have
 * @param differing how many pixels of the panel differ beyond the tolerance
 * @param byMatching how many of those lie by lines of the matching octants only
 * @param example one differing line, in words: "line 23, (150, 150) to (95, 273)"
 */
public record OctantLines(List<Integer> differingOctants, List<Integer> matchingOctants, int differingLines,
        int linesThere, int matchingLines, int differing, int byMatching, String example) implements PanelHint {

    /** A pixel is a line's when its centre is this close to the segment between the rounded ends. */
    static final double NEAR = 1.0;
    /** A line differs when at least this many of its own pixels do ... */
    static final int LEAST = 2;
    /** ... and at least this share of them. */
    static final double LINE_SHARE = 0.05;
    /** An octant differs when at least this share of its lines does ... */
    static final double MOST = 0.75;
    /** ... and matches when at most this share does. */
    static final double FEW = 0.1;
    /** At least this share of the differing pixels lies by lines of the octants that differ. */
    static final double EXPLAINED = 0.8;

    /** Octants that differ together, as a student's branch would have them, and their words. */
    private static final int[][] FAMILIES = {
        {2, 3, 6, 7}, {1, 4, 5, 8}, {3, 4, 5, 6}, {1, 2, 7, 8}, {5, 6, 7, 8}, {1, 2, 3, 4}, {3, 4, 7, 8},
        {1, 2, 5, 6}};
    private static final String[] FAMILY_WORDS = {
        "steep lines, |dy| > |dx|", "shallow lines, |dy| <= |dx|", "lines going left, x1 < x0",
        "lines going right, x1 > x0", "lines going down, y1 < y0", "lines going up, y1 > y0",
        "lines of negative slope", "lines of positive slope"};

    /**
     * The hint for a line panel of n x n pixels (ours and theirs row by row from the top) drawing {@code lines}, or
     * null when its differing pixels do not part the octants so.
     */
    public static OctantLines find(int[] ours, int[] theirs, int n, int tolerance, A1Lines lines) {
        int differing = 0;
        for (int i = 0; i < n * n; i++) {
            differing += Rasters.distance(ours[i], theirs[i]) > tolerance ? 1 : 0;
        }
        if (differing < LEAST) {
            return null;
        }
        int count = lines.count();
        int[] near = new int[n * n]; // how many lines a pixel is near
        int[] owner = new int[n * n]; // the last of them
        int[] octants = new int[n * n]; // a bit for each octant of those lines
        int[] octant = new int[count];
        long[][] ends = new long[count][];
        for (int i = 0; i < count; i++) {
            long ax = Math.round(Math.floor(lines.start(i).x() + 0.5));
            long ay = Math.round(Math.floor(lines.start(i).y() + 0.5));
            long bx = Math.round(Math.floor(lines.end(i).x() + 0.5));
            long by = Math.round(Math.floor(lines.end(i).y() + 0.5));
            ends[i] = new long[] {ax, ay, bx, by};
            if (ax == bx && ay == by) {
                continue; // one pixel: no direction
            }
            double degrees = Math.toDegrees(Math.atan2(by - ay, bx - ax));
            octant[i] = Math.min(8, (int) Math.floor((degrees < 0 ? degrees + 360 : degrees) / 45) + 1);
            mark(ax, ay, bx, by, n, i, 1 << octant[i] - 1, near, owner, octants);
        }
        int[] own = new int[count];
        int[] ownDiffering = new int[count];
        for (int p = 0; p < n * n; p++) {
            if (near[p] == 1) {
                own[owner[p]]++;
                ownDiffering[owner[p]] += Rasters.distance(ours[p], theirs[p]) > tolerance ? 1 : 0;
            }
        }
        int[] linesOf = new int[9];
        int[] differingOf = new int[9];
        for (int i = 0; i < count; i++) {
            if (octant[i] > 0) {
                linesOf[octant[i]]++;
                differingOf[octant[i]] += differs(ownDiffering[i], own[i]) ? 1 : 0;
            }
        }
        List<Integer> differingOctants = new ArrayList<>();
        List<Integer> matchingOctants = new ArrayList<>();
        int differingMask = 0;
        int differingLines = 0;
        int linesThere = 0;
        int matchingLines = 0;
        for (int o = 1; o <= 8; o++) {
            if (linesOf[o] == 0) {
                continue;
            }
            if (differingOf[o] >= MOST * linesOf[o]) {
                differingOctants.add(o);
                differingMask |= 1 << o - 1;
                differingLines += differingOf[o];
                linesThere += linesOf[o];
            } else if (differingOf[o] <= FEW * linesOf[o]) {
                matchingOctants.add(o);
                matchingLines += linesOf[o];
            } else {
                return null; // an octant of both: not a branch of the drawer
            }
        }
        if (differingOctants.isEmpty() || matchingOctants.isEmpty()) {
            return null;
        }
        int explained = 0;
        int byMatching = 0;
        for (int p = 0; p < n * n; p++) {
            if (Rasters.distance(ours[p], theirs[p]) > tolerance) {
                explained += (octants[p] & differingMask) != 0 ? 1 : 0;
                byMatching += octants[p] != 0 && (octants[p] & differingMask) == 0 ? 1 : 0;
            }
        }
        if (explained < EXPLAINED * differing) {
            return null;
        }
        String example = null;
        for (int i = 0; i < count && example == null; i++) {
            if (octant[i] > 0 && (differingMask & 1 << octant[i] - 1) != 0 && differs(ownDiffering[i], own[i])) {
                example = String.format(Locale.ROOT, "line %d, (%d, %d) to (%d, %d)", i + 1, ends[i][0], ends[i][1],
                        ends[i][2], ends[i][3]);
            }
        }
        return new OctantLines(List.copyOf(differingOctants), List.copyOf(matchingOctants), differingLines, linesThere,
                matchingLines, differing, byMatching, example);
    }

    private static boolean differs(int ownDiffering, int own) {
        return ownDiffering >= LEAST && ownDiffering >= LINE_SHARE * own;
    }

    /** Marks the pixels whose centres lie within {@link #NEAR} of the segment (a, b) as near line i. */
    private static void mark(long ax, long ay, long bx, long by, int n, int i, int bit, int[] near, int[] owner,
            int[] octants) {
        double dx = bx - ax;
        double dy = by - ay;
        double lengthSquared = dx * dx + dy * dy;
        int reach = (int) Math.ceil(NEAR);
        long x0 = Math.max(0, Math.min(ax, bx) - reach);
        long x1 = Math.min(n - 1, Math.max(ax, bx) + reach);
        long y0 = Math.max(0, Math.min(ay, by) - reach);
        long y1 = Math.min(n - 1, Math.max(ay, by) + reach);
        for (long y = y0; y <= y1; y++) {
            for (long x = x0; x <= x1; x++) {
                double t = Math.max(0, Math.min(1, ((x - ax) * dx + (y - ay) * dy) / lengthSquared));
                if (Math.hypot(x - ax - t * dx, y - ay - t * dy) <= NEAR) {
                    int p = (int) ((n - 1 - y) * n + x);
                    near[p]++;
                    owner[p] = i;
                    octants[p] |= bit;
                }
            }
        }
    }

    /** The octants in words, their family named where they are one: "octants 2, 3, 6 and 7 (steep lines, ...)". */
    private static String named(List<Integer> octants) {
        String which = (octants.size() == 1 ? "octant " : "octants ")
                + Sentence.listed(octants.stream().map(String::valueOf).toList());
        for (int f = 0; f < FAMILIES.length; f++) {
            if (octants.equals(List.of(FAMILIES[f][0], FAMILIES[f][1], FAMILIES[f][2], FAMILIES[f][3]))) {
                return which + " (" + FAMILY_WORDS[f] + ")";
            }
        }
        return which;
    }

    @Override
    public String brief() {
        return "to draw the lines of " + named(differingOctants) + " otherwise than simpview, the others alike";
    }

    @Override
    public String hint(int n) {
        return String.format(Locale.ROOT, "your lines differ in some directions only: %,d of the %s of %s differ from "
                + "simpview's (%s); the %s of %s match (%s of the %s that differ lie by them only). An octant is the "
                + "direction from a line's first end to its second: octant 1 from 0 up to 45 degrees, octant 2 from 45 "
                + "up to 90, and so on counterclockwise, x right, y up. A line drawer written for octant 1 draws the "
                + "others by swapping x and y (steep lines) and stepping by -1 (lines going left or down): check the "
                + "branch those lines take.", differingLines, Count.of(linesThere, "line"), named(differingOctants),
                example, Count.of(matchingLines, "line"), named(matchingOctants), Count.of(byMatching, "pixel"),
                Count.of(differing, "pixel"));
    }

    @Override
    public double shareThere() {
        return Double.NaN;
    }
}

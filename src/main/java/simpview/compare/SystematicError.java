package simpview.compare;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Locale;

/**
 * One mistake that changes a whole panel the same way, found in a student's
 * picture: the panel moved by a few pixels (a viewport off by one, the
 * course's y counted from the top), turned over or mirrored, x and y
 * swapped, or red and blue swapped. Every pixel is then wrong, or every
 * edge is, though the drawing itself may be right: the shares say "failed"
 * and the patches say "everywhere"; this says why.
 *
 * <p>It is found by laying simpview's panel over theirs each way such a
 * mistake would ({@link Turn} and a move of up to {@link #MOST_MOVED} pixels
 * for a picture turned over or not, one pixel for the rarer turns; red and
 * blue swapped or not) and keeping the way under which theirs is nearest,
 * its move then followed out while a pixel more comes nearer (up to
 * {@link #FARTHEST_MOVED}).
 * Under way W, pixel p of theirs is matched with {@code C(ours(T(p - s)))}: T
 * the turn, s the move, C the swap; p - s must lie in the panel, so a move
 * leaves out the rows and columns it brings in. The ways are first ranked
 * on a coarse grid of pixels, the best few again on a finer one, with the
 * colours' distance made blind to the swap; the swap is then chosen on the
 * finer grid, and the way measured on every pixel. Ways tied on a grid are
 * ranked on every pixel, then the smaller move first: a drawing of flat
 * cells (the first assignment's mesh, 30 px cells) matches many turns and
 * moves on every sampled pixel, the samples missing the few rows and
 * columns where they differ, and the first of them in order, kept for
 * being first, was then rejected on every pixel, so the true turn got no hint.
 *
 * <p>A way is named only where it explains the picture: at least
 * {@link #BETTER} times fewer pixels beyond the tolerance than as it stands
 * (over the same pixels), at least {@link #MIN_SHARE} of the pixels it
 * matches within the tolerance, and as it stands at least
 * {@link #MIN_WRONG} of the panel beyond it. Only exact distances count
 * here, never slack: a panel one pixel off passes with slack, and is still
 * a panel one pixel off.
 *
 * <p>A turn is named only where it can be told apart at all: simpview's
 * own panel, turned (and moved) that way, must itself differ from simpview's
 * panel on more than {@code 1 - MIN_SHARE} of the pixels it matches. A
 * drawing that is (nearly) symmetric under a turn, like the first
 * assignment's starburst upside down and a pixel up (y to 300 - y, its centre
 * 150 onto itself), is the same picture turned but for how ties round: a
 * student's panel that rounds them the other way then matches the turn
 * best (on the course's starburst, 99.96 % against 99.26 % as it stands)
 * though their y runs the right way, and "check how you turn y" would send
 * them after a mistake they did not make. By the hint's own measure a turn
 * whose picture matches simpview's on {@link #MIN_SHARE} is no other
 * picture. A move alone is not held to this: a move never lays a drawing on
 * itself (a turn does, for every drawing symmetric under it), and the
 * mistake it names, a panel a row off ({@code row = 650 - y}), changes only
 * the edges, 0.68 % of page 6, which is just what it is there to find.
 *
 * @param turn how the panel is turned over or mirrored
 * @param right how many pixels right of simpview's the (turned) panel lies; negative: left
 * @param down how many pixels below; negative: above
 * @param redBlueSwapped whether red and blue are swapped
 * @param shareThere the share of the pixels matched that are within the tolerance, that way
 * @param shareAsIs the share of the panel's pixels within the tolerance as the picture stands
 * @param tolerance the tolerance, in 1/255 steps
 */
public record SystematicError(Turn turn, int right, int down, boolean redBlueSwapped, double shareThere,
        double shareAsIs, int tolerance) implements PanelHint {

    /** A turn of the whole panel, as a map of its pixels onto themselves. */
    public enum Turn {
        NONE(""),
        UPSIDE_DOWN("upside down"),
        MIRRORED("mirrored left to right"),
        HALF_TURN("turned half round"),
        TRANSPOSED("transposed (x and y swapped)");

        private final String words;

        Turn(String words) {
            this.words = words;
        }

        /** The pixel of an n x n panel that (x, y) shows, turned this way: its index, row by row from the top. */
        int source(int x, int y, int n) {
            return switch (this) {
                case NONE -> y * n + x;
                case UPSIDE_DOWN -> (n - 1 - y) * n + x;
                case MIRRORED -> y * n + (n - 1 - x);
                case HALF_TURN -> (n - 1 - y) * n + (n - 1 - x);
                case TRANSPOSED -> x * n + y;
            };
        }

        /**
         * How far {@link #source} moves for a pixel one to the right: it is x times this plus what y gives, so a
         * row's pixels are found by stepping.
         */
        int step(int n) {
            return switch (this) {
                case NONE, UPSIDE_DOWN -> 1;
                case MIRRORED, HALF_TURN -> -1;
                case TRANSPOSED -> n;
            };
        }

        /** The farthest move tried with this turn: a picture turned over is often also a pixel off. */
        int mostMoved() {
            return this == NONE || this == UPSIDE_DOWN ? MOST_MOVED : 1;
        }
    }

    /** The farthest move, in pixels either way, tried for a panel that is not turned or is upside down. */
    public static final int MOST_MOVED = 4;
    /**
     * The farthest the best way's move is followed out, a pixel at a time, while it comes nearer; a move that
     * reaches it is not named, its true size not known.
     */
    public static final int FARTHEST_MOVED = 24;
    /** How many times fewer pixels beyond the tolerance a way must leave than the picture as it stands. */
    public static final int BETTER = 4;
    /** The least share of the matched pixels within the tolerance for a way to be named. */
    public static final double MIN_SHARE = 0.98;
    /** The least share of the panel beyond the tolerance as it stands: below, nothing is looked for. */
    public static final double MIN_WRONG = 0.001;
    /** Every way is first ranked on every COARSE_STRIDE-th pixel of every COARSE_STRIDE-th row. */
    static final int COARSE_STRIDE = 9;
    /** The {@link #KEPT} best are then ranked on every FINE_STRIDE-th pixel of every FINE_STRIDE-th row. */
    static final int FINE_STRIDE = 3;
    /** How many ways are ranked again on the finer grid. */
    static final int KEPT = 8;

    /** A turn and a move, and its share of sampled pixels beyond the tolerance once ranked. */
    private static final class Way {
        final Turn turn;
        final int right;
        final int down;
        double rate;

        /** Its share of every pixel beyond the tolerance, swap-blind; NaN until a tie needs it. */
        double full = Double.NaN;
        /** The pixels beyond the tolerance behind {@link #full}, once measured. */
        long fullWrong;

        Way(Turn turn, int right, int down) {
            this.turn = turn;
            this.right = right;
            this.down = down;
        }

        /** Its turn and move as one number: {@link #full} is theirs alone. */
        int key() {
            return key(turn, right, down);
        }

        static int key(Turn turn, int right, int down) {
            return (turn.ordinal() * 256 + right + 128) * 256 + down + 128;
        }

        /** How many pixels it matches: those p of theirs with p - s in the panel. */
        long matched(int n) {
            return (long) (n - Math.abs(down)) * (n - Math.abs(right));
        }

        /** How far it moves, in pixels across and down together. */
        int moveSize() {
            return Math.abs(right) + Math.abs(down);
        }
    }

    /** The systematic error that explains the comparison's picture against simpview's, or null. */
    public static SystematicError find(Comparison comparison, int tolerance) {
        return find(comparison.ours(), comparison.theirs(), comparison.size(), tolerance);
    }

    /**
     * The systematic error that explains theirs against ours, two n x n panels of 0xRRGGBB pixels row by
     * row from the top, or null when none does.
     */
    public static SystematicError find(int[] ours, int[] theirs, int n, int tolerance) {
        if (ours.length != n * n || theirs.length != n * n) {
            throw new IllegalArgumentException("both panels must be " + n + "x" + n + " pixels");
        }
        long wrongAsIs = wrongOver(ours, theirs, n, 0, 0, tolerance);
        if (wrongAsIs < MIN_WRONG * n * n) {
            return null;
        }
        // Both panels made blind to the swap (swapBlind) once a tie needs every pixel measured; until then, none.
        int[][] blind = new int[2][];
        // First every way on a coarse grid of pixels, then the few best on a finer one.
        List<Way> ways = new ArrayList<>();
        // Every way tried, by its turn and move, so that a way met again keeps its share of every pixel.
        Map<Integer, Way> tried = new HashMap<>();
        for (Turn turn : Turn.values()) {
            int most = turn.mostMoved();
            for (int down = -most; down <= most; down++) {
                for (int right = -most; right <= most; right++) {
                    Way way = new Way(turn, right, down);
                    tried.put(way.key(), way);
                    way.rate = sampledRate(ours, theirs, n, way, COARSE_STRIDE, tolerance,
                            Double.POSITIVE_INFINITY);
                    ways.add(way);
                }
            }
        }
        ways.sort(Comparator.comparingDouble((Way w) -> w.rate).thenComparingInt(Way::moveSize));
        // The KEPT best go on to the finer grid, and every way tied with the last of them: where many tie (a
        // mesh of flat cells), their order alone must not leave the true one out.
        List<Way> finer = new ArrayList<>();
        for (Way way : ways) {
            if (finer.size() >= KEPT && way.rate > finer.get(finer.size() - 1).rate) {
                break;
            }
            if (!toldApart(ours, n, way, tolerance)) {
                continue; // a turn that lays simpview's panel on itself: see the class's comment
            }
            finer.add(way);
        }
        Way best = null;
        for (Way way : finer) {
            way.rate = sampledRate(ours, theirs, n, way, FINE_STRIDE, tolerance,
                    best == null ? Double.POSITIVE_INFINITY : best.rate);
            if (best == null || nearer(ours, theirs, blind, n, way, best, tolerance)) {
                best = way;
            }
        }
        // The ways tried move by at most MOST_MOVED (one pixel for the rarer turns); from the best, the move
        // is followed a pixel at a time while a neighbouring one is nearer, up to FARTHEST_MOVED: so a panel
        // 5 px off is not called 4 px off, nor one 6 px down "1 px right and 4 px down". Where no step from
        // the first search's 4 px comes nearer, the move is not followed: page 1's thin lines far apart moved
        // 10 px or more, page 2's blerped mesh moved more than 22, get no hint.
        for (boolean nearer = true; nearer; ) {
            nearer = false;
            for (int k = 0; k < 9; k++) {
                int right = best.right + k % 3 - 1;
                int down = best.down + k / 3 - 1;
                if (k == 4 || Math.abs(right) > FARTHEST_MOVED || Math.abs(down) > FARTHEST_MOVED) {
                    continue;
                }
                Way step = tried.get(Way.key(best.turn, right, down));
                if (step == null) {
                    step = new Way(best.turn, right, down);
                    tried.put(step.key(), step);
                }
                if (!toldApart(ours, n, step, tolerance)) {
                    continue;
                }
                step.rate = sampledRate(ours, theirs, n, step, FINE_STRIDE, tolerance, best.rate);
                if (nearer(ours, theirs, blind, n, step, best, tolerance)) {
                    best = step;
                    nearer = true;
                }
            }
        }
        if (Math.abs(best.right) == FARTHEST_MOVED || Math.abs(best.down) == FARTHEST_MOVED) {
            return null; // it may be farther still: a hint of the wrong size would mislead
        }
        Way asIs = new Way(Turn.NONE, 0, 0);
        boolean moved = best.turn != Turn.NONE || best.right != 0 || best.down != 0;
        if (moved && best.rate * BETTER > sampledRate(ours, theirs, n, asIs, FINE_STRIDE, tolerance, 1)) {
            return null; // the swap aside, no way is near to the share it would need
        }
        // Red and blue swapped or not, by the finer grid; then that one measured on every pixel.
        boolean swap = sampledWrong(ours, theirs, n, best, true, tolerance)
                < sampledWrong(ours, theirs, n, best, false, tolerance);
        if (!moved && !swap) {
            return null;
        }
        long[] there = wrong(ours, theirs, n, best, swap, tolerance);
        // As it stands, over the same pixels the way matches: a move leaves some out.
        long wrongHere = best.right == 0 && best.down == 0 ? wrongAsIs
                : wrongOver(ours, theirs, n, best.right, best.down, tolerance);
        double shareThere = 1 - (double) there[0] / there[1];
        if (there[0] * BETTER > wrongHere || shareThere < MIN_SHARE) {
            return null;
        }
        return new SystematicError(best.turn, best.right, best.down, swap, shareThere,
                1 - (double) wrongAsIs / ((long) n * n), tolerance);
    }

    /**
     * Whether {@code way} is nearer than {@code best}, both ranked on the finer grid: fewer sampled pixels beyond
     * the tolerance; tied there, fewer of every pixel (the ties measured so only); tied there too, the smaller
     * move. The order is strict, so following the move out always ends.
     */
    private static boolean nearer(int[] ours, int[] theirs, int[][] blind, int n, Way way, Way best, int tolerance) {
        if (way.rate != best.rate) {
            return way.rate < best.rate;
        }
        if (blind[0] == null) {
            blind[0] = swapBlind(ours);
            blind[1] = swapBlind(theirs);
        }
        double bestFull = fullRate(blind[0], blind[1], n, best, tolerance, null);
        double full = fullRate(blind[0], blind[1], n, way, tolerance, best);
        return full != bestFull ? full < bestFull : way.moveSize() < best.moveSize();
    }

    /**
     * A way's share of every pixel it matches beyond the tolerance, of two panels made blind to the swap
     * ({@link #swapBlind}): measured once, then kept. Or, given
     * a way {@code than} measured so already, infinity (not kept) as soon as the pixels beyond are so many that the
     * share must be above {@code than}'s: W of its M pixels matched once W * M' exceeds W' * M, whole numbers. Its
     * share W / M is then above W' / M', and the two doubles they round to keep that order: two fractions of
     * denominators at most n * n that differ, differ by at least 1 / n^4, far more than either rounds by (a
     * part in 2^53) for any panel under 7,000 pixels a side. So {@link #nearer} answers as it would have.
     */
    private static double fullRate(int[] ours, int[] theirs, int n, Way way, int tolerance, Way than) {
        if (!Double.isNaN(way.full)) {
            return way.full;
        }
        Turn turn = way.turn;
        int right = way.right;
        int down = way.down;
        int fromX = Math.max(0, right);
        int toX = Math.min(n, n + right);
        long matched = way.matched(n);
        int step = turn.step(n);
        long wrong = 0;
        for (int y = Math.max(0, down); y < Math.min(n, n + down); y++) {
            int o = turn.source(fromX - right, y - down, n);
            for (int t = y * n + fromX; t < y * n + toX; t++, o += step) {
                wrong += Rasters.distance(ours[o], theirs[t]) > tolerance ? 1 : 0;
            }
            if (than != null && wrong * than.matched(n) > than.fullWrong * matched) {
                return Double.POSITIVE_INFINITY;
            }
        }
        way.fullWrong = wrong;
        way.full = (double) wrong / matched;
        return way.full;
    }

    /**
     * Whether a way can be told from simpview's panel as it stands: a move alone always can; a turn (and its
     * move) only where it changes more than {@code 1 - MIN_SHARE} of the pixels it matches of simpview's own
     * panel beyond the tolerance, so that a panel symmetric under it is never called turned (see the class's
     * comment). Measured on the finer grid, and left as soon as the share is past that: a turned panel is
     * nearly always far from itself within its first rows. On every pixel, for each of the dozens of ways
     * ranked, it made a comparison 0.1-0.2 s slower.
     */
    private static boolean toldApart(int[] ours, int n, Way way, int tolerance) {
        return way.turn == Turn.NONE
                || sampledRate(ours, ours, n, way, FINE_STRIDE, tolerance, 1 - MIN_SHARE) > 1 - MIN_SHARE;
    }

    /**
     * Pixels beyond the tolerance, and pixels matched, with theirs at p matched with C(ours(T(p - s))) for
     * every p with p - s in the panel.
     */
    private static long[] wrong(int[] ours, int[] theirs, int n, Way way, boolean swap, int tolerance) {
        Turn turn = way.turn;
        int right = way.right;
        int down = way.down;
        long wrong = 0;
        long matched = 0;
        for (int y = Math.max(0, down); y < Math.min(n, n + down); y++) {
            for (int x = Math.max(0, right); x < Math.min(n, n + right); x++) {
                int o = ours[turn.source(x - right, y - down, n)];
                int colour = swap ? redBlueSwapped(o) : o;
                wrong += Rasters.distance(colour, theirs[y * n + x]) > tolerance ? 1 : 0;
                matched++;
            }
        }
        return new long[] {wrong, matched};
    }

    /** Pixels beyond the tolerance as the picture stands, over the pixels a move of s matches. */
    private static long wrongOver(int[] ours, int[] theirs, int n, int right, int down, int tolerance) {
        long wrong = 0;
        for (int y = Math.max(0, down); y < Math.min(n, n + down); y++) {
            for (int x = Math.max(0, right); x < Math.min(n, n + right); x++) {
                int i = y * n + x;
                wrong += Rasters.distance(ours[i], theirs[i]) > tolerance ? 1 : 0;
            }
        }
        return wrong;
    }

    /**
     * The share of sampled pixels beyond the tolerance under a way, the swap left out of account (the
     * distance of red and blue as a pair, whichever way round); or, as soon as it must be above
     * {@code bound}, a value above it (never one equal to it, which would tie).
     */
    private static double sampledRate(int[] ours, int[] theirs, int n, Way way, int stride, int tolerance,
            double bound) {
        Turn turn = way.turn;
        int right = way.right;
        int down = way.down;
        int fromY = Math.max(0, down);
        int toY = Math.min(n, n + down);
        int fromX = Math.max(0, right);
        int toX = Math.min(n, n + right);
        long samples = (long) ((toY - fromY + stride - 1) / stride) * ((toX - fromX + stride - 1) / stride);
        double most = bound * samples; // wrong pixels past this make a rate above the bound
        int step = turn.step(n) * stride;
        long wrong = 0;
        for (int y = fromY; y < toY; y += stride) {
            int o = turn.source(fromX - right, y - down, n);
            for (int t = y * n + fromX; t < y * n + toX; t += stride, o += step) {
                wrong += swapBlindDistance(ours[o], theirs[t]) > tolerance ? 1 : 0;
            }
            if (wrong > most) {
                return Math.nextUp(bound);
            }
        }
        return (double) wrong / samples;
    }

    /** The sampled pixels (the finer grid) beyond the tolerance under a way, red and blue swapped or not. */
    private static long sampledWrong(int[] ours, int[] theirs, int n, Way way, boolean swap, int tolerance) {
        long wrong = 0;
        for (int y = Math.max(0, way.down); y < Math.min(n, n + way.down); y += FINE_STRIDE) {
            for (int x = Math.max(0, way.right); x < Math.min(n, n + way.right); x += FINE_STRIDE) {
                int o = ours[way.turn.source(x - way.right, y - way.down, n)];
                wrong += Rasters.distance(swap ? redBlueSwapped(o) : o, theirs[y * n + x]) > tolerance ? 1 : 0;
            }
        }
        return wrong;
    }

    /** The colours' distance with red and blue compared as a pair, the smaller with the smaller. */
    private static int swapBlindDistance(int a, int b) {
        int ar = a >> 16 & 0xFF;
        int ab = a & 0xFF;
        int br = b >> 16 & 0xFF;
        int bb = b & 0xFF;
        int g = Math.abs((a >> 8 & 0xFF) - (b >> 8 & 0xFF));
        int low = Math.abs(Math.min(ar, ab) - Math.min(br, bb));
        int high = Math.abs(Math.max(ar, ab) - Math.max(br, bb));
        return Math.max(g, Math.max(low, high));
    }

    /**
     * The colours with red and blue each made the smaller and the larger of the two (green between them): the
     * distance of two colours made so ({@link Rasters#distance}) is theirs with red and blue compared as a pair,
     * the smaller with the smaller, blind to the swap ({@link #swapBlindDistance}): for the shares of every pixel,
     * where it saves more than it costs.
     */
    private static int[] swapBlind(int[] rgb) {
        int[] blind = new int[rgb.length];
        for (int i = 0; i < rgb.length; i++) {
            int red = rgb[i] >> 16 & 0xFF;
            int blue = rgb[i] & 0xFF;
            blind[i] = Math.min(red, blue) << 16 | rgb[i] & 0xFF00 | Math.max(red, blue);
        }
        return blind;
    }

    private static int redBlueSwapped(int rgb) {
        return rgb & 0xFF00FF00 | (rgb >> 16 & 0xFF) | (rgb & 0xFF) << 16;
    }

    /**
     * What is wrong, briefly, to follow "your panel is simpview's" or "looks": "upside down, then moved 1 px
     * down", "moved 3 px right and 2 px up", "red and blue swapped".
     */
    @Override
    public String brief() {
        StringBuilder out = new StringBuilder(turn.words);
        String moved = moved();
        if (!moved.isEmpty()) {
            out.append(out.length() == 0 ? "moved " : ", then moved ").append(moved);
        }
        if (redBlueSwapped) {
            out.append(out.length() == 0 ? "" : ", ").append("red and blue swapped");
        }
        return out.toString();
    }

    private String moved() {
        String across = right == 0 ? "" : Math.abs(right) + " px " + (right > 0 ? "right" : "left");
        String upDown = down == 0 ? "" : Math.abs(down) + " px " + (down > 0 ? "down" : "up");
        return across.isEmpty() ? upDown : upDown.isEmpty() ? across : across + " and " + upDown;
    }

    /**
     * The whole hint: what is wrong, how well it explains the picture, and where to look, e.g. "your panel
     * is simpview's upside down: so turned back, 99.98 % of the pixels it then matches are within 8/255
     * (61.20 % of the panel as it stands). Check how you turn y: ..."
     */
    @Override
    public String hint(int n) {
        return hint(n, "panel");
    }

    /** The same of {@code what} ("panel", "page"), n x n pixels. */
    String hint(int n, String what) {
        String within = "within " + tolerance + "/255";
        String share = String.format(Locale.ROOT, "%s, %s of the pixels it then matches are %s, exactly (%s of "
                + "the %s as it stands)", undone(), Percent.of(shareThere), within, Percent.of(shareAsIs), what);
        return "your " + what + " is simpview's " + brief() + ": " + share + ". " + advice(n, what);
    }

    /** "turned back", "moved back", "x and y swapped back, red and blue too", ... */
    private String undone() {
        String undo = switch (turn) {
            case TRANSPOSED -> "x and y swapped back";
            case MIRRORED -> "mirrored back";
            case UPSIDE_DOWN, HALF_TURN -> "turned back";
            case NONE -> "";
        };
        if (right != 0 || down != 0) {
            undo = undo.isEmpty() ? "moved back" : undo.replace(" back", "") + " and moved back";
        }
        if (redBlueSwapped) {
            undo = undo.isEmpty() ? "red and blue swapped back" : undo + ", red and blue swapped too";
        }
        return "so " + undo;
    }

    /** Where to look, for a {@code what} ("panel", "page") of n x n pixels. */
    private String advice(int n, String what) {
        String rows = "the pixel of y is row " + (n - 1) + " - y";
        String advice = switch (turn) {
            case UPSIDE_DOWN -> "Check how you turn y: an image's rows run down from its top, the course's y up "
                    + "from the " + what + "'s bottom-left pixel, so " + rows + ".";
            case MIRRORED, HALF_TURN -> "Check how your x and y become a column and a row: x runs right from the "
                    + what + "'s left edge, y up from its bottom edge (" + rows + ").";
            case TRANSPOSED -> "Check the order of x and y where you set a pixel: x is the column, y the row.";
            case NONE -> right != 0 || down != 0
                    ? "Check how points become pixels: the panel's offset in the page, rounding, and the row of y ("
                            + rows + "; row " + n + " - y puts everything a row down)."
                    : "";
        };
        String channels = redBlueSwapped ? "Check how you pack a colour: 0xRRGGBB has red in bits 16-23, blue in "
                + "bits 0-7 (a BGR image type stores them the other way round)." : "";
        return advice.isEmpty() ? channels : channels.isEmpty() ? advice : advice + " " + channels;
    }
}

package simpview.scene.simp;

import java.util.ArrayList;
import java.util.List;

/**
 * The points of a line or polygon as its line writes them, each in its own
 * parentheses: "(0,0,-1) (1,0,-1,1,0,0)" holds two points, of 3 and 6
 * numbers. When the command's count of numbers is wrong and it has as many
 * points as it takes, what each point holds says where the mistake is; the
 * total alone reads as too many points.
 */
final class PointGroups {

    private PointGroups() {
    }

    /**
     * How many words (numbers, as the readers separate them) each outermost
     * pair of parentheses in b[from, to) holds, a nested pair counted in its
     * point ("(x, y, z, (r, g, b))" holds 6); null when a word stands outside
     * every pair or the parentheses do not pair up.
     */
    static List<Integer> counts(byte[] b, int from, int to) {
        List<Integer> counts = new ArrayList<>();
        int depth = 0;
        boolean inWord = false;
        for (int j = from; j < to; j++) {
            byte c = b[j];
            if (c == '(') {
                if (depth++ == 0) {
                    counts.add(0);
                }
            } else if (c == ')' && --depth < 0) {
                return null;
            }
            boolean separator = SimpReader.isSeparator(c);
            if (!separator && !inWord) {
                if (depth == 0) {
                    return null;
                }
                counts.set(counts.size() - 1, counts.get(counts.size() - 1) + 1);
            }
            inWord = !separator;
        }
        return depth == 0 ? counts : null;
    }

    /**
     * For a command of {@code vertices} points whose count of numbers is
     * wrong: when its line writes that many points, each in parentheses,
     * what each holds and what a point takes; else "".
     */
    static String hint(byte[] b, int from, int to, int vertices) {
        List<Integer> counts = counts(b, from, to);
        if (counts == null || counts.size() != vertices) {
            return "";
        }
        StringBuilder held = new StringBuilder();
        for (int i = 0; i < vertices; i++) {
            held.append(i == 0 ? "" : i == vertices - 1 ? " and " : ", ").append(counts.get(i));
        }
        boolean someColoured = counts.contains(6) && counts.contains(3);
        return " (its " + vertices + " points hold " + held + " numbers: a point is 3 numbers, x y z, or 6 with its"
                + " colour, x y z r g b" + (someColoured ? "; either every point has its colour or none has" : "")
                + ")";
    }
}

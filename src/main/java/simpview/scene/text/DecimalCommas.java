package simpview.scene.text;

/**
 * Commas written as decimal points, as a German or French locale writes
 * numbers: "1,5" for one and a half. SIMP and .obj lines take a comma as a
 * separator (SPEC), so "1,5" is the two numbers 1 and 5; both readers count
 * such commas to say so when the line's count of numbers shows they were
 * meant as decimal points.
 */
public final class DecimalCommas {

    /** What a reader's message adds, in parentheses. */
    public static final String HINT = "a comma separates two numbers: one and a half is 1.5, not 1,5";

    private DecimalCommas() {
    }

    /**
     * How many commas in b[from, to) stand in a word that is digits, a comma
     * and digits, with at most a sign before ("1,5", "-0,25"), outside
     * parentheses (where a point's numbers are written "(1,2,3)"). A comma
     * beside a decimal point ("1.5,2") or in a longer run ("1,2,3") is a
     * separator however it is read.
     */
    public static int count(byte[] b, int from, int to) {
        int commas = 0;
        for (int j = first(b, from, to); j >= 0; j = first(b, j + 1, to)) {
            commas++;
        }
        return commas;
    }

    /** The index of the first comma {@link #count} counts in b[from, to), or -1. */
    public static int first(byte[] b, int from, int to) {
        boolean inPoint = false;
        for (int j = from; j + 1 < to; j++) {
            inPoint = b[j] == '(' || (inPoint && b[j] != ')');
            if (!inPoint && j > from && b[j] == ',' && isDigit(b[j - 1]) && isDigit(b[j + 1])
                    && wordStarts(b, from, j - 1) && wordEnds(b, j + 1, to)) {
                return j;
            }
        }
        return -1;
    }

    /** True when the digits ending at b[last] start a word: before them only a sign, a blank or '('. */
    private static boolean wordStarts(byte[] b, int from, int last) {
        int k = last;
        while (k > from && isDigit(b[k - 1])) {
            k--;
        }
        if (k > from && (b[k - 1] == '-' || b[k - 1] == '+')) {
            k--;
        }
        return k == from || b[k - 1] == ' ' || b[k - 1] == '\t' || b[k - 1] == '(';
    }

    /** True when the digits starting at b[first] end a word: after them the end, a blank or ')'. */
    private static boolean wordEnds(byte[] b, int first, int to) {
        int k = first;
        while (k < to && isDigit(b[k])) {
            k++;
        }
        return k == to || b[k] == ' ' || b[k] == '\t' || b[k] == ')';
    }

    /**
     * How many words b[from, to) holds, words being what stands between blanks, commas and parentheses, as
     * both readers separate numbers: with {@link #count}, whether the commas' numbers would make another count.
     */
    public static int words(byte[] b, int from, int to) {
        int words = 0;
        boolean inWord = false;
        for (int j = from; j < to; j++) {
            byte c = b[j];
            boolean separator = c == ' ' || c == '\t' || c == ',' || c == '(' || c == ')';
            words += !separator && !inWord ? 1 : 0;
            inWord = !separator;
        }
        return words;
    }

    private static boolean isDigit(byte c) {
        return c >= '0' && c <= '9';
    }
}

package simpview.scene.text;

import java.nio.charset.StandardCharsets;

/**
 * Reads a decimal number straight out of a byte buffer, without making a
 * String, and gives exactly the double {@link Double#parseDouble} would give.
 *
 * <p>Accepted: {@code [+-]? (digits [. digits?] | . digits) ([eE] [+-]? digits)?},
 * ASCII digits only; no NaN, Infinity, hex or type suffixes.
 *
 * <p>Why it is exact: when the digits, read as one integer m (the decimal
 * point dropped), are at most 2^53, m is an exact double, and for
 * |k| &lt;= 22 so is 10^k. One IEEE multiplication or division of two
 * exact values is correctly rounded, so m * 10^k or m / 10^-k is the double
 * nearest the decimal, which is what parseDouble returns. Anything else goes
 * to parseDouble itself.
 *
 * <p>One instance is reused for every number; not for two threads at once.
 */
public final class DecimalParser {

    /** Up to this many digits a long holds the mantissa without overflow ({@code 10^18 < 2^63}). */
    private static final int MAX_LONG_DIGITS = 18;
    /** Integers up to 2^53 are exact doubles. */
    private static final long MAX_EXACT_MANTISSA = 1L << 53;
    private static final int MAX_EXACT_POWER = 22;
    /** Exponents beyond this make every value 0 or infinite; the slow path sorts them out. */
    private static final int EXPONENT_CAP = 100_000;

    private static final double[] POWERS_OF_TEN = new double[MAX_EXACT_POWER + 1];

    static {
        double p = 1;
        for (int k = 0; k <= MAX_EXACT_POWER; k++) {
            POWERS_OF_TEN[k] = p;
            p *= 10; // exact up to 1e22: 5^22 < 2^53
        }
    }

    private double value;
    /** The exponent just read, capped; a field so that reading it needs no object to return two ints. */
    private int exponent;

    /**
     * Scans a number starting at {@code from}: one pass over its bytes, the
     * digits accumulated into a long as they go by.
     *
     * @return the index just past the number, or -1 when no number starts there
     *     (its value is then undefined)
     */
    public int scan(byte[] b, int from, int to) {
        int i = from;
        boolean negative = false;
        if (i < to && (b[i] == '+' || b[i] == '-')) {
            negative = b[i] == '-';
            i++;
        }
        long mantissa = 0;
        int wholeStart = i;
        for (int d; i < to && (d = b[i] - '0') >= 0 && d <= 9; i++) {
            mantissa = 10 * mantissa + d; // may overflow past 18 digits: then the slow path decides
        }
        int digits = i - wholeStart;
        int fractionDigits = 0;
        if (i < to && b[i] == '.') {
            int fractionStart = ++i;
            for (int d; i < to && (d = b[i] - '0') >= 0 && d <= 9; i++) {
                mantissa = 10 * mantissa + d;
            }
            fractionDigits = i - fractionStart;
            digits += fractionDigits;
        }
        if (digits == 0) {
            return -1;
        }
        int exponent = 0;
        if (i < to && (b[i] == 'e' || b[i] == 'E')) {
            i = exponent(b, i + 1, to);
            if (i < 0) {
                return -1;
            }
            exponent = this.exponent;
        }
        value = digits <= MAX_LONG_DIGITS ? exact(negative, mantissa, exponent - fractionDigits) : Double.NaN;
        if (Double.isNaN(value)) {
            value = Double.parseDouble(new String(b, from, i - from, StandardCharsets.ISO_8859_1));
        }
        return i;
    }

    /** Reads {@code [+-]? digits} at i into {@link #exponent}; -1 when there are no digits. */
    private int exponent(byte[] b, int i, int to) {
        boolean negative = false;
        if (i < to && (b[i] == '+' || b[i] == '-')) {
            negative = b[i] == '-';
            i++;
        }
        int start = i;
        int e = 0;
        for (; i < to && b[i] >= '0' && b[i] <= '9'; i++) {
            e = Math.min(EXPONENT_CAP, e * 10 + (b[i] - '0'));
        }
        exponent = negative ? -e : e;
        return i == start ? -1 : i;
    }

    /**
     * mantissa * 10^power when one IEEE operation gives it correctly rounded
     * (Clinger's fast path: both factors exact doubles); NaN when it cannot.
     */
    private static double exact(boolean negative, long mantissa, int power) {
        if (mantissa == 0) {
            return negative ? -0.0 : 0.0;
        }
        if (mantissa > MAX_EXACT_MANTISSA || power < -MAX_EXACT_POWER || power > MAX_EXACT_POWER) {
            return Double.NaN;
        }
        double m = mantissa;
        double v = power >= 0 ? m * POWERS_OF_TEN[power] : m / POWERS_OF_TEN[-power];
        return negative ? -v : v;
    }

    /** The value of the number last scanned successfully. */
    public double value() {
        return value;
    }

    /** Convenience for tests and tools: the whole string must be one number, else NumberFormatException. */
    public static double parse(String text) {
        byte[] b = text.getBytes(StandardCharsets.ISO_8859_1);
        DecimalParser parser = new DecimalParser();
        if (parser.scan(b, 0, b.length) != b.length || text.length() != b.length) {
            throw new NumberFormatException("not a decimal number: '" + text + "'");
        }
        return parser.value();
    }

    /**
     * For an error on a token that is not a number: when it holds a
     * character beyond ASCII, which no number may, a sentence naming the
     * first (", whose '−' is U+2212 MINUS SIGN, not ASCII: ..."), since text
     * copied from a PDF or a word processor looks right and is not; else "".
     */
    public static String nonAsciiHint(String token) {
        return CopiedText.hint(token, "a number is written with the ASCII digits, '-', '+', '.' and 'e'");
    }
}

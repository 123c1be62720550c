package simpview.simp;

import java.nio.charset.StandardCharsets;

/**
 * Reads a decimal number straight out of a byte buffer, without making a
 * String, and gives exactly the double {@link Double#parseDouble} would give.
 *
 * <p>Accepted: {@code [+-]? (digits [. digits?] | . digits) ([eE] [+-]? digits)?},
 * ASCII digits only; no NaN, Infinity, hex or type suffixes.
 *
 * <p>Why it is exact: when the digits, leading and trailing zeros aside, fit
 * in 15 decimal places, their value m is an exact double (below 2^53), and
 * for |k| &lt;= 22 so is 10^k. One IEEE multiplication or division of two
 * exact values is correctly rounded, so m * 10^k or m / 10^-k is the double
 * nearest the decimal, which is what parseDouble returns. Anything else goes
 * to parseDouble itself.
 *
 * <p>One instance is reused for every number; not for two threads at once.
 */
public final class DecimalParser {

    private static final int MAX_EXACT_DIGITS = 15;
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

    private static final long[] POW10_LONG = new long[MAX_EXACT_DIGITS + 2];

    static {
        long p = 1;
        for (int k = 0; k < POW10_LONG.length; k++) {
            POW10_LONG[k] = p;
            p *= 10;
        }
    }

    private double value;

    /**
     * Scans a number starting at {@code from}.
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
        int significant = 0;
        int pendingZeros = 0; // zeros after the last non-zero digit, not yet in the mantissa
        int fractionDigits = 0;
        int digits = 0;
        boolean exact = true;
        boolean inFraction = false;
        for (; i < to; i++) {
            int d = b[i] - '0';
            if (d >= 0 && d <= 9) {
                digits++;
                if (inFraction) {
                    fractionDigits++;
                }
                if (d == 0) {
                    pendingZeros++;
                } else if (mantissa == 0) {
                    mantissa = d; // leading zeros are not significant
                    significant = 1;
                    pendingZeros = 0;
                } else if (significant + pendingZeros + 1 <= MAX_EXACT_DIGITS) {
                    mantissa = mantissa * POW10_LONG[pendingZeros + 1] + d;
                    significant += pendingZeros + 1;
                    pendingZeros = 0;
                } else {
                    exact = false;
                }
            } else if (b[i] == '.' && !inFraction) {
                inFraction = true;
            } else {
                break;
            }
        }
        if (digits == 0) {
            return -1;
        }
        int exponent = 0;
        if (i < to && (b[i] == 'e' || b[i] == 'E')) {
            i++;
            boolean negativeExponent = false;
            if (i < to && (b[i] == '+' || b[i] == '-')) {
                negativeExponent = b[i] == '-';
                i++;
            }
            int exponentStart = i;
            while (i < to && b[i] >= '0' && b[i] <= '9') {
                exponent = Math.min(EXPONENT_CAP, exponent * 10 + (b[i] - '0'));
                i++;
            }
            if (i == exponentStart) {
                return -1;
            }
            if (negativeExponent) {
                exponent = -exponent;
            }
        }
        if (mantissa == 0) {
            value = negative ? -0.0 : 0.0;
            return i;
        }
        int power = exponent + pendingZeros - fractionDigits;
        if (exact && power >= -MAX_EXACT_POWER && power <= MAX_EXACT_POWER) {
            double m = mantissa;
            double v = power >= 0 ? m * POWERS_OF_TEN[power] : m / POWERS_OF_TEN[-power];
            value = negative ? -v : v;
        } else {
            value = Double.parseDouble(new String(b, from, i - from, StandardCharsets.ISO_8859_1));
        }
        return i;
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
}

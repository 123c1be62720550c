package simpview.inspect;

import java.math.BigInteger;
import java.util.ArrayList;
import java.util.List;

/**
 * A pixel given as text, the one reading of it for the window's Go to pixel
 * (Shift+G) and the command line's {@code inspect --at}: two whole numbers,
 * x then y, with commas or blanks between them ("325,400", "325 400",
 * "325, 400"), perhaps in parentheses as the inspector writes a pixel
 * ("(325, 400)"). A number may have a sign, and its digits may be of any
 * script (a Japanese keyboard's full-width ３ is 3). A whole number of any
 * size is a place: outside the panel when it is not in it, not "not a
 * number". The problems are said the same way to both, the text quoted as
 * given; the command line puts "--at " before them.
 */
public record PixelPair(int x, int y) {

    /** Why a text is not a pixel inside the panel (or page), in words. */
    public static final class NotAPixel extends Exception {

        private static final long serialVersionUID = 1L;

        NotAPixel(String message) {
            super(message, null, false, false);
        }
    }

    /**
     * The pixel {@code text} names, x and y from 0 to {@code last} in the
     * coordinates of {@code where} ("panel" or "page": x right, y up from
     * its bottom-left pixel).
     */
    public static PixelPair read(String text, String where, int last) throws NotAPixel {
        String example = "; give x and y, two whole numbers in " + where + " coordinates, for example 325,400 or "
                + "(325, 400)";
        String inside = stripBlanks(text);
        boolean opens = inside.startsWith("(");
        boolean closes = inside.endsWith(")");
        if (opens && closes && inside.length() > 1) {
            inside = stripBlanks(inside.substring(1, inside.length() - 1));
        } else if (opens) {
            throw new NotAPixel(quoted(text) + " is not a pixel: its '(' is not closed" + example);
        } else if (closes) {
            throw new NotAPixel(quoted(text) + " is not a pixel: its ')' closes no '('" + example);
        }
        List<String> parts = parts(inside);
        if (parts.isEmpty()) {
            throw new NotAPixel(quoted(text) + " is not a pixel: it has no number" + example);
        }
        if (parts.size() != 2) {
            throw new NotAPixel(quoted(text) + " is not a pixel: it has "
                    + (parts.size() == 1 ? "one part" : parts.size() + " parts") + ", not two (x and y)" + example);
        }
        BigInteger[] numbers = new BigInteger[2];
        for (int k = 0; k < 2; k++) {
            String part = parts.get(k);
            numbers[k] = wholeNumber(part);
            if (numbers[k] == null) {
                throw new NotAPixel(quoted(text) + " is not a pixel: its " + (k == 0 ? "x" : "y") + ", "
                        + quoted(part) + ", is not a whole number" + example);
            }
        }
        BigInteger high = BigInteger.valueOf(last);
        String out = "";
        for (int k = 0; k < 2; k++) {
            if (numbers[k].signum() < 0 || numbers[k].compareTo(high) > 0) {
                out += (out.isEmpty() ? "" : " and ") + (k == 0 ? "x" : "y") + " is " + numbers[k];
            }
        }
        if (!out.isEmpty()) {
            throw new NotAPixel(quoted(text) + " is outside the " + where + ": " + out + ", and x and y are 0 to "
                    + last + ", from the " + where + "'s bottom-left pixel, y up");
        }
        return new PixelPair(numbers[0].intValue(), numbers[1].intValue());
    }

    /** The pieces between commas and blanks, none empty. */
    private static List<String> parts(String text) {
        List<String> parts = new ArrayList<>();
        int start = 0;
        for (int k = 0; k <= text.length(); k++) {
            if (k == text.length() || isSeparator(text.charAt(k))) {
                if (k > start) {
                    parts.add(text.substring(start, k));
                }
                start = k + 1;
            }
        }
        return parts;
    }

    /** The number a sign or none, then digits of any scripts, make; null when the part is not that. */
    private static BigInteger wholeNumber(String part) {
        int from = part.startsWith("+") || part.startsWith("-") ? 1 : 0;
        if (from == part.length()) {
            return null;
        }
        StringBuilder digits = new StringBuilder(part.substring(0, from));
        for (int k = from; k < part.length(); k += Character.charCount(part.codePointAt(k))) {
            int c = part.codePointAt(k);
            if (Character.getType(c) != Character.DECIMAL_DIGIT_NUMBER) {
                return null;
            }
            digits.append((char) ('0' + Character.digit(c, 10)));
        }
        return new BigInteger(digits.toString());
    }

    private static boolean isSeparator(char c) {
        return c == ',' || isBlank(c);
    }

    /** A space of any kind, a non-breaking one (copied from a web page) too, or a tab. */
    private static boolean isBlank(char c) {
        return Character.isWhitespace(c) || Character.isSpaceChar(c);
    }

    private static String stripBlanks(String text) {
        int from = 0;
        int to = text.length();
        while (from < to && isBlank(text.charAt(from))) {
            from++;
        }
        while (to > from && isBlank(text.charAt(to - 1))) {
            to--;
        }
        return text.substring(from, to);
    }

    private static String quoted(String text) {
        return "'" + text + "'";
    }
}

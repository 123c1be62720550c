package simpview.scene.text;

import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.Locale;
import java.util.Set;

/**
 * A unit written with a number: {@code rotate Z 45deg}, {@code rotate Z 45 deg},
 * {@code translate 10px 0 0}. SIMP's numbers are plain: an angle is in
 * degrees, a length in world units. An error found there says which number
 * was meant and that it takes no unit; radians are worked out in degrees. A
 * ';' after a number is told that it separates nothing.
 */
public final class StuckUnit {

    /** Words a number's unit is commonly written as, standing alone after it. */
    private static final Set<String> UNIT_WORDS = Set.of("deg", "degs", "degree", "degrees", "rad", "rads",
            "radian", "radians", "px", "pixel", "pixels", "units");

    private StuckUnit() {
    }

    /**
     * What an error at a number followed straight away by {@code rest} adds:
     * a hint for letters (a unit) or a ';', else "".
     *
     * @param number the number as written, e.g. "45"
     * @param rest the rest of the token after it, e.g. "deg"
     */
    public static String afterNumber(String number, String rest) {
        if (rest.isEmpty()) {
            return "";
        }
        if (rest.charAt(0) == ';') {
            return ": ';' separates nothing here; blanks, commas and parentheses separate numbers";
        }
        if (!isLetters(rest)) {
            return "";
        }
        return ", the number " + number + " with '" + rest + "' stuck to it: " + noUnit(number, rest);
    }

    /** What "expected the end of the line, found 'deg'" adds when the text found starts with a unit word. */
    public static String alone(String found) {
        int wordEnd = 0;
        while (wordEnd < found.length() && Character.isLetter(found.charAt(wordEnd))) {
            wordEnd++;
        }
        String word = found.substring(0, wordEnd);
        if (!UNIT_WORDS.contains(word.toLowerCase(Locale.ROOT))) {
            return "";
        }
        return " (" + noUnit(null, word) + ")";
    }

    private static String noUnit(String number, String unit) {
        String plain = "a number takes no unit (an angle is in degrees, a length in world units)";
        if (unit.toLowerCase(Locale.ROOT).startsWith("rad")) {
            if (number == null) {
                return plain + ": write the angle in degrees";
            }
            try {
                return plain + ": " + number + " radians is " + degrees(Math.toDegrees(Double.parseDouble(number)))
                        + " degrees";
            } catch (NumberFormatException e) {
                return plain + ": write the angle in degrees";
            }
        }
        return number == null ? plain + ": leave '" + unit + "' out" : plain + ": write " + number;
    }

    /** An angle in degrees as a student would write it: to six places, no trailing zeros (85.943669). */
    static String degrees(double angle) {
        if (!Double.isFinite(angle)) {
            return String.valueOf(angle);
        }
        return BigDecimal.valueOf(angle).setScale(6, RoundingMode.HALF_EVEN).stripTrailingZeros().toPlainString();
    }

    private static boolean isLetters(String s) {
        for (int k = 0; k < s.length(); k++) {
            char c = s.charAt(k);
            if (!(c >= 'a' && c <= 'z' || c >= 'A' && c <= 'Z' || c == '%')) {
                return false;
            }
        }
        return true;
    }
}

package simpview.scene.text;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.charset.StandardCharsets;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class DecimalParserTest {

    private static void assertSameAsJava(String text) {
        long expected = Double.doubleToRawLongBits(Double.parseDouble(text));
        long actual = Double.doubleToRawLongBits(DecimalParser.parse(text));
        assertEquals(expected, actual, () -> text + ": parseDouble gives " + Double.parseDouble(text)
                + ", DecimalParser gives " + DecimalParser.parse(text));
    }

    @ParameterizedTest
    @ValueSource(strings = {"0", "-0", "+0", "0.0", "-0.0", "00", "1", "-1.5", ".3", "-.3", "5.", "2e3", "2E-3",
        "+4", "0.1", "0.7", "1.0000000000000002", "123456789012345", "1234567890123456", "12345678901234567890",
        "9007199254740993", "0.30000000000000004", "1e22", "1e23", "1e-22", "1e-23", "4.9e-324", "2e-324",
        "1.7976931348623157e308", "2.2250738585072014E-308", "1e-400", "0e999999999", "100000000000000000000000",
        "0.000000000000000000000000000001", "3.14159265358979323846", "1.500000000000000000000", "-20", "00.0010"})
    void agreesWithParseDouble(String text) {
        assertSameAsJava(text);
    }

    @Test
    void overflowGivesInfinityLikeParseDouble() {
        assertEquals(Double.POSITIVE_INFINITY, DecimalParser.parse("1e999"));
        assertEquals(Double.NEGATIVE_INFINITY, DecimalParser.parse("-1e99999999999999"));
    }

    @ParameterizedTest
    @ValueSource(strings = {"", "-", "+", ".", "-.", "e5", ".e5", "1e", "1e+", "NaN", "Infinity", "0x10", "1d",
        "1f", "1..2", "1.2.3", "--1", " 1", "1 ", "١"})
    void refusesWhatIsNotADecimal(String text) {
        assertThrows(NumberFormatException.class, () -> DecimalParser.parse(text));
    }

    @Test
    void scanStopsAtTheFirstCharacterAfterTheNumber() {
        byte[] b = "x-12.5e1, 7".getBytes(StandardCharsets.US_ASCII);
        DecimalParser p = new DecimalParser();
        assertEquals(8, p.scan(b, 1, b.length));
        assertEquals(-125.0, p.value());
        assertEquals(-1, p.scan(b, 8, b.length), "a comma starts no number");
    }

    @Property(tries = 3000, seed = "1202003")
    void randomDecimalStringsAgreeWithParseDouble(@ForAll("decimals") String text) {
        assertSameAsJava(text);
    }

    @Property(tries = 2000, seed = "1202004")
    void printedDoublesReadBackExactly(@ForAll double d) {
        if (Double.isFinite(d)) {
            assertSameAsJava(Double.toString(d));
            assertEquals(Double.doubleToRawLongBits(d), Double.doubleToRawLongBits(DecimalParser.parse(Double.toString(d))));
        }
    }

    @Provide
    Arbitrary<String> decimals() {
        Arbitrary<String> sign = Arbitraries.of("", "-", "+");
        Arbitrary<String> digits = Arbitraries.strings().withCharRange('0', '9').ofMinLength(0).ofMaxLength(22);
        Arbitrary<String> exponent = Combinators.combine(Arbitraries.of("", "e", "E", "e-", "e+", "E-"),
                Arbitraries.integers().between(0, 340))
                .as((e, n) -> e.isEmpty() ? "" : e + n);
        return Combinators.combine(sign, digits, Arbitraries.of(true, false), digits, exponent)
                .as((s, whole, point, fraction, exp) -> s + whole + (point ? "." + fraction : "") + exp)
                .filter(t -> t.chars().anyMatch(Character::isDigit) && mantissaHasDigit(t));
    }

    /** Digits before the exponent: "e5" alone is not a number. */
    private static boolean mantissaHasDigit(String t) {
        int e = Math.max(t.indexOf('e'), t.indexOf('E'));
        String mantissa = e < 0 ? t : t.substring(0, e);
        return mantissa.chars().anyMatch(Character::isDigit);
    }
}

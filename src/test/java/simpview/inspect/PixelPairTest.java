package simpview.inspect;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * One table of what the window's Go to pixel and inspect --at read, in the
 * panel (0 to 649) unless the row says page (0 to 749): the pixel read, as
 * "x,y", or the problem said, word for word.
 */
class PixelPairTest {

    private static final String PANEL_EXAMPLE = "; give x and y, two whole numbers in panel coordinates, for example "
            + "325,400 or (325, 400)";
    private static final String PANEL_RANGE = ", and x and y are 0 to 649, from the panel's bottom-left pixel, y up";

    static Stream<Arguments> table() {
        return Stream.of(
                // the command line's X,Y, blanks or none around the comma
                row("325,400", "325,400"),
                row("325, 400", "325,400"),
                row(" 325 , 400 ", "325,400"),
                // the window's: blanks alone, and parentheses as the inspector writes a pixel
                row("325 400", "325,400"),
                row("(325, 400)", "325,400"),
                row(" ( 3,4 ) ", "3,4"),
                row("(3 4)", "3,4"),
                // what the window's reading let through before stays: a run of commas and blanks, one after y
                row("325,,400", "325,400"),
                row("325, 400,", "325,400"),
                row("3\t4", "3,4"),
                // a non-breaking space, as a web page's copy has it, is a blank
                row("3,\u00A04", "3,4"),
                // signs, the panel's edges, digits of other scripts (full-width, Arabic-Indic)
                row("+3,-0", "3,0"),
                row("0,0", "0,0"),
                row("649,649", "649,649"),
                row("\uFF13,\uFF14", "3,4"),
                row("\u0663\u0662\u0665,4", "325,4"),
                row("0007,8", "7,8"),
                // the first assignment's page: 0 to 749
                page("749,700", "749,700"),
                page("750,0", "'750,0' is outside the page: x is 750, and x and y are 0 to 749, from the page's "
                        + "bottom-left pixel, y up"),
                // outside the panel, however large the number
                row("650,10", "'650,10' is outside the panel: x is 650" + PANEL_RANGE),
                row("-1,3", "'-1,3' is outside the panel: x is -1" + PANEL_RANGE),
                row("(700, -5)", "'(700, -5)' is outside the panel: x is 700 and y is -5" + PANEL_RANGE),
                row("99999999999,1", "'99999999999,1' is outside the panel: x is 99999999999" + PANEL_RANGE),
                row("1,-99999999999999999999",
                        "'1,-99999999999999999999' is outside the panel: y is -99999999999999999999" + PANEL_RANGE),
                row("\uFF16\uFF15\uFF10,1", "'\uFF16\uFF15\uFF10,1' is outside the panel: x is 650" + PANEL_RANGE),
                // not a pixel at all
                row("", "'' is not a pixel: it has no number" + PANEL_EXAMPLE),
                row(" ( ) ", "' ( ) ' is not a pixel: it has no number" + PANEL_EXAMPLE),
                row("3", "'3' is not a pixel: it has one part, not two (x and y)" + PANEL_EXAMPLE),
                row("1,2,3", "'1,2,3' is not a pixel: it has 3 parts, not two (x and y)" + PANEL_EXAMPLE),
                row("a,b", "'a,b' is not a pixel: its x, 'a', is not a whole number" + PANEL_EXAMPLE),
                row("3.5,4", "'3.5,4' is not a pixel: its x, '3.5', is not a whole number" + PANEL_EXAMPLE),
                row("3,4px", "'3,4px' is not a pixel: its y, '4px', is not a whole number" + PANEL_EXAMPLE),
                row("3,+", "'3,+' is not a pixel: its y, '+', is not a whole number" + PANEL_EXAMPLE),
                row("(3, 4", "'(3, 4' is not a pixel: its '(' is not closed" + PANEL_EXAMPLE),
                row("3, 4)", "'3, 4)' is not a pixel: its ')' closes no '('" + PANEL_EXAMPLE),
                row("((3, 4))", "'((3, 4))' is not a pixel: its x, '(3', is not a whole number" + PANEL_EXAMPLE));
    }

    private static Arguments row(String text, String expected) {
        return Arguments.of(text, "panel", 649, expected);
    }

    private static Arguments page(String text, String expected) {
        return Arguments.of(text, "page", 749, expected);
    }

    @ParameterizedTest
    @MethodSource("table")
    void readsAPixelOrSaysWhyNot(String text, String where, int last, String expected) {
        String got;
        try {
            PixelPair pixel = PixelPair.read(text, where, last);
            got = pixel.x() + "," + pixel.y();
        } catch (PixelPair.NotAPixel e) {
            got = e.getMessage();
        }
        assertEquals(expected, got, "reading '" + text + "'");
    }
}

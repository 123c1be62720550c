package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import picocli.CommandLine.TypeConversionException;

public class CompareOptionsTest {

    @Test
    void tolerancesInStepsOf255ths() {
        CompareOptions.Tolerance t = new CompareOptions.Tolerance();
        assertEquals(8, t.convert("8"));
        assertEquals(8, t.convert("8/255"));
        assertEquals(0, t.convert("0"));
        for (String bad : new String[] {"-1", "256", "0.5", "x", "8/256", ""}) {
            assertThrows(TypeConversionException.class, () -> t.convert(bad), bad);
        }
    }

    @Test
    void sharesInPercent() {
        CompareOptions.Share s = new CompareOptions.Share();
        assertEquals(99.5, s.convert("99.5%"));
        assertEquals(100.0, s.convert("100"));
        for (String bad : new String[] {"101", "-3", "NaN", "ninety"}) {
            assertThrows(TypeConversionException.class, () -> s.convert(bad), bad);
        }
    }

    /** 0.99 meant as 99 % would pass nearly any picture: a share between 0 and 1 is refused unless given with %. */
    @Test
    void aFractionWhereAShareInPercentGoesIsRefused() {
        CompareOptions.Share s = new CompareOptions.Share();
        TypeConversionException e = assertThrows(TypeConversionException.class, () -> s.convert("0.99"));
        assertEquals("'0.99' is a fraction, not a share in percent (0 to 100): for 99 %, write 99 (or 0.99% for "
                + "0.99 %)", e.getMessage());
        assertThrows(TypeConversionException.class, () -> s.convert("0.575"), "any fraction");
        assertEquals(0.99, s.convert("0.99%"), "a share under 1 % given with its sign is meant");
        assertEquals(0.0, s.convert("0"));
        assertEquals(1.0, s.convert("1"));
    }

    @Test
    void pageRanges() {
        CompareOptions.PageRangeConverter c = new CompareOptions.PageRangeConverter();
        CompareOptions.PageRange range = c.convert("1,3,6-8");
        for (int page = 1; page <= 8; page++) {
            assertEquals(page == 1 || page == 3 || page >= 6, range.contains(page), "page " + page);
        }
        assertFalse(range.contains(0));
        assertTrue(c.convert("1-8").contains(8));
        TypeConversionException backwards = assertThrows(TypeConversionException.class, () -> c.convert("1,8-6"));
        assertEquals("'1,8-6' is not a set of pages: the range 8-6 runs backwards, so it fits no page: write it 6-8",
                backwards.getMessage());
        for (String bad : new String[] {"0-8", "1-9", "1--3", "a", ""}) {
            TypeConversionException e = assertThrows(TypeConversionException.class, () -> c.convert(bad), bad);
            assertTrue(e.getMessage().contains("expected pages 1 to 8"), e.getMessage());
        }
    }
}

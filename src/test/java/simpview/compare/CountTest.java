package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** Counts in the reports: the noun in the singular for one, thousands separated. */
class CountTest {

    @Test
    void oneIsSingularAndEveryOtherCountPlural() {
        assertEquals("1 picture", Count.of(1, "picture"));
        assertEquals("0 pictures", Count.of(0, "picture"));
        assertEquals("1,234 pixels", Count.of(1234, "pixel"));
        assertEquals("1 patch", Count.of(1, "patch", "patches"));
        assertEquals("12 patches", Count.of(12, "patch", "patches"));
        assertEquals("1 pixel fails", Count.with(1, "pixel", "fails", "fail"));
        assertEquals("2,000 pixels fail", Count.with(2000, "pixel", "fails", "fail"));
    }
}

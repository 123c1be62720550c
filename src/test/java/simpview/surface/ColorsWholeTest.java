package simpview.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** {@link Colors#whole} is the cast to int for every whole number the packed-pixel loops give it, and beyond. */
class ColorsWholeTest {

    @Test
    void everyPackedLevelConvertsAsTheCastDoes() {
        for (int w = 0; w < 1 << 24; w++) {
            if (Colors.whole(w) != w) {
                assertEquals(w, Colors.whole(w), "the level " + w);
            }
        }
    }

    @Test
    void theRangesEdgesAndNegativeZero() {
        assertEquals(0, Colors.whole(-0.0));
        assertEquals(Integer.MAX_VALUE, Colors.whole(Integer.MAX_VALUE));
        assertEquals((1 << 30) + 12345, Colors.whole((1 << 30) + 12345));
        assertEquals(0xFFFFFF, Colors.whole(0xFFFFFF));
    }
}

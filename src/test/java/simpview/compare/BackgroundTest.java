package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.HashMap;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** {@link Background#mostCommon} against counting by hand, on panels of many colours, greys and ties. */
class BackgroundTest {

    /** The colour whose count first reaches the largest count, in pixel order: the rule, written plainly. */
    private static int byHand(int[] pixels, int[] where, int only) {
        Map<Integer, Integer> counts = new HashMap<>();
        int largest = 0;
        for (int i = 0; i < pixels.length; i++) {
            if (where == null || (where[i] & 0xFFFFFF) == only) {
                largest = Math.max(largest, counts.merge(pixels[i] & 0xFFFFFF, 1, Integer::sum));
            }
        }
        Map<Integer, Integer> again = new HashMap<>();
        for (int i = 0; i < pixels.length; i++) {
            if (where == null || (where[i] & 0xFFFFFF) == only) {
                if (again.merge(pixels[i] & 0xFFFFFF, 1, Integer::sum) == largest) {
                    return pixels[i] & 0xFFFFFF;
                }
            }
        }
        return 0;
    }

    private static int[] panel(long seed, int colours) {
        Random random = new Random(seed);
        int[] pixels = new int[650 * 650];
        for (int i = 0; i < pixels.length; i++) {
            int kind = random.nextInt(4);
            pixels[i] = random.nextInt(256) << 24 | switch (kind) {
                case 0 -> random.nextInt(256) * 0x010101; // greys, whose Integer hashes fold alike
                case 1 -> random.nextInt(colours);
                case 2 -> 0x000000;
                default -> random.nextInt(1 << 24);
            };
        }
        return pixels;
    }

    @Test
    void theMostCommonColourIsTheOneCountedByHand() {
        for (long seed = 1; seed <= 6; seed++) {
            int[] pixels = panel(seed, seed % 2 == 0 ? 5 : 70_000);
            assertEquals(byHand(pixels, null, 0), Background.mostCommon(pixels, null, 0), "seed " + seed);
            int[] where = panel(seed + 100, 3);
            int only = where[17] & 0xFFFFFF;
            assertEquals(byHand(pixels, where, only), Background.mostCommon(pixels, where, only), "seed " + seed);
        }
    }

    @Test
    void ofTwoAsCommonTheFirstToGetThereWins() {
        int[] pixels = {0x0000FF, 0xFF0000, 0xFF0000, 0x0000FF, 0x00FF00};
        assertEquals(0xFF0000, Background.mostCommon(pixels, null, 0)); // red reaches 2 first
        assertEquals(0x00FF00, Background.mostCommon(new int[] {0xFF00FF00}, null, 0));
        assertEquals(0, Background.mostCommon(new int[0], null, 0));
    }
}

package simpview.tools.shapes;

import java.util.Map;

/**
 * Block letters from boxes: each letter is a 5x7 pattern, and each horizontal
 * run of filled cells becomes one scaled unit cube ({@code file "cube"}), so
 * the letters show nested includes as well as transforms.
 */
final class BlockLetters {

    static final int WIDTH = 5;
    static final int HEIGHT = 7;
    /** Cells between two letters. */
    static final int GAP = 1;
    /** Thickness of the letters along z, in cells. */
    static final double DEPTH = 1.5;

    private static final Map<Character, String[]> GLYPHS = Map.of(
            'S', new String[] {".####", "#....", "#....", ".###.", "....#", "....#", "####."},
            'I', new String[] {"#####", "..#..", "..#..", "..#..", "..#..", "..#..", "#####"},
            'M', new String[] {"#...#", "##.##", "#.#.#", "#.#.#", "#...#", "#...#", "#...#"},
            'P', new String[] {"####.", "#...#", "#...#", "####.", "#....", "#....", "#...."});

    private BlockLetters() {
    }

    /**
     * The word in block letters, one cell per unit: from x = 0 rightward, y = 0
     * to 7, z = 0 back to -DEPTH.
     */
    static String word(String word) {
        SimpWriter w = Solids.header("the block letters \"" + word + "\": cells of 1 unit, "
                + (word.length() * (WIDTH + GAP) - GAP) + " wide, " + HEIGHT + " high, made of unit cubes");
        for (int k = 0; k < word.length(); k++) {
            String[] glyph = GLYPHS.get(word.charAt(k));
            if (glyph == null) {
                throw new IllegalArgumentException("no block letter for '" + word.charAt(k) + "'");
            }
            w.comment("letter " + word.charAt(k));
            letter(w, glyph, k * (WIDTH + GAP));
        }
        return w.toString();
    }

    private static void letter(SimpWriter w, String[] glyph, int left) {
        for (int row = 0; row < HEIGHT; row++) {
            String cells = glyph[row];
            int y = HEIGHT - 1 - row; // the pattern's first row is the top
            int x = 0;
            while (x < WIDTH) {
                if (cells.charAt(x) != '#') {
                    x++;
                    continue;
                }
                int runStart = x;
                while (x < WIDTH && cells.charAt(x) == '#') {
                    x++;
                }
                box(w, left + runStart, y, x - runStart);
            }
        }
    }

    private static void box(SimpWriter w, int x, int y, int length) {
        w.push().translate(x, y, -DEPTH).scale(length, 1, DEPTH).file("cube").pop();
    }
}

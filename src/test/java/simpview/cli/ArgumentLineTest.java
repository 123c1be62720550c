package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** -PappArgs="..." is split as a shell splits a line, so quoted paths stay whole. */
public class ArgumentLineTest {

    @Test
    void blanksSeparateWordsHoweverManyThereAre() {
        assertEquals(List.of("--seed", "7", "render"), ArgumentLine.split("  --seed  7\t render "));
        assertEquals(List.of(), ArgumentLine.split("   "));
    }

    @Test
    void quotedPathsWithSpacesStayWhole() {
        assertEquals(List.of("--simp-dir", "/home/ana/My Course/simp", "--out", "C:\\Users\\Bo\\a b.png"),
                ArgumentLine.split("--simp-dir '/home/ana/My Course/simp' --out \"C:\\\\Users\\\\Bo\\\\a b.png\""));
    }

    @Test
    void quotesJoinTheWordTheyAreIn() {
        assertEquals(List.of("--simp-dir=/a b/c", "it's"), ArgumentLine.split("--simp-dir='/a b'/c it\\'s"));
        assertEquals(List.of(""), ArgumentLine.split("''"));
    }

    @Test
    void insideDoubleQuotesOnlyQuoteAndBackslashAreEscaped() {
        assertEquals(List.of("say \"hi\" \\n"), ArgumentLine.split("\"say \\\"hi\\\" \\n\""));
    }

    @Test
    void anUnclosedQuoteIsNamed() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ArgumentLine.split("--simp-dir '/a b"));
        assertTrue(e.getMessage().contains("' at column 12 is never closed"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> ArgumentLine.split("\"open"));
    }

    @Test
    void theLineComesBeforeTheProgramsOwnArguments() {
        assertArrayEquals(new String[] {"render", "--out", "a b.png", "--page", "2"},
                Main.withAppArgs("render --out 'a b.png'", new String[] {"--page", "2"}));
        String[] own = {"--version"};
        assertArrayEquals(own, Main.withAppArgs(null, own));
    }
}

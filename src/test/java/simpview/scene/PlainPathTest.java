package simpview.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** A path without its "." parts, as the folder "." lists its files: bad.simp, not ./bad.simp. */
class PlainPathTest {

    private static String plain(String path) {
        return PlainPath.of(Path.of(path)).toString();
    }

    @Test
    void theDotPartsAreLeftOut() {
        assertEquals("bad.simp", plain("./bad.simp"));
        assertEquals("bad.simp", PlainPath.of(Path.of(".").resolve("bad.simp")).toString());
        assertEquals("pics/page1.png", plain("./pics/./page1.png"));
        assertEquals("/tmp/pics/page1.png", plain("/tmp/./pics/page1.png"));
    }

    /** ".." through a link to a folder leads elsewhere than the name before it: it stays. */
    @Test
    void twoDotsAndADotAloneStay() {
        assertEquals("../course/cube.simp", plain("./../course/./cube.simp"));
        assertEquals("parts/../cube.simp", plain("parts/../cube.simp"));
        assertEquals(".", plain("."));
        assertEquals(".hidden/a.png", plain("./.hidden/a.png"));
    }
}

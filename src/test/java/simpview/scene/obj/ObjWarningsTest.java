package simpview.scene.obj;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;
import simpview.scene.SceneException;

/**
 * What reading a model warns of without stopping: each warning names the
 * file, and a model kept and replayed gives the same warnings as streaming it.
 */
class ObjWarningsTest {

    private static List<String> warnings(String text) throws SceneException {
        byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
        ObjCounts streamed = ObjReader.stream(ObjReaderTest.NAME, bytes, face -> { });
        assertEquals(streamed, ObjModel.of(ObjReaderTest.NAME, bytes).counts(), "the kept model's counts");
        return streamed.warnings();
    }

    private static final String HINT = "(a comma separates two numbers: one and a half is 1.5, not 1,5)";

    /**
     * A model saved under a German or French locale: SPEC reads "0,5" as two
     * numbers, so each v line is a position and a colour, drawn; the first
     * such line is named, at its first such number.
     */
    @Test
    void decimalCommasThatMakeAnotherCountAVertexTakesAreNamed() throws SceneException {
        assertEquals(List.of("model.obj:2:4: '-1,0' is read as two numbers, so this v line's 6 numbers are"
                + " x y z r g b " + HINT + "; this is the first such line"),
                warnings("# saved in Berlin\nv  -1,0 0,5 -4,0\nv 1,0 0,0 -4,0\nv 0,0 1,0 -4,0\nf 1 2 3\n"));
        assertEquals(List.of("model.obj:1:3: '1,5' is read as two numbers, so this v line's 4 numbers are"
                + " x y z w " + HINT + "; this is the first such line"), warnings("v 1,5 2 3\n"));
    }

    @Test
    void commasThatCannotBeDecimalCommasWarnOfNothing() throws SceneException {
        assertEquals(List.of(), warnings("v 1,2,3\nv (1,5, 2, 3)\nv 1, 2, 3, 0.5, 0.5, 0.5\nv 0.5,1 2 3\nv 1,5,2 3\nf 1,2,3\n"));
    }
}

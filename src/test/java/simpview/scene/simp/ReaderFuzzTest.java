package simpview.scene.simp;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import simpview.scene.SceneException;

/** Whatever the bytes, reading them ends normally or with a SceneException: nothing else escapes. */
class ReaderFuzzTest {

    @Property(tries = 2000, seed = "1202006")
    void anyTextGivesCommandsOrASceneException(@ForAll("simpLike") String text) {
        SimpReader r = SimpReader.of(Path.of("fuzz.simp"), text.getBytes(StandardCharsets.UTF_8));
        Command c = new Command();
        try {
            while (r.next(c)) {
                // keep reading
            }
        } catch (SceneException e) {
            if (e.line() < 1 || e.column() < 0 || e.getMessage().isEmpty()) {
                throw new AssertionError("badly located error: " + e.getMessage());
            }
        }
    }

    @Provide
    Arbitrary<String> simpLike() {
        Arbitrary<String> pieces = Arbitraries.of("{", "}", "scale", "translate", "rotate", "line", "polygon", "file",
                "wire", "filled", " ", "\t", ",", "(", ")", "\"", "X", "Y", "z", "1", "-2.5", ".3", "1e999", "e",
                "#", "\n", "\r\n", "NaN", "+", "é", "\u0000");
        return pieces.list().ofMaxSize(40).map(l -> String.join("", l));
    }
}

package simpview.scene.simp;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;

/** The quick reading of points gives what the careful reading gives: the same commands or the same error. */
class QuickPathTest {

    @Property(tries = 3000)
    void quickAndCarefulReadTheSame(@ForAll("pointLines") String text) {
        assertEquals(read(text, false), read(text, true), text);
    }

    /** Every command as text (kind, colours, numbers as bits), then the error message if there is one. */
    private static List<String> read(String text, boolean careful) {
        SimpReader r = SimpReader.of(Path.of("q.simp"), text.getBytes(StandardCharsets.UTF_8));
        if (careful) {
            r.carefulOnly();
        }
        List<String> out = new ArrayList<>();
        Command c = new Command();
        try {
            while (r.next(c)) {
                StringBuilder sb = new StringBuilder(c.kind() + " " + c.colored() + " " + c.argumentIndex);
                for (int k = 0; k < c.vertexCount(); k++) {
                    for (int i = 0; i < 3; i++) {
                        sb.append(' ').append(Double.doubleToRawLongBits(c.coordinate(k, i)))
                                .append('/').append(Double.doubleToRawLongBits(c.color(k, i)));
                    }
                }
                out.add(sb.toString());
            }
        } catch (SceneException e) {
            out.add(e.getMessage());
        }
        return out;
    }

    @Provide
    Arbitrary<String> pointLines() {
        Arbitrary<String> pieces = Arbitraries.of("polygon", "line", " ", "\t", ",", ", ", "(", ")", "(1,2,3)",
                " (0, 0, 0)", "(-1.5 .5 2e3)", "1", "-2.5", ".3", "1e999", "1e", "5.", "x", "#", "\n", "\r\n",
                "polygon (0,0,0) (1,0,0) (0,1,0)", "line (1,1,1)(2,2,2)", "(1,0,0)(0,1,0)(0,0,1)", "+", "--1",
                "0.30000000000000004", "12345678901234567890", "9007199254740993");
        return pieces.list().ofMaxSize(30).map(l -> String.join("", l));
    }
}

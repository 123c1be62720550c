package simpview.scene.simp;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.scene.FileChecksum;
import simpview.scene.SceneException;

/** Replaying a small file's recorded commands is indistinguishable from reading its bytes again. */
class RecordingTest {

    private static final Path FILE = Path.of("r.simp");

    @Property(tries = 1000, seed = "1202005")
    void replayGivesWhatReadingGives(@ForAll("scenes") String text) throws SceneException {
        byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
        SimpReader first = SimpReader.recording(FILE, bytes);
        List<String> read = everything(first);
        Recording recording = first.finishedRecording();
        assertEquals(read, everything(SimpReader.of(FILE, bytes)));
        assertEquals(read, everything(SimpReader.replaying(FILE, bytes, recording, FileChecksum.of(bytes))));
    }

    /** Per command: what it says, where it stands, and the errors that would point into it; then the line count. */
    private static List<String> everything(SimpReader r) throws SceneException {
        List<String> out = new ArrayList<>();
        Command c = new Command();
        while (r.next(c)) {
            StringBuilder sb = new StringBuilder(c.kind() + " " + c.colored() + " " + r.lineNumber() + " "
                    + r.linesRead() + " " + r.lineText());
            for (int k = 0; k < Math.max(1, c.vertexCount()); k++) {
                for (int i = 0; i < 3; i++) {
                    sb.append(' ').append(Double.doubleToRawLongBits(c.coordinate(k, i)))
                            .append('/').append(Double.doubleToRawLongBits(c.color(k, i)));
                }
            }
            if (c.kind() == Command.Kind.ROTATE) {
                sb.append(' ').append(c.axis()).append(' ').append(Double.doubleToRawLongBits(c.angle()));
            }
            if (c.kind() == Command.Kind.FILE) {
                sb.append(' ').append(c.fileName()).append(' ').append(r.error(c.argumentIndex, "a").getMessage());
            }
            out.add(sb.append('\n').append(r.error(c.commandIndex, "c").getMessage()).toString());
        }
        out.add("lines " + r.linesRead() + " " + r.lineNumber());
        return out;
    }

    @Provide
    Arbitrary<String> scenes() {
        Arbitrary<String> lines = Arbitraries.of("{", "}", "  }  ", "scale 1 2 3", "translate 1, 0, -2.5",
                "rotate X 30", "rotate Z -90", "line (0,0,0) (1,1,1)", "line (0,0,0) (1,0,0) (1,1,1) (0,1,0)",
                "polygon (1,2,3) (4,5,6) (7,8,9)", "\tpolygon (1 2 3)(1 0 0) (4,5,6)(0,1,0) (7,8,9)(0,0,1)",
                "file \"cube\"", "file sphere", "wire", "filled", "", "   ", "# comment", "\r", "# é");
        return Combinators.combine(Arbitraries.of("", "\uFEFF"), lines.list().ofMaxSize(40))
                .as((bom, l) -> bom + String.join("\n", l));
    }

    @TempDir
    Path dir;

    @Test
    void errorInAReplayedFileIsReportedAsOnAFirstReading() throws IOException {
        Files.writeString(dir.resolve("pop.simp"), "# pops\n\n  polygon (0,0,-1) (1,0,-1) (0,1,-1)\n  }\n");
        Files.writeString(dir.resolve("top.simp"), "{\n{\nfile pop\nfile pop\nfile \"pop\"\n");
        SceneException cached = new SceneFixture(dir).failure("top");
        SceneFixture streaming = new SceneFixture(dir);
        SceneException streamed = null;
        try {
            streaming.run("top", new FileStack(-1));
        } catch (SceneException e) {
            streamed = e;
        }
        assertEquals(streamed.getMessage(), cached.getMessage());
        assertEquals(4, cached.line());
        assertEquals(3, cached.column());
        assertEquals("pop.simp", cached.file().getFileName().toString());
    }
}

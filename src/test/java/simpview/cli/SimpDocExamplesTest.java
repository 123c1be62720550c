package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.api.io.TempDir;
import simpview.surface.PageCanvas;

/**
 * The examples of docs/simp.md, drawn as a student would draw them
 * ({@code simpview render --scene}), so the language's description cannot
 * go stale: every ```simp block renders without error to a picture with
 * something on it, and every ```simp-error block fails with the
 * file:line:column message the document shows.
 */
public class SimpDocExamplesTest {

    private static final Pattern BLOCK = Pattern.compile("(?m)^```(simp[a-z-]*)\\n(.*?)^```$", Pattern.DOTALL);
    private static final Pattern FILE_NAME = Pattern.compile("\\A# file: (\\S+\\.simp)\\n");

    @TempDir
    static Path dir;

    private record Example(int number, String kind, String text) {
        String fileName() {
            Matcher m = FILE_NAME.matcher(text);
            return m.find() ? m.group(1) : "example" + number + ".simp";
        }
    }

    private static List<Example> examples() throws IOException {
        Path doc = Path.of(System.getProperty("simpview.projectDir", ".")).resolve("docs/simp.md");
        Matcher m = BLOCK.matcher(Files.readString(doc));
        List<Example> examples = new ArrayList<>();
        while (m.find()) {
            examples.add(new Example(examples.size() + 1, m.group(1), m.group(2)));
        }
        return examples;
    }

    @Test
    void theDocumentHasExamplesOfEveryKind() throws IOException {
        List<String> kinds = examples().stream().map(Example::kind).toList();
        assertTrue(kinds.stream().filter("simp"::equals).count() >= 6, "depth-cued examples: " + kinds);
        assertTrue(kinds.contains("simp-error") && kinds.contains("simp-lit"), kinds.toString());
        assertTrue(Set.of("simp", "simp-error", "simp-lit", "simp-colour").containsAll(kinds),
                "an unknown kind of block: " + kinds);
    }

    @TestFactory
    Stream<DynamicTest> everyExampleDrawsOrFailsAsTheDocumentSays() throws IOException {
        List<Example> all = examples();
        for (Example e : all) {
            Files.writeString(dir.resolve(e.fileName()), e.text()); // before any runs: examples include others
        }
        return all.stream().map(e -> DynamicTest.dynamicTest("example " + e.number() + " (" + e.kind() + ", " + e.fileName() + ")",
                        () -> check(e)));
    }

    private static void check(Example e) throws IOException {
        Path scene = dir.resolve(e.fileName());
        Path png = dir.resolve(e.fileName().replace(".simp", ".png"));
        CliRun run = CliRun.of("render", "--scene", scene.toString(), "--out", png.toString());
        assertFalse(run.showsStackTrace(), run.err());
        if (e.kind().equals("simp-error")) {
            assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.err());
            assertTrue(run.err().matches("(?s)" + Pattern.quote(scene.toString()) + ":\\d+:\\d+: .+\\n {4}.+\\n *\\^\\n?"),
                    "file:line:col, the line and a caret: " + run.err());
            return;
        }
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        if (e.kind().equals("simp-colour")) {
            // depth-cued, so the colours are not drawn, and the one warning says where and how to draw them
            assertTrue(run.err().matches("warning: " + Pattern.quote(e.fileName())
                    + ":\\d+: the vertices' own colours are not drawn: [^\n]*\n"), run.err());
        } else {
            assertEquals("", run.err(), "no warnings");
        }
        assertTrue(litPixels(ImageIO.read(png.toFile())) > 0, "the picture of " + e.fileName() + " is empty");
    }

    private static int litPixels(BufferedImage image) {
        int lit = 0;
        for (int y = PageCanvas.MARGIN; y < PageCanvas.SIZE - PageCanvas.MARGIN; y++) {
            for (int x = PageCanvas.MARGIN; x < PageCanvas.SIZE - PageCanvas.MARGIN; x++) {
                lit += (image.getRGB(x, y) & 0xFFFFFF) != 0 ? 1 : 0;
            }
        }
        return lit;
    }
}

package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Which files a line that could not be run names as its outputs, to be released for their readers. */
class NamedOutputsTest {

    @TempDir
    Path dir;

    private List<Path> named(List<String> options, String... line) {
        return NamedOutputs.filesNamed(options, line);
    }

    @Test
    void theValuesOfTheOutputOptionsAreNamedUpToTheDoubleDash() {
        String f = dir.resolve("f.png").toString();
        assertEquals(List.of(Path.of(f)), named(List.of("--out"), "render", "--page", "1", "--out", f, "--sede", "3"));
        assertEquals(List.of(Path.of(f)), named(List.of("--out"), "render", "--page", "1", "--out=" + f));
        assertEquals(List.of(), named(List.of("--out"), "render", "--sede", "3", "--", "--out", f));
        assertEquals(List.of(), named(List.of("--primitives"), "render", "--page", "1", "--primitives", "-"));
    }

    /** A file named by two output options, or twice by one, is one file: released once, its reader not given two ends. */
    @Test
    void aFileNamedTwiceIsNamedOnce() {
        String f = dir.resolve("f.png").toString();
        String same = dir.resolve("sub").resolve("..").resolve("f.png").toString();
        assertEquals(List.of(Path.of(f)), named(List.of("--out", "--primitives"),
                "render", "--page", "1", "--out", f, "--primitives", same, "--sede", "3"));
        assertEquals(List.of(Path.of(f)), named(List.of("--out"), "render", "--out", f, "--out=" + f, "--sede"));
    }

    /**
     * A file the line also names otherwise is left alone: the picture to compare given again as --diff, the scene
     * again as --primitives, a scene after "--", or --scene=F. It may be an input, fed by another program through
     * a FIFO: opening it would let that program write into nothing.
     */
    @Test
    void aFileTheLineAlsoNamesOtherwiseIsNoOutputToRelease() {
        String mine = dir.resolve("mine.png").toString();
        String scene = dir.resolve("house.simp").toString();
        String diff = dir.resolve("diff.png").toString();
        assertEquals(List.of(), named(List.of("--diff"), "compare", mine, "--page", "2", "--diff", mine, "--tolerence", "3"));
        assertEquals(List.of(Path.of(diff)), named(List.of("--diff"),
                "compare", mine, "--page", "2", "--diff", diff, "--tolerence", "3"));
        assertEquals(List.of(), named(List.of("--out", "--primitives"), "render", "--scene=" + scene, "--primitives",
                scene, "--sede", "3"));
        assertEquals(List.of(), named(List.of("--out"), "render", "--out", scene, "--sede", "3", "--", scene));
    }
}

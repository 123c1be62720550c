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
        return NamedOutputs.filesNamed(options, List.of(), line);
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

    private List<Path> ofLine(NamedOutputs.OfCommand command, String... line) {
        return NamedOutputs.filesNamed(command, line);
    }

    /**
     * render's --out-dir files are known when the words name --all, --page N or --scene F alone (and an
     * assignment that has the page); the pictures of --scenes or of scene files, and a page named twice or not as
     * a number, are not: the options that could not be read may say otherwise.
     */
    @Test
    void renderReleasesInItsFolderOnlyThePicturesItsWordsName() {
        String d = dir.resolve("out").toString();
        RenderCommand render = new RenderCommand();
        assertEquals(List.of(Path.of(d, "a1-page1.png"), Path.of(d, "a1-page5.png")), List.of(
                ofLine(render, "--assignment", "1", "--all", "--out-dir", d, "--sede").get(0),
                ofLine(render, "--assignment", "1", "--all", "--out-dir", d, "--sede").get(4)));
        assertEquals(8, ofLine(render, "--all", "--out-dir", d, "--sede").size());
        assertEquals(List.of(Path.of(d, "page7.png")), ofLine(render, "--page", "7", "--out-dir=" + d, "--sede"));
        assertEquals(List.of(Path.of(d, "cube.png")), ofLine(render, "--scene", "a3/cube.simp", "--out-dir", d, "-x"));
        assertEquals(List.of(), ofLine(render, "--page", "7", "--all", "--out-dir", d));
        assertEquals(List.of(), ofLine(render, "--page", "seven", "--out-dir", d));
        assertEquals(List.of(), ofLine(render, "--assignment", "1", "--page", "7", "--out-dir", d));
        assertEquals(List.of(), ofLine(render, "--assignment", "3", "--all", "--out-dir", d));
        assertEquals(List.of(), ofLine(render, "--scenes", "a.simp", "b.simp", "--out-dir", d, "--sede"));
        assertEquals(List.of(), ofLine(render, "--all", "--sede", "--", "--out-dir", d));
    }

    /**
     * compare's tables go to --out-dir, or to --html's folder without it, and index.html to --html's folder: each
     * file once, however many options name its folder. Its diff images are named for the pictures found, not known.
     */
    @Test
    void compareReleasesItsTablesAndItsWebReport() {
        String d = dir.resolve("out").toString();
        String h = dir.resolve("web").toString();
        CompareCommand compare = new CompareCommand();
        assertEquals(List.of(Path.of(d, "compare.md"), Path.of(d, "compare.csv"), Path.of(d, "totals.csv"),
                Path.of(h, "index.html")), ofLine(compare, "--dir", "subs", "--out-dir", d, "--html", h, "--pages", "one"));
        assertEquals(List.of(Path.of(h, "compare.md"), Path.of(h, "compare.csv"), Path.of(h, "totals.csv"),
                Path.of(h, "index.html")), ofLine(compare, "--dir", "subs", "--html", h, "--pages", "one"));
        assertEquals(List.of(Path.of(d, "compare.md"), Path.of(d, "compare.csv"), Path.of(d, "totals.csv")),
                ofLine(compare, "--dir", "subs", "--out-dir", d, "--html", d, "--pages", "one").subList(0, 3));
        assertEquals(4, ofLine(compare, "--dir", "subs", "--out-dir", d, "--html", d, "--pages", "one").size());
    }
}

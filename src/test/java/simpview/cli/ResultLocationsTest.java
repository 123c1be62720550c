package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;

/**
 * Where a batch's results go is looked at before any picture is compared:
 * a place they cannot go is said with its reason, and two reports named one
 * file are a usage error.
 */
class ResultLocationsTest {

    @TempDir
    Path dir;

    private Path subs;
    private Path aFile;

    @BeforeEach
    void aFolderOfOnePictureAndAFile() throws Exception {
        subs = Files.createDirectories(dir.resolve("subs"));
        ImageIO.write(new PageRenderer().renderImage(1, PageContext.defaults()), "png", subs.resolve("page1.png").toFile());
        aFile = Files.writeString(dir.resolve("afile"), "not a folder");
    }

    /** The run stopped before comparing, saying {@code message}; the file in the way is kept. */
    private void cannotWrite(CliRun run, String command, String message) throws Exception {
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out() + run.err());
        assertEquals("simpview " + command + ": cannot write the results: " + message,
                run.err().lines().findFirst().orElse(""), run.err());
        assertFalse(run.err().contains("[1/1]"), "no picture compared: " + run.err());
        assertEquals("", run.out());
        assertFalse(run.showsStackTrace(), run.err());
        assertEquals("not a folder", Files.readString(aFile));
    }

    @Test
    void aFileWhereTheResultsFolderGoesIsSaidWithItsReasonBeforeComparing() throws Exception {
        String inTheWay = aFile + " is in the way: it is a file, not a folder";
        cannotWrite(CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--out-dir", aFile.toString()),
                "compare", "--out-dir " + aFile + ": " + inTheWay);
        cannotWrite(CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--html", aFile.toString()),
                "compare", "--html " + aFile + ": " + inTheWay);
        cannotWrite(CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--junit",
                aFile.resolve("r.xml").toString()), "compare", "--junit " + aFile.resolve("r.xml") + ": " + inTheWay);
        cannotWrite(CliRun.of("check", subs.toString(), "--pages", "1", "--out-dir", aFile.resolve("deeper/r").toString()),
                "check", "--out-dir " + aFile.resolve("deeper/r") + ": " + inTheWay);
    }

    @Test
    void aFolderWhereAReportGoesIsSaidBeforeComparing() throws Exception {
        Path folder = Files.createDirectories(dir.resolve("results.json"));
        cannotWrite(CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--gradescope", folder.toString()),
                "compare", "--gradescope " + folder + ": " + folder + " is a folder");
        Path report = dir.resolve("report");
        Files.createDirectories(report.resolve("compare.md"));
        cannotWrite(CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--out-dir", report.toString()),
                "compare", "--out-dir " + report + ": " + report.resolve("compare.md") + " is a folder");
    }

    @Test
    void twoReportsNamingOneFileAreAUsageError() throws Exception {
        Path both = dir.resolve("g.json");
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--gradescope", both.toString(),
                "--junit", both.toString());
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), run.err());
        assertEquals("simpview: --gradescope and --junit both write " + both + "; give each its own file",
                run.err().lines().findFirst().orElse(""));
        assertTrue(run.err().contains("See 'simpview compare --help'"), run.err());
        assertFalse(Files.exists(both));

        Path report = dir.resolve("report");
        Path csv = report.resolve("compare.csv");
        run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--out-dir", report.toString(), "--junit",
                csv.toString());
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), run.err());
        assertEquals("simpview: --out-dir and --junit both write " + csv + "; give each its own file",
                run.err().lines().findFirst().orElse(""));
        assertFalse(Files.exists(report));
    }

    @Test
    void theResultsAndTheirFoldersAreWrittenWhenNothingStandsInTheWay() throws Exception {
        Path report = dir.resolve("new/report");
        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--out-dir", report.toString(),
                "--html", report.toString(), "--gradescope", dir.resolve("new/g/results.json").toString());
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        for (String written : new String[] {"report/compare.md", "report/compare.csv", "report/index.html",
            "report/diffs/page1-diff.png", "g/results.json"}) {
            assertTrue(Files.isRegularFile(dir.resolve("new").resolve(written)), written);
        }
    }
}

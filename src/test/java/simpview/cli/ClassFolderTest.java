package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;

/**
 * A class's folder as a teacher has it on disk: unzipped into a folder of its own, or with links in it. Each
 * student's pictures are graded as that student's, and nothing handed in is passed over without a word.
 */
class ClassFolderTest {

    @TempDir
    Path dir;

    private static BufferedImage page(int number) throws Exception {
        return new PageRenderer().renderImage(number, PageContext.defaults());
    }

    private static void png(Path file, BufferedImage image) throws Exception {
        Files.createDirectories(file.getParent());
        ImageIO.write(image, "png", file.toFile());
    }

    /**
     * A link to a picture that is not there was passed over: the student, whose folder lists page2.png, was told
     * no picture of page 2 was found. It is a row saying where the link leads.
     */
    @Test
    void aLinkToNothingIsARowSayingSo() throws Exception {
        Path mine = dir.resolve("mine");
        png(mine.resolve("page1.png"), page(1));
        Path nowhere = dir.resolve("gone/page2.png");
        Files.createSymbolicLink(mine.resolve("page2.png"), nowhere);

        CliRun check = CliRun.of("check", mine.toString(), "--pages", "1-2");

        assertEquals(ExitCode.SCENE_ERROR, check.exitCode(), check.out() + check.err());
        assertTrue(check.out().contains("page2.png  page 2 (seed 361)  ERROR             " + mine.resolve("page2.png")
                + " is a link to " + nowhere + ", which does not exist: put the picture itself in its place\n"),
                check.out());
        assertFalse(check.out().contains("no picture of page 2"), check.out());
        assertFalse(check.showsStackTrace(), check.err());
    }

    /**
     * A link to a folder of pictures (renders -> ../build/renders) was not looked into: its pages were missing.
     * Its pictures are graded; a link back up to a folder on the way is no endless walk.
     */
    @Test
    void aLinkedFolderIsLookedIntoAndALinkBackUpIsNoLoop() throws Exception {
        Path mine = dir.resolve("mine");
        png(mine.resolve("page1.png"), page(1));
        png(dir.resolve("build/renders/page2.png"), page(2));
        Files.createSymbolicLink(mine.resolve("renders"), dir.resolve("build/renders"));
        Files.createSymbolicLink(mine.resolve("renders-again"), mine);

        CliRun check = CliRun.of("check", mine.toString(), "--pages", "1-2");

        assertEquals(ExitCode.OK, check.exitCode(), check.out() + check.err());
        assertTrue(check.out().contains("renders/page2.png  page 2 (seed 361)  PASS"), check.out());
        assertTrue(check.out().endsWith("2 of 2 pictures pass\n"), check.out());
    }
}

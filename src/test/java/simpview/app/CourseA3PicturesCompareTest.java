package simpview.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Disabled;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import simpview.compare.CourseFiles;
import simpview.compare.IndependentShares;
import simpview.compare.Picture;

/**
 * The A3 pages (lit scenes: camera, lighting, .obj) against the course's own
 * pictures in reference/images/a3 (window captures; the panel is found). The
 * shares printed must agree with an independent computation, and each page
 * must reach the share measured minus {@link #MARGIN}.
 *
 * <p>TO SET AFTER MEASURING (lead): once simpview draws lit scenes, run
 * {@code simpview compare ../shared/reference/images/a3/pageA.png --scene
 * ../shared/course-simp-a3/pageA.simp} for each page, and put the printed
 * "within 8/255 with slack" share in {@code MEASURED_WITHIN_8_SLACK} below
 * (the -1 placeholders fail on purpose, so none can be forgotten).
 */
@Disabled("enabled when simpview draws lit scenes (issue 11)")
class CourseA3PicturesCompareTest {

    /** How far below the measured share a page may fall, in percentage points. */
    static final double MARGIN = 0.5;

    @ParameterizedTest(name = "{0}")
    @CsvSource({
        // scene, the course's picture, MEASURED_WITHIN_8_SLACK (percent; -1 = not measured yet)
        "pageA.simp, pageA.png, -1",
        "pageB.simp, pageB.png, -1",
        "pageC.simp, pageC.png, -1",
        "pageD.simp, pageD.png, -1",
        "pageE.simp, pageE.png, -1",
        "pageF.simp, pageF.png, -1",
        "pageG.simp, pageG.png, -1",
        "pageH.simp, pageH.png, -1",
        "pageI.simp, pageI.png, -1",
        "tomsPageJ.simp, pageJ_tomsPageJ.png, -1"})
    void sceneAgainstTheCoursesPicture(String scene, String pictureName, double measured) throws Exception {
        assertTrue(measured >= 0, scene + ": its share is not measured yet; set MEASURED_WITHIN_8_SLACK");
        Path file = CourseFiles.require("course-simp-a3/" + scene);
        Path picture = CourseFiles.require("reference/images/a3/" + pictureName);
        Path ours = Path.of(System.getProperty("java.io.tmpdir")).resolve("simpview-a3-" + scene + ".png");
        CliRun render = CliRun.of("render", "--scene", file.toString(), "--out", ours.toString());
        assertEquals(Main.OK, render.exitCode(), render.err());
        CliRun run = CliRun.of("compare", picture.toString(), "--scene", file.toString());
        System.out.println(run.out());

        double[] printed8 = CompareCommandTest.printed(run.out(), "within 8/255");
        assertTrue(printed8[1] >= measured - MARGIN, scene + ": within 8/255 with slack " + printed8[1]);
        Picture theirs = Picture.read(picture);
        assertEquals(51, theirs.place().left());
        assertEquals(81, theirs.place().top());
        BufferedImage oursImage = ImageIO.read(ours.toFile());
        BufferedImage theirsImage = ImageIO.read(picture.toFile());
        assertEquals(CompareCommandTest.asPrinted(IndependentShares.direct(oursImage, 50, 50, theirsImage, 51, 81, 8)),
                printed8[0]);
        assertEquals(CompareCommandTest.asPrinted(IndependentShares.withSlack(oursImage, 50, 50, theirsImage, 51, 81, 8)),
                printed8[1]);
    }
}

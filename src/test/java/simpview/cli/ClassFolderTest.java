package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static simpview.testing.Images.page;
import static simpview.testing.Images.writePng;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A class's folder as a teacher has it on disk: unzipped into a folder of its own, or with links in it. Each
 * student's pictures are graded as that student's, and nothing handed in is passed over without a word.
 */
class ClassFolderTest {

    @TempDir
    Path dir;

    /**
     * subs/class/ann and subs/class/bob: graded as subs, the whole class was one submission, ann's page 1
     * counted, bob's wrong one "not counted", and the run passed. It is graded as subs/class, and says so.
     */
    @Test
    void aClassUnzippedIntoAFolderOfItsOwnIsGradedStudentByStudent() throws Exception {
        Path subs = dir.resolve("subs");
        writePng(subs.resolve("class/ann/page1.png"), page(1));
        writePng(subs.resolve("class/bob/page1.png"), page(2)); // wrong
        Path xml = dir.resolve("results.xml");
        Path out = dir.resolve("out");

        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--out-dir", out.toString(),
                "--junit", xml.toString());

        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), "bob's page 1 fails: " + run.out() + run.err());
        assertTrue(run.err().contains("simpview compare: every picture in " + subs + " is in "
                + subs.resolve("class") + ": its folders (ann, bob) are graded as the submissions, as --dir "
                + subs.resolve("class") + " grades them\n"), run.err());
        assertTrue(run.out().contains("| bob/page1.png | 1 (seed 361) |"), run.out());
        assertFalse(run.out().contains("not counted"), run.out());
        assertTrue(run.out().contains("2 pictures: 1 pass, 1 fail, 0 could not be compared, 0 skipped\n"), run.out());
        String junit = Files.readString(xml);
        assertTrue(junit.contains("<testsuite name=\"bob\" id=\"1\" tests=\"1\" failures=\"1\""), junit);
    }

    /**
     * A class's A3 pictures named each by its student (ann_pageA.png, bob-pageA.png) in subs/class: they name the
     * same scene of --scene's folder, so subs/class is a class's folder, graded student by student.
     */
    @Test
    void aClassOfScenePicturesNamedByTheirStudentsIsAClass() throws Exception {
        Path scenes = dir.resolve("scenes");
        Files.createDirectories(scenes);
        Files.writeString(scenes.resolve("pageA.simp"), "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n");
        Path subs = dir.resolve("subs");
        for (Path picture : new Path[] {subs.resolve("class/ann/ann_pageA.png"), subs.resolve("class/bob/bob-pageA.png")}) {
            Files.createDirectories(picture.getParent());
            assertEquals(ExitCode.OK, CliRun.of("render", "--scene", scenes.resolve("pageA.simp").toString(), "--out",
                    picture.toString()).exitCode());
        }

        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--scene", scenes.toString(), "--out-dir",
                dir.resolve("out").toString());

        assertEquals(ExitCode.OK, run.exitCode(), run.out() + run.err());
        assertTrue(run.err().contains("its folders (ann, bob) are graded as the submissions"), run.err());
        assertFalse(run.out().contains("not counted"), run.out());
    }

    /**
     * A picture named like no page at the top of a class's folder (the teacher's example.png) made the top a
     * submission lacking every page: a MISSING row "at the top of the folder", a JUnit failure, exit 1, while
     * every student passed. It is a skipped row and nobody's pages.
     */
    @Test
    void aPictureOfNoPageBesideTheStudentsFoldersAsksNothing() throws Exception {
        Path subs = dir.resolve("subs");
        writePng(subs.resolve("ann/page1.png"), page(1));
        writePng(subs.resolve("bob/page1.png"), page(1));
        writePng(subs.resolve("example.png"), page(1));
        Path xml = dir.resolve("results.xml");

        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--out-dir",
                dir.resolve("out").toString(), "--junit", xml.toString());

        assertEquals(ExitCode.OK, run.exitCode(), run.out() + run.err());
        assertTrue(run.out().contains("| example.png |  |  |  |  |  |  |  |  | SKIPPED |"), run.out());
        assertFalse(run.out().contains("MISSING"), run.out());
        String junit = Files.readString(xml);
        assertTrue(junit.contains("<testsuite name=\"submission\" id=\"2\" tests=\"1\" failures=\"0\" errors=\"0\" "
                + "skipped=\"1\">"), junit);
    }

    /** A student's own folder nested so (subs/A2/page1.png, pictures at its top) is one submission, as given. */
    @Test
    void aStudentsFolderNestedInAnotherIsGradedAsGiven() throws Exception {
        Path subs = dir.resolve("subs");
        writePng(subs.resolve("A2/page1.png"), page(1));
        writePng(subs.resolve("A2/old/page1.png"), page(2));
        writePng(subs.resolve("A2/drafts/page1.png"), page(2));

        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--out-dir",
                dir.resolve("out").toString());

        assertEquals(ExitCode.OK, run.exitCode(), "A2/page1.png counts and passes: " + run.out() + run.err());
        assertFalse(run.err().contains("graded as the submissions"), run.err());
        assertTrue(run.out().contains("| A2/page1.png | 1 (seed 361) |"), run.out());
    }

    /**
     * One student's folder with its pages in output/part1 and output/part2 was taken for a class unzipped into
     * output: part1 and part2 the submissions, each lacking the other's pages, exit 1, where check passed. Each
     * page is once in those folders: it is one student's, graded as given.
     */
    @Test
    void aStudentsPagesFolderedByPartAreNoClass() throws Exception {
        Path mine = dir.resolve("mine");
        writePng(mine.resolve("output/part1/page1.png"), page(1));
        writePng(mine.resolve("output/part2/page2.png"), page(2));

        CliRun run = CliRun.of("compare", "--dir", mine.toString(), "--pages", "1-2", "--out-dir",
                dir.resolve("out").toString());

        assertEquals(ExitCode.OK, run.exitCode(), run.out() + run.err());
        assertFalse(run.err().contains("graded as the submissions"), run.err());
        assertFalse(run.out().contains("MISSING"), run.out());
        assertEquals(ExitCode.OK, CliRun.of("check", mine.toString(), "--pages", "1-2").exitCode());
    }

    /**
     * One student's folder with page 1 at its top and page 2 in renders/: compare --dir took the top and renders/
     * for two submissions, each lacking the other's page, and exited 1 with JUnit failing both, where results.json
     * scored both pages and check passed. It is one submission, as results.json and check take it.
     */
    @Test
    void aStudentsPicturesAtTheTopAndInOneFolderAreOneSubmission() throws Exception {
        Path mine = dir.resolve("mine");
        writePng(mine.resolve("page1.png"), page(1));
        writePng(mine.resolve("renders/page2.png"), page(2));
        Path xml = dir.resolve("results.xml");
        Path json = dir.resolve("results.json");

        CliRun run = CliRun.of("compare", "--dir", mine.toString(), "--pages", "1-2", "--out-dir",
                dir.resolve("out").toString(), "--junit", xml.toString(), "--gradescope", json.toString());

        assertEquals(ExitCode.OK, run.exitCode(), run.out() + run.err());
        assertFalse(run.out().contains("MISSING"), run.out());
        assertTrue(run.err().contains("simpview compare: " + mine + " holds pictures at its top and in one folder, "
                + "renders: they are graded as one student's submission (were they two students', put each one's "
                + "pictures in a folder of its own)\n"), "the guess is said: " + run.err());
        assertTrue(run.err().indexOf("holds pictures at its top") < run.err().indexOf("[1/2]"),
                "before the pictures' progress, as a class's folder in a folder of its own is: " + run.err());
        String junit = Files.readString(xml);
        assertTrue(junit.contains("<testsuite name=\"submission\" id=\"0\" tests=\"2\" failures=\"0\""), junit);
        assertFalse(junit.contains("name=\"renders\""), junit);
        assertTrue(Files.readString(json).contains("\"score\": 2.0"), Files.readString(json));
        assertEquals(ExitCode.OK, CliRun.of("check", mine.toString(), "--pages", "1-2").exitCode());
    }

    /**
     * The same with renders\page2.png, as a Windows zip's folder comes out of some unzip tools: a file at the top
     * whose name the table, JUnit and the web report put in the submission renders. compare --dir took the top and
     * renders for two submissions again, each lacking the other's page, and exited 1.
     */
    @Test
    void aWindowsFolderInAFilesNameIsThatFolder() throws Exception {
        Path mine = dir.resolve("mine");
        writePng(mine.resolve("page1.png"), page(1));
        writePng(mine.resolve("renders\\page2.png"), page(2));

        CliRun run = CliRun.of("compare", "--dir", mine.toString(), "--pages", "1-2", "--out-dir",
                dir.resolve("out").toString());

        assertEquals(ExitCode.OK, run.exitCode(), run.out() + run.err());
        assertFalse(run.out().contains("MISSING"), run.out());
        assertTrue(run.err().contains("at its top and in one folder, renders: "), run.err());
    }

    /** With one scene for every picture, each picture is a student's, at the top of the folder or in one below. */
    @Test
    void withOneSceneEveryPictureStillCountsOnItsOwn() throws Exception {
        Path scene = dir.resolve("tri.simp");
        Files.writeString(scene, "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n");
        Path subs = dir.resolve("subs");
        Files.createDirectories(subs.resolve("late"));
        for (Path picture : new Path[] {subs.resolve("ann.png"), subs.resolve("bob.png"), subs.resolve("late/cy.png")}) {
            assertEquals(ExitCode.OK, CliRun.of("render", "--scene", scene.toString(), "--out", picture.toString())
                    .exitCode());
        }

        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--scene", scene.toString(), "--out-dir",
                dir.resolve("out").toString());

        assertEquals(ExitCode.OK, run.exitCode(), run.out() + run.err());
        assertTrue(run.out().contains("3 pictures: 3 pass, 0 fail, 0 could not be compared, 0 skipped\n"), run.out());
    }

    /**
     * A link to a picture that is not there was passed over: the student, whose folder lists page2.png, was told
     * no picture of page 2 was found. It is a row saying where the link leads.
     */
    @Test
    void aLinkToNothingIsARowSayingSo() throws Exception {
        Path mine = dir.resolve("mine");
        writePng(mine.resolve("page1.png"), page(1));
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

    /** A link that is a loop of links was "a link to page2.png, which does not exist": it is a loop, said so. */
    @Test
    void aLoopOfLinksIsARowSayingSo() throws Exception {
        Path mine = dir.resolve("mine");
        writePng(mine.resolve("page1.png"), page(1));
        Files.createSymbolicLink(mine.resolve("page2.png"), Path.of("page2.png"));

        CliRun check = CliRun.of("check", mine.toString(), "--pages", "1-2");

        assertTrue(check.out().contains("page2.png  page 2 (seed 361)  ERROR             " + mine.resolve("page2.png")
                + " is a loop of symbolic links (page2.png → page2.png): put the picture itself in its place\n"),
                check.out());
    }

    /**
     * A link to a folder of pictures in the folder (renders -> build/renders) is looked into, as a file manager shows
     * it; a link back up to a folder on the way is no endless walk.
     */
    @Test
    void aLinkedFolderIsLookedIntoAndALinkBackUpIsNoLoop() throws Exception {
        Path mine = dir.resolve("mine");
        writePng(mine.resolve("page1.png"), page(1));
        writePng(mine.resolve("build/renders/page2.png"), page(2));
        Files.createSymbolicLink(mine.resolve("renders"), Path.of("build/renders"));
        Files.createSymbolicLink(mine.resolve("renders-again"), mine);

        CliRun check = CliRun.of("check", mine.toString(), "--pages", "1-2");

        assertEquals(ExitCode.OK, check.exitCode(), check.out() + check.err());
        assertTrue(check.out().contains("renders/page2.png        page 2 (seed 361)  PASS"), check.out());
        assertTrue(check.out().endsWith("2 of 2 pictures pass; 1 picture not counted\n"), check.out());
    }

    /**
     * A link out of the folder graded was followed: bob's stuff -> /usr walked the whole tree for thousands of rows
     * (and a picture there named like a page could count for him), and his page2.png -> a teacher's text file was
     * a row quoting that file's first line. Neither is followed: the folder is said on stderr, the picture is a row
     * saying where it leads.
     */
    @Test
    void aLinkOutOfTheFolderGradedIsNotFollowed() throws Exception {
        Path subs = dir.resolve("subs");
        writePng(subs.resolve("ann/page1.png"), page(1));
        writePng(subs.resolve("bob/page1.png"), page(1));
        writePng(dir.resolve("elsewhere/page2.png"), page(2));
        Path secret = Files.writeString(dir.resolve("answers.txt"), "the teacher's answer key\n");
        Files.createSymbolicLink(subs.resolve("bob/stuff"), dir.resolve("elsewhere"));
        Files.createSymbolicLink(subs.resolve("ann/page2.png"), secret);

        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1-2", "--out-dir",
                dir.resolve("out").toString());

        assertTrue(run.err().contains("simpview compare: " + Path.of("bob", "stuff") + " is a link to "
                + dir.resolve("elsewhere") + ", a folder outside " + subs + ": it was not looked into (simpview "
                + "follows no link out of the folder it grades: put what it leads to itself in its place)\n"),
                run.err());
        assertFalse(run.out().contains("stuff/"), run.out());
        assertTrue(run.out().contains("| ann/page2.png | 2 (seed 361) |  |  |  |  |  |  |  | ERROR |  |  | "
                + subs.resolve("ann/page2.png") + " is a link to " + secret + ", which is outside " + subs
                + ": simpview follows no link out of the folder it grades; put the picture itself in its place |"),
                run.out());
        assertFalse(run.out().contains("answer key"), run.out());
        assertTrue(run.out().contains("| bob/ | 2 (seed 361) |"), "bob lacks page 2: " + run.out());
        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out() + run.err());
    }

    /**
     * The reports written into the class's folder, into one student's folder, or into the class's folder unzipped
     * into a folder of its own: that folder was left out of the pictures whole, and the student (or the whole class,
     * 0 pictures) silently dropped. Only what simpview writes there is left out, so a second run grades as the first.
     */
    @Test
    void reportsWrittenIntoTheClassOrAStudentsFolderLeaveEveryStudentGraded() throws Exception {
        Path subs = dir.resolve("subs");
        Path class_ = subs.resolve("class");
        writePng(class_.resolve("ann/page1.png"), page(1));
        writePng(class_.resolve("ann/renders/page2.png"), page(2));
        writePng(class_.resolve("bob/page1.png"), page(1));
        writePng(class_.resolve("bob/page2.png"), page(1)); // wrong: a diff image for it in every run
        Path[] outDirs = {class_, class_.resolve("ann"), class_.resolve("ann/renders"), class_.resolve("reports")};
        for (Path out : outDirs) {
            for (int pass = 1; pass <= 2; pass++) {
                CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1-2", "--out-dir",
                        out.toString(), "--html", out.toString(), "--junit", out.resolve("results.xml").toString());
                String said = "--out-dir " + out + ", run " + pass + ": " + run.out() + run.err();
                assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), "bob's page 2 fails: " + said);
                assertTrue(run.out().contains("4 pictures: 3 pass, 1 fail, 0 could not be compared, 0 skipped\n"),
                        said);
                assertTrue(run.out().contains("| ann/renders/page2.png | 2 (seed 361) |"), said);
                assertFalse(run.out().contains("MISSING") || run.out().contains("diff.png |"), said);
                assertTrue(run.err().contains("its folders (ann, bob) are graded"), said);
                assertTrue(Files.isRegularFile(out.resolve("diffs/bob_page2-diff.png")), said);
            }
        }
    }

    /**
     * A class's folder of which one student's folder holds pictures, the others a zip or a .webp: those students were
     * left out of the results (only ann's suite), and the run passed. Each is a student lacking every page, said.
     */
    @Test
    void aClassOfWhichOneStudentHandedInPicturesStillAsksTheOthers() throws Exception {
        Path subs = dir.resolve("subs");
        writePng(subs.resolve("ann/page1.png"), page(1));
        Files.createDirectories(subs.resolve("bob"));
        Files.writeString(subs.resolve("bob/bob.zip"), "PK");
        Files.createDirectories(subs.resolve("build")); // empty: no student, with one folder of pictures

        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--out-dir",
                dir.resolve("out").toString());

        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), run.out() + run.err());
        assertTrue(run.out().contains("| bob/ | 1 (seed 361) |"), run.out());
        assertFalse(run.out().contains("| build/"), run.out());
        assertTrue(run.err().contains("only ann in " + subs + " holds pictures; bob, which holds only what a class's "
                + "pictures may be handed in as"), run.err());
    }

    /**
     * One student's upload (a Gradescope submission): output/ with the pictures beside report/writeup.pdf and
     * assets/sky.hdr. Taken for a class of which only output handed in pictures, report and assets were two more
     * students lacking every page, and the run failed. Only a folder of archives beside the pictures is a student.
     */
    @Test
    void oneStudentsUploadWithAWriteUpBesideItsPicturesIsOneSubmission() throws Exception {
        Path subs = dir.resolve("submission");
        writePng(subs.resolve("output/page1.png"), page(1));
        Files.createDirectories(subs.resolve("report"));
        Files.writeString(subs.resolve("report/writeup.pdf"), "%PDF-1.4");
        Files.createDirectories(subs.resolve("assets"));
        Files.writeString(subs.resolve("assets/sky.hdr"), "#?RADIANCE");

        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--out-dir",
                dir.resolve("out").toString());

        assertEquals(ExitCode.OK, run.exitCode(), run.out() + run.err());
        assertTrue(run.out().contains("1 picture: 1 pass, 0 fail, 0 could not be compared, 0 skipped\n"), run.out());
        assertFalse(run.out().contains("MISSING"), run.out());
        assertFalse(run.err().contains("only output in"), run.err());
    }

    /**
     * The teacher's reference pictures in subs/reference beside the class in subs/class: graded as subs, the whole
     * class was one submission (each page counted once) and reference another. The class is graded student by
     * student and the reference pictures are said to be left out; so are the rubric's alternates, said as such.
     */
    @Test
    void referencePicturesBesideTheClassAreNoStudents() throws Exception {
        Path subs = dir.resolve("subs");
        writePng(subs.resolve("class/ann/page1.png"), page(1));
        writePng(subs.resolve("class/bob/page1.png"), page(2)); // wrong
        writePng(subs.resolve("reference/page1.png"), page(1));

        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--out-dir",
                dir.resolve("out").toString());

        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), "bob fails: " + run.out() + run.err());
        assertTrue(run.out().contains("2 pictures: 1 pass, 1 fail, 0 could not be compared, 0 skipped\n"), run.out());
        assertTrue(run.err().contains("its folders (ann, bob) are graded as the submissions, as --dir "
                + subs.resolve("class") + " grades them; 1 picture beside it, in " + subs.resolve("reference")
                + ", is taken for the teacher's"), run.err());

        Path rubric = Files.writeString(dir.resolve("compare.json"), "{ \"defaults\": { \"alternates\": \""
                + subs.resolve("reference") + "\" } }\n");
        CliRun alternates = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--rubric",
                rubric.toString(), "--out-dir", dir.resolve("out").toString());
        assertTrue(alternates.out().contains("2 pictures: 1 pass, 1 fail"), alternates.out());
        assertTrue(alternates.err().contains("(the rubric's accepted alternates, in reference, are the teacher's) is in "
                + subs.resolve("class")), alternates.err());
    }

    /**
     * A Windows zip unzipped flat: ann\page1.png, bob\page1.png, cy\cy.zip in one folder. cy was left out, and of
     * ann\page1.png and ann\old\page1.png neither was taken for named the page alone.
     */
    @Test
    void aWindowsZipUnzippedFlatIsGradedStudentByStudent() throws Exception {
        Path subs = dir.resolve("subs");
        writePng(subs.resolve("ann\\old\\page1.png"), page(2));
        writePng(subs.resolve("ann\\page1 v2.png"), page(2));
        writePng(subs.resolve("ann\\page1.png"), page(1));
        writePng(subs.resolve("bob\\page1.png"), page(1));
        Files.writeString(subs.resolve("cy\\cy.zip"), "PK");

        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--out-dir",
                dir.resolve("out").toString());

        assertTrue(run.out().contains("not counted: ann\\page1.png counts for page 1 (seed 361) instead: its name is "
                + "the page's name and nothing else"), run.out());
        assertTrue(run.out().contains("| cy/ | 1 (seed 361) |"), run.out());
        assertTrue(run.out().contains("4 pictures: 2 pass, 0 fail, 0 could not be compared, 0 skipped, 2 not counted"),
                run.out());
    }
}

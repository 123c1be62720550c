package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static simpview.testing.Images.page;
import static simpview.testing.Images.writePng;

import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * What a teacher keeps beside a class's folders (a backup zip of the class, the reports' folder), a class of two
 * students, and a picture named for a page there is not: each graded as the teacher expects, and said once.
 */
class TeacherFolderTest {

    @TempDir
    Path dir;

    /** Writes a zip holding page 1 of each student, named as Windows names them (class\ann\page1.png). */
    private static void backupZip(Path zip, String... students) throws Exception {
        Files.createDirectories(zip.getParent());
        try (OutputStream out = Files.newOutputStream(zip); ZipOutputStream entries = new ZipOutputStream(out)) {
            for (String student : students) {
                entries.putNextEntry(new ZipEntry("class\\" + student + "\\page1.png"));
                entries.write(new byte[] {1, 2, 3});
                entries.closeEntry();
            }
        }
    }

    /**
     * The teacher's class-backup.zip kept in the reports' folder (--out-dir class/output) made that folder a student
     * who handed in a zip: a MISSING row of each page, exit 1, though every student passed.
     */
    @Test
    void aBackupZipInTheReportsFolderIsTheTeachers() throws Exception {
        Path subs = dir.resolve("class");
        writePng(subs.resolve("ann/page1.png"), page(1));
        writePng(subs.resolve("bob/page1.png"), page(1));
        backupZip(subs.resolve("output/class-backup.zip"), "ann", "bob", "cy");

        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--out-dir",
                subs.resolve("output").toString());

        assertEquals(ExitCode.OK, run.exitCode(), run.out() + run.err());
        assertFalse(run.out().contains("MISSING"), run.out());
        assertTrue(run.err().contains("simpview compare: taken for the teacher's, not a student's, and not graded: "
                + subs.resolve("output/class-backup.zip") + " (in a folder of reports); a student who hands in a zip "
                + "has it in a folder of their own\n"), run.err());
    }

    /**
     * A folder beside the students' holding only a zip of the class's own folders (backup/class-backup.zip) is the
     * teacher's copy of the class, not a student who handed in a zip; a student's own zip still is one.
     */
    @Test
    void aZipOfTheClassesOwnFoldersIsNoStudent() throws Exception {
        Path subs = dir.resolve("class");
        writePng(subs.resolve("ann/page1.png"), page(1));
        writePng(subs.resolve("bob/page1.png"), page(1));
        backupZip(subs.resolve("backup/class-backup.zip"), "ann", "bob");
        backupZip(subs.resolve("dee/dee.zip"), "dee");

        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1", "--out-dir",
                dir.resolve("out").toString());

        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), "dee lacks page 1: " + run.out() + run.err());
        assertFalse(run.out().contains("| backup/ |"), run.out());
        assertTrue(run.out().contains("| dee/ | 1 (seed 361) |"), run.out());
        assertTrue(run.err().contains(subs.resolve("backup/class-backup.zip") + " (a zip of the class's own folders "
                + "ann, bob: a copy of the class)"), run.err());
    }

    /**
     * A class of two in a folder of its own, one of whom named every page like no page (p1.png): the two folders
     * had no page name in common and were taken for one student's parts, and bob's eight pages were never asked
     * for (exit 0). They are two students; one student's parts (each page once, each named) stay one submission,
     * as does one student's folder of pages at its top.
     */
    @Test
    void twoStudentsOneOfThemMisnamingEveryPageAreAClass() throws Exception {
        Path subs = dir.resolve("subs");
        writePng(subs.resolve("class/ann/page1.png"), page(1));
        writePng(subs.resolve("class/ann/page2.png"), page(2));
        writePng(subs.resolve("class/bob/p1.png"), page(1));
        writePng(subs.resolve("class/bob/p2.png"), page(2));

        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1-2", "--out-dir",
                dir.resolve("out").toString());

        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), "bob lacks both pages: " + run.out() + run.err());
        assertTrue(run.err().contains("its folders (ann, bob) are graded as the submissions"), run.err());
        assertTrue(run.out().contains("| bob/ | 1 (seed 361) |"), run.out());
        assertTrue(run.out().contains("bob/p1.png is named like no page (its number, 1, is not after the word "
                + "\"page\"): did you mean page1.png?"), run.out());

        Path parts = dir.resolve("mine");
        writePng(parts.resolve("output/part1/page1.png"), page(1));
        writePng(parts.resolve("output/part2/page2.png"), page(2));
        CliRun one = CliRun.of("compare", "--dir", parts.toString(), "--pages", "1-2", "--out-dir",
                dir.resolve("out2").toString());
        assertEquals(ExitCode.OK, one.exitCode(), one.out() + one.err());

        Path direct = dir.resolve("direct");
        writePng(direct.resolve("page1.png"), page(1));
        writePng(direct.resolve("page2.png"), page(2));
        CliRun alone = CliRun.of("compare", "--dir", direct.toString(), "--pages", "1-2", "--out-dir",
                dir.resolve("out3").toString());
        assertEquals(ExitCode.OK, alone.exitCode(), alone.out() + alone.err());
        assertFalse(alone.err().contains("graded as the submissions"), alone.err());
    }

    /**
     * One student's parts stay one submission with a draft named like no page beside a named page (part2/p1.png
     * beside part2/page2.png): only a folder whose pictures all name no page has its numbers taken for pages, as
     * bob's above; a part that names its page is one student's part, its p1.png a draft of page 1, not a second
     * student who lacks page 1.
     */
    @Test
    void oneStudentsPartsWithADraftNamedLikeNoPageStayOneSubmission() throws Exception {
        Path parts = dir.resolve("mine");
        writePng(parts.resolve("output/part1/page1.png"), page(1));
        writePng(parts.resolve("output/part2/page2.png"), page(2));
        writePng(parts.resolve("output/part2/p1.png"), page(1));
        CliRun one = CliRun.of("compare", "--dir", parts.toString(), "--pages", "1-2", "--out-dir",
                dir.resolve("out").toString());
        assertEquals(ExitCode.OK, one.exitCode(), one.out() + one.err());
        assertFalse(one.err().contains("graded as the submissions"), one.err());
        assertFalse(one.out().contains("MISSING"), one.out());
    }

    /**
     * bob/page9.png, named for a page there is not, was told on each of bob's MISSING rows. It is told once, on the
     * first page bob lacks, naming every page it may have been meant as.
     */
    @Test
    void aPictureNamedForNoPageIsToldOnce() throws Exception {
        Path subs = dir.resolve("class");
        for (int p = 1; p <= 4; p++) {
            writePng(subs.resolve("ann/page" + p + ".png"), page(p));
        }
        writePng(subs.resolve("bob/page1.png"), page(1));
        writePng(subs.resolve("bob/page3.png"), page(3));
        writePng(subs.resolve("bob/page9.png"), page(2));
        Path xml = dir.resolve("results.xml");

        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1-4", "--out-dir",
                dir.resolve("out").toString(), "--junit", xml.toString());

        String note = "bob/page9.png is named for page 9, and there is no page 9 (the pages are 1 to 8): was it meant "
                + "as page 2 or page 4, which bob lacks?";
        assertTrue(run.out().contains("| bob/ | 2 (seed 361) |  |  |  |  |  |  |  | MISSING |  |  | no picture of page 2 "
                + "(seed 361) in bob was found; " + note + " |"), run.out());
        assertTrue(run.out().contains("| bob/ | 4 |  |  |  |  |  |  |  | MISSING |  |  | no picture of page 4 in bob was "
                + "found |"), run.out());
        String junit = Files.readString(xml);
        assertTrue(junit.contains("<failure message=\"no picture of page 4 found\" type=\"missing\">No picture's name "
                + "names page 4.</failure>"), "told on page 2's test only: " + junit);
    }

    /**
     * A class's lit scenes, lettered: bob's page_C.png was offered on each of his MISSING rows as every scene he
     * lacked (did you mean pageB.png? on pageB's), each two letters from it; his page1.png, meant as pageA, was
     * offered as none. Each is offered as the one scene it names.
     */
    @Test
    void aLetteredScenesSlipIsOfferedAsThatSceneOnly() throws Exception {
        Path scenes = dir.resolve("scenes");
        Files.createDirectories(scenes);
        for (String scene : new String[] {"pageA", "pageB", "pageC"}) {
            Files.writeString(scenes.resolve(scene + ".simp"), "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n");
        }
        Path subs = dir.resolve("class");
        for (String picture : new String[] {"ann/pageA.png", "ann/pageB.png", "ann/pageC.png", "bob/page1.png",
                "bob/page_C.png"}) {
            Files.createDirectories(subs.resolve(picture).getParent());
            assertEquals(ExitCode.OK, CliRun.of("render", "--scene", scenes.resolve("pageA.simp").toString(), "--out",
                    subs.resolve(picture).toString()).exitCode());
        }

        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--scene", scenes.toString(), "--out-dir",
                dir.resolve("out").toString());

        String table = run.out();
        assertTrue(table.contains("| bob/ | pageB.simp |  |  |  |  |  |  |  | MISSING |  |  | no picture of pageB.simp in "
                + "bob was found |"), table);
        assertTrue(table.contains("no picture of pageC.simp in bob was found; bob/page_C.png is named like no scene: "
                + "did you mean pageC.png? |"), table);
        assertTrue(table.contains("no picture of pageA.simp in bob was found; bob/page1.png is named for page 1, and "
                + "the scenes here are lettered: did you mean pageA.png (page A)? |"), table);
    }

    /**
     * A class zipped on Windows in a folder of its own and unzipped flat (files named class\\ann\\page1.png, as
     * Python's zipfile or 7-Zip unzips it on Linux): the whole class was one submission, ann's pages counted, the
     * others' "not counted", and a page bob lacked was no MISSING row. Its students are graded as those of a class
     * unzipped into folders; a name leading out of the folder (C:\\page1.png) is read as no folder.
     */
    @Test
    void aClassZippedOnWindowsAndUnzippedFlatIsGradedStudentByStudent() throws Exception {
        Path subs = dir.resolve("subs");
        writePng(subs.resolve("class\\ann\\page1.png"), page(1));
        writePng(subs.resolve("class\\ann\\page2.png"), page(2));
        writePng(subs.resolve("class\\bob\\page1.png"), page(1));
        writePng(subs.resolve("C:\\page2.png"), page(2));
        Path xml = dir.resolve("results.xml");

        CliRun run = CliRun.of("compare", "--dir", subs.toString(), "--pages", "1-2", "--out-dir",
                dir.resolve("out").toString(), "--junit", xml.toString());

        assertEquals(ExitCode.SCENE_ERROR, run.exitCode(), "bob lacks page 2: " + run.out() + run.err());
        assertTrue(run.err().contains("every picture in " + subs + " is in " + subs.resolve("class\\") + " (folders in "
                + "its files' names, as a Windows zip writes them, unzipped flat): its folders (ann, bob) are graded as "
                + "the submissions\n"), run.err());
        assertTrue(run.err().contains(subs.resolve("C:\\page2.png") + ": its name leads out of " + subs), run.err());
        assertTrue(run.out().contains("| bob\\page1.png | 1 (seed 361) |"), run.out());
        assertTrue(run.out().contains("| bob/ | 2 (seed 361) |  |  |  |  |  |  |  | MISSING |"), run.out());
        assertFalse(run.out().contains("not counted"), run.out());
        assertTrue(Files.readString(xml).contains("<testsuite name=\"bob\""), Files.readString(xml));
    }
}

package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Optional;
import java.util.OptionalInt;
import org.junit.jupiter.api.Test;

/** Which page or scene a submitted picture's name names. */
class SubmissionNamesTest {

    @Test
    void pageNumbersInNames() {
        assertEquals(OptionalInt.of(3), SubmissionNames.pageNumber("page3.png"));
        assertEquals(OptionalInt.of(3), SubmissionNames.pageNumber("Page_3.PNG"));
        assertEquals(OptionalInt.of(3), SubmissionNames.pageNumber("alice-page03.png"));
        assertEquals(OptionalInt.of(1), SubmissionNames.pageNumber("page1_mesh_wire.png"));
        assertEquals(OptionalInt.of(12), SubmissionNames.pageNumber("page 12.jpg"));
        assertEquals(OptionalInt.empty(), SubmissionNames.pageNumber("pageC.png"));
        assertEquals(OptionalInt.empty(), SubmissionNames.pageNumber("homepage3.png"), "not inside a word");
        assertEquals(OptionalInt.empty(), SubmissionNames.pageNumber("notes.png"));
        assertEquals(OptionalInt.empty(), SubmissionNames.pageNumber("page99999999999.png"));
    }

    @Test
    void paginaIsPageButANumberAfterAnotherWordIsNone() {
        assertEquals(OptionalInt.of(1), SubmissionNames.pageNumber("página1.png"));
        assertEquals(OptionalInt.of(1), SubmissionNames.pageNumber("pa\u0301gina1.png"), "as a Mac spells it (NFD)");
        assertEquals(OptionalInt.of(2), SubmissionNames.pageNumber("Pagina_2.PNG"));
        // full-width, as a Japanese or Chinese keyboard types them: page８.png was skipped, "no page number"
        assertEquals(OptionalInt.of(8), SubmissionNames.pageNumber("page\uff18.png"));
        // and nothing else folded: NFKD made a superscript or a fraction after the number more of its digits
        assertEquals(OptionalInt.of(3), SubmissionNames.pageNumber("page3\u00b2.png"), "page3².png");
        assertEquals(OptionalInt.of(1), SubmissionNames.pageNumber("page1\u00bd.png"), "page1½.png");
        org.junit.jupiter.api.Assertions.assertTrue(SubmissionNames.isPageName("\uff30\uff41\uff47\uff45\u3000\uff13.png", 3),
                "Ｐａｇｅ　３.png");
        org.junit.jupiter.api.Assertions.assertTrue(SubmissionNames.isPageName("página3.png", 3));
        assertEquals(OptionalInt.empty(), SubmissionNames.pageNumber("p1.png"), "p may be a part, a problem or a panel");
        assertEquals(OptionalInt.empty(), SubmissionNames.pageNumber("paginas1.png"));

        assertEquals("no page number in the name: its number, 1, is not after the word \"page\" (expected a name like "
                + "page1.png)", SubmissionNames.noPageNumber("p1.png", "page", 8));
        assertEquals("no page number in the name: its number, 7, is not after the word \"page\" (expected a name like "
                + "page7.jpg)", SubmissionNames.noPageNumber("scan_07.JPG", "page", 8));
        assertEquals("no page number in the name: its number, 2024, is not after the word \"page\" (expected a name "
                + "like page3.png)", SubmissionNames.noPageNumber("IMG 2024.png", "page", 8));
        assertEquals("no page number in the name (expected a name like page3.png)",
                SubmissionNames.noPageNumber("notes.png", "page", 8));
        // a screenshot's, a camera's or a copy's number is no page's: not offered as one, as in a MISSING row's guess
        assertEquals("no page number in the name: it is named as a screenshot tool or a camera names its pictures, "
                + "by a date, a time or a counter (expected a name like page3.png)",
                SubmissionNames.noPageNumber("Screenshot (5).png", "page", 8));
        assertEquals("no page number in the name: it is named as a screenshot tool or a camera names its pictures, "
                + "by a date, a time or a counter (expected a name like page3.jpg)",
                SubmissionNames.noPageNumber("IMG_0005.JPG", "page", 8));
        assertEquals("no page number in the name: (2) is a copy's counter (expected a name like page3.png)",
                SubmissionNames.noPageNumber("image ( 2 ).png", "page", 8));
        assertEquals("no page number in the name: its number, 4, is not after the word \"page\" (expected a name like "
                + "page4.png)", SubmissionNames.noPageNumber("p4 (1).png", "page", 8));
        assertEquals("no page number in the name: its number, 3, is not after the word \"page\" (expected a name like "
                + "a1-page3.png)", SubmissionNames.noPageNumber("a1-p3.png", "a1-page", 5));
        assertEquals("no page number in the name: 99999999999 is no page's number (expected a name like page3.png)",
                SubmissionNames.noPageNumber("page99999999999.png", "page", 8));
        assertEquals("no page number in the name: 0 is no page's number, pages count from 1 (expected a name like "
                + "page1.png)", SubmissionNames.noPageNumber("page0.png", "page", 8));
        assertEquals("no page number in the name: 0 is no page's number, pages count from 1 (expected a name like "
                + "a1-page1.png)", SubmissionNames.noPageNumber("a1-page_00.png", "a1-page", 5));
    }

    @Test
    void namesThatAreAPagesNameAndNothingElse() {
        for (String name : new String[] {"page3.png", "Page_3.PNG", "page 03.jpg", "PAGE-3.png", "page3 .png"}) {
            org.junit.jupiter.api.Assertions.assertTrue(SubmissionNames.isPageName(name, 3), name);
        }
        for (String name : new String[] {"page3 copy.png", "page3_v2.png", "old_page3.png", "page33.png", "page3"}) {
            org.junit.jupiter.api.Assertions.assertEquals(name.equals("page3"), SubmissionNames.isPageName(name, 3), name);
        }
        org.junit.jupiter.api.Assertions.assertTrue(SubmissionNames.isFirstAssignmentPageName("A1_Page_2.png", 2));
        org.junit.jupiter.api.Assertions.assertTrue(SubmissionNames.isFirstAssignmentPageName("assignment1-page2.png", 2));
        org.junit.jupiter.api.Assertions.assertFalse(SubmissionNames.isFirstAssignmentPageName("a1-page2 (1).png", 2));
        org.junit.jupiter.api.Assertions.assertTrue(SubmissionNames.isSceneName("pagec.png", "pageC"));
        org.junit.jupiter.api.Assertions.assertFalse(SubmissionNames.isSceneName("pageJ_tomsPageJ.png", "tomsPageJ"));
    }

    @Test
    void sceneNamesInNames() {
        List<String> a3 = List.of("cube", "pageA", "pageC", "pageJ", "tomsPageJ", "page-a2", "page-a");
        assertEquals(Optional.of("pageC"), SubmissionNames.sceneName("pageC.png", a3));
        assertEquals(Optional.of("pageC"), SubmissionNames.sceneName("pagec_v2.png", a3));
        assertEquals(Optional.of("tomsPageJ"), SubmissionNames.sceneName("pageJ_tomsPageJ.png", a3), "the longest");
        assertEquals(Optional.of("page-a2"), SubmissionNames.sceneName("page-a2.png", a3));
        assertEquals(Optional.of("page-a"), SubmissionNames.sceneName("bob-page-a.png", a3));
        assertEquals(Optional.empty(), SubmissionNames.sceneName("pageAB.png", a3), "pageA inside a longer word");
        assertEquals(Optional.empty(), SubmissionNames.sceneName("cubes.png", a3));
    }

    @Test
    void namesOfTheFirstAssignmentsPages() {
        org.junit.jupiter.api.Assertions.assertTrue(SubmissionNames.namesFirstAssignment("a1-page2.png"));
        org.junit.jupiter.api.Assertions.assertTrue(SubmissionNames.namesFirstAssignment("bob_A1_page5.PNG"));
        org.junit.jupiter.api.Assertions.assertTrue(SubmissionNames.namesFirstAssignment("assignment1-page3.png"));
        org.junit.jupiter.api.Assertions.assertFalse(SubmissionNames.namesFirstAssignment("page2.png"));
        org.junit.jupiter.api.Assertions.assertFalse(SubmissionNames.namesFirstAssignment("a12-page2.png"));
        org.junit.jupiter.api.Assertions.assertFalse(SubmissionNames.namesFirstAssignment("data1-page2.png"));
        assertEquals(OptionalInt.of(2), SubmissionNames.pageNumber("a1-page2.png"));
    }

    /**
     * Full-width letters and digits (as a Japanese or Chinese keyboard types them) were folded for the eight pages'
     * numbers only: pageＣ.png named no scene, ａ１-page2.png no first-assignment page, p３.png no number.
     */
    @Test
    void fullWidthFormsFoldForScenesAndTheFirstAssignmentToo() {
        assertEquals(Optional.of("pageC"), SubmissionNames.sceneName("page\uff23.png", List.of("pageC", "pageB")));
        assertEquals(Optional.of("pageC"), SubmissionNames.sceneName("\uff50\uff41\uff47\uff45\uff23_v2.png",
                List.of("pageC")));
        org.junit.jupiter.api.Assertions.assertTrue(SubmissionNames.isSceneName("page\uff23.png", "pageC"));
        org.junit.jupiter.api.Assertions.assertTrue(SubmissionNames.namesFirstAssignment("\uff41\uff11-page2.png"));
        org.junit.jupiter.api.Assertions.assertTrue(SubmissionNames.namesFirstAssignment("A\uff11_Page_2.png"));
        org.junit.jupiter.api.Assertions.assertTrue(SubmissionNames.isFirstAssignmentPageName("a\uff11-page\uff12.png",
                2));
        assertEquals("no page number in the name: its number, 3, is not after the word \"page\" (expected a name like "
                + "page3.png)", SubmissionNames.noPageNumber("p\uff13.png", "page", 8));
    }

    /**
     * The names students give their pages, and what each is taken for: a page (counted as named), or, named like
     * none, the one page or scene it was likely meant for, or no guess where a guess would as likely be wrong.
     * Before, a lit scene's slip (page_C.png, pageJ.png) was offered as every lettered scene a student lacked, each
     * two letters from it, and a screenshot's counter (Screenshot (3).png) as page 3.
     */
    @Test
    void realisticMisnamingsAreGuessedRightOrNotAtAll() {
        List<String> scenes = List.of("pageA", "pageB", "pageC", "pageD", "pageE", "pageF", "pageG", "pageH", "pageI",
                "tomsPageJ");
        // named as a page: no guess needed
        for (String name : List.of("page01.png", "Page 1.PNG", "page_1.png", "page-1.png", "page1 (1).png")) {
            assertEquals(OptionalInt.of(1), SubmissionNames.pageNumber(name), name);
        }
        // named like no page: its number, not a copy's counter or a screenshot's date, time or counter
        String[][] pages = {
            {"p1.png", "1"}, {"pg1.png", "1"}, {"p.1.png", "1"}, {"image (2).png", ""}, {"Screenshot (3).png", ""},
            {"Screenshot 2024-03-05 at 10.15.32.png", ""}, {"Screen Shot 2024-03-05 at 1.02.03 PM.png", ""},
            {"Capture d’écran (2).png", ""}, {"p3 (1).png", "3"}, {"IMG_0003.png", ""}, {"DSC_0002.JPG", ""}, {"img3.png", "3"},
        };
        for (String[] c : pages) {
            assertEquals(c[1].isEmpty() ? OptionalInt.empty() : OptionalInt.of(Integer.parseInt(c[1])),
                    SubmissionNames.numberIn(c[0]), c[0]);
        }
        // a lit scene's slips: the one scene meant, or none
        String[][] slips = {
            {"page_C.png", "pageC"}, {"page-c.png", "pageC"}, {"pagC.png", "pageC"}, {"pageCC.png", "pageC"},
            {"pageC2.png", "pageC"}, {"pageJ.png", "tomsPageJ"}, {"tomPageJ.png", "tomsPageJ"}, {"pageK.png", ""},
            {"pages.png", ""}, {"notes.png", ""},
        };
        for (String[] c : slips) {
            assertEquals(c[1].isEmpty() ? Optional.empty() : Optional.of(c[1]),
                    SubmissionNames.nearestScene(c[0], scenes), c[0]);
        }
        // an A3 page's letter as a number, and the other way round
        assertEquals(Optional.of("pageA"), SubmissionNames.sceneOfLetter('A', scenes));
        assertEquals(Optional.of("tomsPageJ"), SubmissionNames.sceneOfLetter('j', scenes));
        assertEquals(Optional.empty(), SubmissionNames.sceneOfLetter('K', scenes));
        assertEquals(Optional.of('B'), SubmissionNames.pageLetter("pageb.png"));
        assertEquals(Optional.empty(), SubmissionNames.pageLetter("page2.png"));
    }
}

package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/** What a MISSING row says of the archives its submission holds beside its pictures. */
class WantedArchiveNoteTest {

    private static Wanted page2(List<String> archives) {
        return new Wanted("2 (seed 361)", null, List.of(), "page2.png", List.of(), List.of(), archives);
    }

    /** Three archives or more are listed as a list is said, the last after "and", the others after commas. */
    @Test
    void threeArchivesAreListedWithCommas() {
        assertEquals("bob/a.zip, bob/b.zip and bob/c.7z are in the folder too, not opened (simpview does not look "
                + "inside an archive): the page may be in them; unpack them",
                page2(List.of("bob/a.zip", "bob/b.zip", "bob/c.7z")).archiveNote("bob"));
        assertEquals("bob/a.zip and bob/b.ZIP are in the folder too, not opened (simpview does not look inside a "
                + "zip): the page may be in them; unzip them",
                page2(List.of("bob/a.zip", "bob/b.ZIP")).archiveNote("bob"));
        assertEquals("bob/pages.tar.gz is in the folder too, not opened (simpview does not look inside an archive): "
                + "the page may be in it; unpack it", page2(List.of("bob/pages.tar.gz", "ann/x.rar")).archiveNote("bob"));
    }
}

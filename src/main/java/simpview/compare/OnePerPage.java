package simpview.compare;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.function.Predicate;

/**
 * Each page counts once per submission. Every picture is compared and listed, but of the pictures of one
 * page (or scene, or first-assignment panel) in one submission only one is scored: the one whose name is
 * the page's name and nothing else (page3.png, Page_3.png; not page3 copy.png, page3_v2.png or
 * old_page3.png); of those named equally well, the one in the fewest folders (page3.png over old/page3.png, a
 * draft kept in a folder that comes first by the alphabet); then the one in the truest format
 * ({@link PictureFormat}: PNG, BMP, GIF, JPEG), so a right page3.png is not failed for the page3.jpg beside it;
 * and of those, the first in the table's order (natural order of their paths). The others are marked {@link BatchRow#notCounted}: they score
 * nothing and are worth nothing, so a submission's total is never more than the pages asked for are worth.
 * The rule goes by file names alone, never by results, so handing in more pictures of a page never raises its
 * score. The format too is the name's, not the one the bytes were decoded as (which the rows' notes go by): a
 * picture that cannot be read has no decoded format but is a candidate all the same, and by names alone a
 * student can tell which picture counts before any is read; a JPEG renamed x.png is told what it holds
 * ({@link PictureFormat#failingAdvice(String, PictureFormat, boolean)}).
 */
public final class OnePerPage {

    private OnePerPage() {
    }

    /**
     * For a class's folder: each first-level folder is a submission (as {@link JUnitResults#submission} says),
     * but a picture that {@code alone} picks is one of its own (one scene for every picture: a picture a student).
     */
    public static List<BatchRow> bySubmission(List<BatchRow> rows, Predicate<String> plainlyNamed,
            Predicate<String> alone) {
        return counted(rows, file -> alone.test(file) ? file : JUnitResults.submission(file), plainlyNamed);
    }

    /** For one submission's folder (check's, or a Gradescope results.json's): all its pictures are one submission. */
    public static List<BatchRow> asOne(List<BatchRow> rows, Predicate<String> plainlyNamed) {
        return counted(rows, file -> "", plainlyNamed);
    }

    /**
     * The rows, in their order, those that do not count marked so.
     *
     * @param submission the submission of a row's file
     * @param plainlyNamed whether a row's file (its path in the folder) is named its page's name and nothing else
     */
    static List<BatchRow> counted(List<BatchRow> rows, Function<String, String> submission,
            Predicate<String> plainlyNamed) {
        Map<List<String>, String> counting = new LinkedHashMap<>();
        for (BatchRow row : rows) {
            if (!row.target().isEmpty()) {
                List<String> page = List.of(submission.apply(row.file()), row.page());
                String first = counting.get(page);
                if (first == null || before(row.file(), first, plainlyNamed)) {
                    counting.put(page, row.file());
                }
            }
        }
        List<BatchRow> marked = new ArrayList<>();
        for (BatchRow row : rows) {
            String counts = row.target().isEmpty() ? row.file()
                    : counting.get(List.of(submission.apply(row.file()), row.page()));
            marked.add(counts.equals(row.file())
                    ? row : row.notCounted(why(counts, row.file(), row.page(), plainlyNamed)));
        }
        return marked;
    }

    /** Whether {@code file} counts over {@code first}, a picture of the same page before it by name. */
    private static boolean before(String file, String first, Predicate<String> plainlyNamed) {
        if (plainlyNamed.test(file) != plainlyNamed.test(first)) {
            return plainlyNamed.test(file);
        }
        if (depth(file) != depth(first)) {
            return depth(file) < depth(first);
        }
        return PictureFormat.of(file).truerThan(PictureFormat.of(first));
    }

    /**
     * How many folders a picture (its path in the folder graded) is in: of one submission's pictures, the one nearer
     * its top is what was handed in (page1.png), one further down a draft or a copy (old/page1.png), whatever their
     * folders' names are by the alphabet.
     */
    private static int depth(String file) {
        return (int) file.chars().filter(c -> c == '/' || c == '\\').count();
    }

    /**
     * Why {@code counts} is the picture of {@code target} that counts, and not {@code file}: "page3.png counts for
     * page 3 instead: ...", giving the reason that decided between the two.
     */
    private static String why(String counts, String file, String target, Predicate<String> plainlyNamed) {
        String page = GradescopeResults.name(target);
        boolean plain = plainlyNamed.test(counts);
        String reason;
        if (plain && !plainlyNamed.test(file)) {
            reason = "its name is the page's name and nothing else";
        } else {
            PictureFormat format = PictureFormat.of(counts);
            PictureFormat other = PictureFormat.of(file);
            String named = plain ? "both are named the page's name and nothing else"
                    : "no picture's name is the page's name alone";
            reason = depth(counts) < depth(file) ? named + ", and it is nearer the top of the submission's folder"
                    : format.truerThan(other) ? named + ", and " + format.whyOver(other)
                    : named + ", and it is the first by name";
        }
        return counts + " counts for " + page + " instead: " + reason;
    }
}

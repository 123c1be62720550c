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
 * and of those, the first in the table's order (natural order of their paths), except that of two whose names differ
 * only in case (page3.png and page3.PNG), which no rule by name tells apart, the one that could be compared counts
 * over one that could not, then the one whose bytes are of the truer format. The others are marked
 * {@link BatchRow#notCounted}: they score
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
        Map<List<String>, BatchRow> counting = new LinkedHashMap<>();
        for (BatchRow row : rows) {
            if (!row.target().isEmpty()) {
                List<String> page = List.of(submission.apply(row.file()), row.page());
                BatchRow first = counting.get(page);
                if (first == null || before(row, first, plainlyNamed)) {
                    counting.put(page, row);
                }
            }
        }
        List<BatchRow> marked = new ArrayList<>();
        for (BatchRow row : rows) {
            BatchRow counts = row.target().isEmpty() ? row
                    : counting.get(List.of(submission.apply(row.file()), row.page()));
            marked.add(counts.file().equals(row.file())
                    ? row : row.notCounted(why(counts, row, plainlyNamed)));
        }
        return marked;
    }

    /**
     * Whether {@code row}'s picture counts over {@code first}'s, a picture of the same page before it by name; for
     * two whose names differ only in case, {@link #overTwin}.
     */
    private static boolean before(BatchRow row, BatchRow first, Predicate<String> plainlyNamed) {
        String file = row.file();
        if (plainlyNamed.test(file) != plainlyNamed.test(first.file())) {
            return plainlyNamed.test(file);
        }
        if (depth(file) != depth(first.file())) {
            return depth(file) < depth(first.file());
        }
        if (PictureFormat.of(file) != PictureFormat.of(first.file())) {
            return PictureFormat.of(file).truerThan(PictureFormat.of(first.file()));
        }
        return twins(file, first.file()) && overTwin(row, first);
    }

    /**
     * Whether two pictures' names differ only in case (page3.png and page3.PNG): a case-sensitive file system
     * (Linux's) holds both, where on Windows or macOS they are one file, so neither name tells which was meant,
     * and the first by name is only the one with the capitals. Between them what they hold decides.
     */
    private static boolean twins(String file, String other) {
        return !file.equals(other) && file.equalsIgnoreCase(other);
    }

    /**
     * Whether {@code row}'s picture counts over its twin's ({@link #twins}), {@code first}, before it by name: one
     * that could be compared (read, and its page found in it) over one that could not (not a picture, damaged, at
     * another size), then the truer format its bytes were decoded as (a PNG over a JPEG named page3.PNG); else not,
     * and the first by name counts. Never by how it compared: a right picture does not count over a wrong one.
     */
    private static boolean overTwin(BatchRow row, BatchRow first) {
        if (row.compared() != first.compared()) {
            return row.compared();
        }
        return row.format() != null && first.format() != null && row.format().truerThan(first.format());
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
    private static String why(BatchRow countsRow, BatchRow row, Predicate<String> plainlyNamed) {
        String counts = countsRow.file();
        String file = row.file();
        String page = GradescopeResults.name(row.page());
        boolean plain = plainlyNamed.test(counts);
        String reason;
        if (plain && !plainlyNamed.test(file)) {
            reason = "its name is the page's name and nothing else";
        } else {
            PictureFormat format = PictureFormat.of(counts);
            PictureFormat other = PictureFormat.of(file);
            String named = plain ? "both are named the page's name and nothing else"
                    : "no picture's name is the page's name alone";
            String twins = named + ", their names differ only in case";
            reason = depth(counts) < depth(file) ? named + ", and it is nearer the top of the submission's folder"
                    : format.truerThan(other) ? named + ", and " + format.whyOver(other)
                    : twins(counts, file) && countsRow.compared() && !row.compared()
                            ? twins + ", and it could be compared, this one not"
                    : twins(counts, file) && overTwin(countsRow, row)
                            ? twins + ", and by what their bytes hold " + countsRow.format().whyOver(row.format())
                    : named + ", and it is the first by name";
        }
        return counts + " counts for " + page + " instead: " + reason;
    }
}

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
 * old_page3.png), or, when none or several are, the first of those in the table's order (natural order of
 * their paths). The others are marked {@link BatchRow#notCounted}: they score nothing and are worth nothing,
 * so a submission's total is never more than the pages asked for are worth. The rule goes by names alone,
 * so handing in more pictures of a page never raises its score.
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
                if (first == null || !plainlyNamed.test(first) && plainlyNamed.test(row.file())) {
                    counting.put(page, row.file());
                }
            }
        }
        List<BatchRow> marked = new ArrayList<>();
        for (BatchRow row : rows) {
            String counts = row.target().isEmpty() ? row.file()
                    : counting.get(List.of(submission.apply(row.file()), row.page()));
            marked.add(counts.equals(row.file()) ? row : row.notCounted(why(counts, row.page(), plainlyNamed)));
        }
        return marked;
    }

    /** Why {@code counts} is the picture of {@code target} that counts: "page3.png counts for page 3 instead: ...". */
    private static String why(String counts, String target, Predicate<String> plainlyNamed) {
        String page = GradescopeResults.name(target);
        return counts + " counts for " + page + " instead: "
                + (plainlyNamed.test(counts) ? "its name is the page's name and nothing else"
                        : "no picture's name is the page's name alone, and it is the first by name");
    }
}

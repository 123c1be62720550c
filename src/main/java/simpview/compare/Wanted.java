package simpview.compare;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A page or scene the batch was asked for (by --pages or the scenes of
 * --scene). One that no submitted picture matched is, in the results, a test
 * that scores nothing.
 *
 * @param target its label, as the rows name it ("6", "pageC.simp")
 * @param rule the rule it is judged by (its points are lost when it is missing)
 */
public record Wanted(String target, RubricRule rule) {

    /** Those of {@code wanted} that none of {@code rows} was matched to. */
    public static List<Wanted> missing(List<Wanted> wanted, List<BatchRow> rows) {
        return wanted.stream().filter(w -> rows.stream().noneMatch(r -> r.target().equals(w.target()))).toList();
    }

    /**
     * What each submission (the first folder of a row's path, as
     * {@link JUnitResults#submission} names it) lacks, as (submission, page)
     * pairs in the rows' order; all of {@code wanted}, under no submission
     * (""), when there are no rows.
     */
    public static List<Map.Entry<String, Wanted>> missingBySubmission(List<Wanted> wanted, List<BatchRow> rows) {
        Map<String, List<BatchRow>> bySubmission = new LinkedHashMap<>();
        for (BatchRow row : rows) {
            bySubmission.computeIfAbsent(JUnitResults.submission(row.file()), k -> new ArrayList<>()).add(row);
        }
        List<Map.Entry<String, Wanted>> missing = new ArrayList<>();
        if (bySubmission.isEmpty()) {
            wanted.forEach(w -> missing.add(Map.entry("", w)));
        }
        bySubmission.forEach((submission, its) ->
                missing(wanted, its).forEach(w -> missing.add(Map.entry(submission, w))));
        return missing;
    }
}

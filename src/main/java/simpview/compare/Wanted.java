package simpview.compare;

import java.util.List;

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
}

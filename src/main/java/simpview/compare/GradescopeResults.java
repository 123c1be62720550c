package simpview.compare;

import com.google.gson.GsonBuilder;
import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import java.util.List;
import java.util.Locale;

/**
 * A batch as Gradescope's autograder {@code results.json}: one test per
 * compared picture (its name the page and the file, its output the shares,
 * the largest regions and the diff image's name; {@code max_score} the
 * rule's points), one test scoring 0 for each page asked for that no picture
 * matched, one for each picture that could not be compared; the top-level
 * score is the sum of the tests' scores. Pictures that match no page are
 * left out (they are named in the top-level output).
 */
public final class GradescopeResults {

    /** The tag of a test of a picture that does not count (another picture of its page does). */
    static final String NOT_COUNTED = "NOT COUNTED";

    private GradescopeResults() {
    }

    /** {@code wanted}: every page or scene asked for; one no picture matched is a test scoring 0. */
    public static String json(List<BatchRow> rows, List<Wanted> wanted, double seconds) {
        List<Wanted> missing = Wanted.missing(wanted, rows);
        JsonArray tests = new JsonArray();
        double total = 0;
        int number = 0;
        StringBuilder skipped = new StringBuilder();
        for (BatchRow row : rows) {
            if (row.result() == BatchRow.Result.SKIPPED) {
                skipped.append("\n  ").append(row.file()).append(": ").append(row.note());
                continue;
            }
            JsonObject test = new JsonObject();
            test.addProperty("name", name(row.target()) + " (" + row.file() + ")");
            test.addProperty("number", String.valueOf(++number));
            test.addProperty("score", row.score());
            test.addProperty("max_score", row.rule().points());
            test.addProperty("output", output(row));
            test.addProperty("visibility", row.rule().visibility());
            JsonArray tags = new JsonArray();
            tags.add(name(row.target()));
            tags.add(row.result().name());
            if (!row.counts()) {
                tags.add(NOT_COUNTED);
            }
            test.add("tags", tags);
            tests.add(test);
            total += row.score();
        }
        for (Wanted lost : missing) {
            JsonObject test = new JsonObject();
            test.addProperty("name", name(lost.target()) + " (no picture)");
            test.addProperty("number", String.valueOf(++number));
            test.addProperty("score", 0.0);
            test.addProperty("max_score", lost.rule().points());
            String unreadable = lost.whyMissing("");
            test.addProperty("output", "No picture of " + name(lost.target()) + " was found in the submission"
                    + (unreadable.isEmpty() ? " (a picture is matched by its name, e.g. " + lost.example() + ")."
                            : ": " + Sentence.ended(unreadable)));
            test.addProperty("visibility", lost.rule().visibility());
            JsonArray tags = new JsonArray();
            tags.add(name(lost.target()));
            tags.add("MISSING");
            test.add("tags", tags);
            tests.add(test);
        }
        JsonObject results = new JsonObject();
        results.addProperty("score", hundredths(total));
        results.addProperty("execution_time", Math.max(1, (int) Math.ceil(seconds)));
        results.addProperty("output", BatchTable.summary(rows, missing.size())
                + (skipped.length() == 0 ? "" : "\nNot matched to any page:" + skipped));
        results.addProperty("stdout_visibility", "hidden");
        results.add("tests", tests);
        return new GsonBuilder().setPrettyPrinting().disableHtmlEscaping().create().toJson(results) + "\n";
    }

    /**
     * How a failing row scored in part came to its score, on a line of its own after the verdict: the share's way
     * from the zero point (zero_share, or an empty panel's share when higher) to min_share, and the failing pixels'
     * factor; "" for a row not scored in part.
     */
    private static String partialCredit(BatchRow row) {
        if (row.result() != BatchRow.Result.FAIL || !row.counts() || Double.isNaN(row.emptyShare())) {
            return "";
        }
        RubricRule rule = row.rule();
        double zero = rule.zeroPoint(row.emptyShare());
        String from = row.emptyShare() > rule.zeroShare()
                ? Percent.of(zero / 100) + ", what an empty panel (simpview's black background alone) gets here, above "
                        + "zero_share " + Percent.of(rule.zeroShare() / 100) + ","
                : "zero_share " + Percent.of(zero / 100) + " (an empty panel, simpview's black background alone, gets "
                        + Percent.of(row.emptyShare() / 100) + " here)";
        String pixels = rule.maxFailing() >= 0 && row.failing() > rule.maxFailing()
                ? String.format(Locale.ROOT, ", times %,d allowed / %,d failing pixels", rule.maxFailing(), row.failing())
                : "";
        return String.format(Locale.ROOT, "%npartial credit: %s of %s: the share counts from %s up to %s%s",
                points(row.score()), points(rule.points()) + (rule.points() == 1 ? " point" : " points"), from,
                Percent.of(rule.minShare() / 100), pixels);
    }

    /** A sum of scores rounded to hundredths, as the top-level score is (and each submission's total). */
    static double hundredths(double value) {
        return Math.round(value * 100) / 100.0;
    }

    /** Points as a score is read: "2", "0.26" (the web report writes them so too). */
    static String points(double value) {
        return value == Math.rint(value) ? String.valueOf((long) value) : String.format(Locale.ROOT, "%.2f", value);
    }

    /** "page 6" for a page's label ("6", "2 (seed 361)"), the scene's file name otherwise. */
    static String name(String target) {
        return target.matches("[0-9].*") ? "page " + target : target;
    }

    /**
     * The shares, the verdict, the largest regions and the diff image, as the test's output; first, when it
     * does not count, why not.
     */
    static String output(BatchRow row) {
        if (!row.compared()) {
            return row.result() + ": " + row.remarks();
        }
        RubricRule rule = row.rule();
        StringBuilder out = new StringBuilder();
        if (!row.counts()) {
            out.append("NOT COUNTED (scores nothing): ").append(row.notCounted()).append('\n');
        }
        out.append(String.format(Locale.ROOT, "%s: %s of panel pixels %s (%s needed)",
                row.result(), Percent.of(row.verdict()), row.verdictName(), Percent.of(rule.minShare() / 100)));
        if (rule.maxFailing() >= 0) {
            out.append("; " + Count.with(row.failing(), "pixel", "fails", "fail")
                    + String.format(Locale.ROOT, " (at most %,d allowed)", rule.maxFailing()));
        }
        out.append(partialCredit(row));
        out.append(String.format(Locale.ROOT, "%nidentical %s, within 1/255 %s, within 8/255 %s exactly; "
                + "%s, %s, %s with slack%n", Percent.of(row.exact().identical()), Percent.of(row.exact().within1()),
                Percent.of(row.exact().within8()), Percent.of(row.slack().identical()), Percent.of(row.slack().within1()),
                Percent.of(row.slack().within8())));
        if (!row.alternate().isEmpty()) {
            out.append("matched the accepted alternate ").append(row.alternate()).append('\n');
        }
        if (row.regions().isEmpty()) {
            out.append("no region differs beyond the tolerance\n");
        } else {
            out.append(rule.metric() == Comparison.Metric.FLIP
                    ? Count.with(row.failing(), "pixel", "is", "are") + " above FLIP's threshold"
                    : Count.with(row.failing(), "pixel", "differs", "differ") + " beyond the tolerance");
            out.append(String.format(Locale.ROOT, "; the largest regions (panel pixels, origin bottom-left, y up):%n"));
            for (DiffRegion region : row.regions()) {
                out.append("  ").append(region.describe()).append('\n');
            }
        }
        if (row.panelHint() != null) {
            out.append("hint: ").append(row.panelHint().hint(row.size())).append('\n');
        }
        row.notes().forEach(note -> out.append("note: ").append(note).append('\n'));
        // a panel of the first assignment's pages has no margins of its own
        out.append(row.margins().isEmpty() ? row.note() : "margins: " + row.margins());
        if (!row.diff().isEmpty()) {
            out.append("\ndiff image: ").append(row.diff());
        }
        return out.toString();
    }
}

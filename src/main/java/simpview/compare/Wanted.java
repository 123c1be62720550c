package simpview.compare;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Function;

/**
 * A page or scene the batch was asked for (by --pages or the scenes of
 * --scene). One that no submitted picture matched is, in the results, a test
 * that scores nothing.
 *
 * @param target its label, as the rows name it ("6", "pageC.simp")
 * @param rule the rule it is judged by (its points are lost when it is missing)
 * @param unreadable the files handed in that are named like it but are in a format simpview does not read
 *     (page6.tif), by their paths in the folder: a page missing from a submission that handed in one of
 *     these is told why
 * @param example a file name a picture of it may have, for the words of a missing page ("page3.png",
 *     "a1-page3.png")
 * @param withoutPictures the submissions that hold no picture at all (a class's first-level folder holding only
 *     a zip, or the whole folder): each lacks it, and is told what it holds instead
 * @param misnamed the pictures handed in that were not taken for it but may have been meant as it, each with why
 *     ("pag3.png is named like no page: did you mean page3.png?"): a submission that lacks it and handed in one
 *     of these is told so
 * @param archives the archives handed in beside pictures (alice/alice_A2.zip beside alice/page1.png), by their
 *     paths in the folder, which simpview does not open: a submission that lacks it and holds one of these is told
 *     that it may be in there
 */
public record Wanted(String target, RubricRule rule, List<String> unreadable, String example,
        List<WithoutPictures> withoutPictures, List<Misnamed> misnamed, List<String> archives) {

    /**
     * A picture (its path in the folder) that names no page or scene asked for, but may have been meant as this one,
     * and why: "pag3.png is named like no page: did you mean page3.png?".
     */
    public record Misnamed(String file, String why) {
    }

    public Wanted(String target, RubricRule rule, List<String> unreadable, String example,
            List<WithoutPictures> withoutPictures, List<Misnamed> misnamed) {
        this(target, rule, unreadable, example, withoutPictures, misnamed, List.of());
    }

    public Wanted(String target, RubricRule rule, List<String> unreadable, String example,
            List<WithoutPictures> withoutPictures) {
        this(target, rule, unreadable, example, withoutPictures, List.of());
    }

    /** A page's file name for the examples when none is given. */
    public static final String PAGE_EXAMPLE = "page3.png";

    public Wanted(String target, RubricRule rule) {
        this(target, rule, List.of());
    }

    public Wanted(String target, RubricRule rule, List<String> unreadable) {
        this(target, rule, unreadable, PAGE_EXAMPLE);
    }

    public Wanted(String target, RubricRule rule, List<String> unreadable, String example) {
        this(target, rule, unreadable, example, List.of());
    }

    /** Those of {@code wanted} that none of {@code rows} was matched to. */
    public static List<Wanted> missing(List<Wanted> wanted, List<BatchRow> rows) {
        return wanted.stream().filter(w -> rows.stream().noneMatch(w::metBy)).toList();
    }

    /**
     * Whether a row is of it: its target is this one, or (a page compared panel by panel, the first
     * assignment's "A1 page 2") one of its panels ("A1 page 2 panel 4 (antialiased)").
     */
    public boolean metBy(BatchRow row) {
        return row.target().equals(target) || row.target().startsWith(target + " panel ");
    }

    /**
     * What each submission (the first folder of a row's path, as
     * {@link JUnitResults#submission} names it) lacks, as (submission, page)
     * pairs in the rows' order; then the submissions that handed in no picture
     * but a file in a format simpview does not read, and the first-level folders
     * without a picture ({@link #withoutPictures}), which lack every page; all
     * of {@code wanted}, under no submission (""), when there are none of these.
     */
    public static List<Map.Entry<String, Wanted>> missingBySubmission(List<Wanted> wanted, List<BatchRow> rows) {
        return missingBySubmission(wanted, rows, JUnitResults::submission);
    }

    /**
     * The same with the submission of a file (its path in the folder) given: "" for every file when the folder is
     * one student's however its pictures are foldered (page1.png beside renders/page8.png), whose pages are then
     * missing from the whole folder.
     */
    public static List<Map.Entry<String, Wanted>> missingBySubmission(List<Wanted> wanted, List<BatchRow> rows,
            Function<String, String> submissionOf) {
        Map<String, List<BatchRow>> bySubmission = new LinkedHashMap<>();
        for (BatchRow row : rows) {
            bySubmission.computeIfAbsent(submissionOf.apply(row.file()), k -> new ArrayList<>()).add(row);
        }
        for (Wanted w : wanted) {
            w.unreadable().forEach(file -> bySubmission.computeIfAbsent(submissionOf.apply(file),
                    k -> new ArrayList<>()));
        }
        for (String folder : foldersWithoutPictures(wanted)) {
            bySubmission.computeIfAbsent(folder, k -> new ArrayList<>());
        }
        List<Map.Entry<String, Wanted>> missing = new ArrayList<>();
        if (bySubmission.isEmpty()) {
            wanted.forEach(w -> missing.add(Map.entry("", w)));
        }
        bySubmission.forEach((submission, its) -> {
            if (asked(submission, its, bySubmission.size(), wanted)) {
                missing(wanted, its).forEach(w -> missing.add(Map.entry(submission, w)));
            }
        });
        return missing;
    }

    /**
     * Whether a submission, {@code its} rows, one of {@code submissions}, is asked for the pages of {@code wanted}.
     * Every one is but the pictures at the top of a class's folder ({@link JUnitResults#TOP} beside other
     * submissions) when each of them names no page and nothing there is named like one in a format simpview does
     * not read: an example.png the teacher keeps beside the students' folders is nobody's pages, and was a
     * submission lacking every page, failing the run. A student's folder of pictures named like no page is asked,
     * its skipped rows saying why its pages are missing.
     */
    static boolean asked(String submission, List<BatchRow> its, int submissions, List<Wanted> wanted) {
        boolean nobodys = submission.equals(JUnitResults.TOP) && submissions > 1 && !its.isEmpty()
                && its.stream().allMatch(r -> r.result() == BatchRow.Result.SKIPPED)
                && wanted.stream().allMatch(w -> w.unreadableIn(JUnitResults.TOP).isEmpty());
        return !nobodys;
    }

    /** The first-level folders without a picture that lack every page of {@code wanted}, in order, each once. */
    public static List<String> foldersWithoutPictures(List<Wanted> wanted) {
        return wanted.stream().flatMap(w -> w.withoutPictures().stream()).map(WithoutPictures::submission)
                .filter(s -> !s.isEmpty()).distinct().toList();
    }

    /**
     * Why {@code submission} ("" or {@link JUnitResults#TOP} for the whole folder) has no picture of it, when what
     * it handed in tells: a file named like it in a format simpview does not read ({@link #unreadableNote}), or
     * no picture at all but a zip or other files ({@link WithoutPictures#note}); the archives it holds beside its
     * pictures, unopened ({@link #archiveNote}); then each picture of it that may have been meant as it
     * ({@link #misnamed}); "" when none tells.
     */
    public String whyMissing(String submission) {
        String unreadable = unreadableNote(submission);
        String why = !unreadable.isEmpty() ? unreadable : withoutPictures.stream().filter(w -> w.isOf(submission))
                .map(WithoutPictures::note).findFirst().orElse("");
        if (withoutPictures.stream().noneMatch(w -> w.isOf(submission))) {
            String archived = archiveNote(submission);
            why = why.isEmpty() || archived.isEmpty() ? why + archived : why + "; " + archived;
        }
        // the pictures of the submission that may have been meant as it: misnamed, or named for no page there is
        for (Misnamed picture : misnamed) {
            if (submission.isEmpty() || JUnitResults.submission(picture.file()).equals(submission)) {
                why = why.isEmpty() ? picture.why() : why + "; " + picture.why();
            }
        }
        return why;
    }

    /**
     * The archives {@code submission} ("" for the whole folder) holds beside its pictures, which simpview does not
     * open: "alice/alice_A2.zip is in the folder too, not opened (simpview does not look inside a zip): the page
     * may be in it; unzip it"; "" when it holds none.
     */
    public String archiveNote(String submission) {
        List<String> files = archives.stream()
                .filter(file -> submission.isEmpty() || JUnitResults.submission(file).equals(submission)).toList();
        if (files.isEmpty()) {
            return "";
        }
        boolean zips = files.stream().allMatch(f -> f.toLowerCase(Locale.ROOT).endsWith(".zip"));
        boolean one = files.size() == 1;
        return Sentence.listed(files) + (one ? " is" : " are") + " in the folder too, not opened (simpview does "
                + "not look inside " + (zips ? "a zip" : "an archive") + "): the " + (target.endsWith(".simp")
                ? "picture" : "page") + " may be in " + (one ? "it; " : "them; ") + (zips ? "unzip " : "unpack ")
                + (one ? "it" : "them");
    }

    /** Its unreadable files handed in by {@code submission} (a first-level folder, or "" for the whole folder). */
    public List<String> unreadableIn(String submission) {
        return unreadable.stream()
                .filter(file -> submission.isEmpty() || JUnitResults.submission(file).equals(submission)).toList();
    }

    /**
     * Why a submission ("" for the whole folder) that lacks it has no picture of it, when it handed in a file
     * named like it in a format simpview does not read: "st/page6.tif is named like it, but is in a format
     * simpview does not read (it reads PNG, JPEG, GIF and BMP)"; "" otherwise.
     */
    public String unreadableNote(String submission) {
        List<String> files = unreadableIn(submission);
        if (files.isEmpty()) {
            return "";
        }
        return files.size() == 1
                ? files.get(0) + " is named like it, but is in a format simpview does not read (it reads PNG, "
                        + "JPEG, GIF and BMP)"
                : String.join(" and ", files) + " are named like it, but are in formats simpview does not read (it "
                        + "reads PNG, JPEG, GIF and BMP)";
    }
}

package simpview.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Function;
import simpview.compare.CompareException;
import simpview.compare.Comparison;
import simpview.compare.ComparisonReport;
import simpview.compare.Picture;
import simpview.compare.RubricRule;

/**
 * A rubric rule's accepted alternates (docs/grading.md): the pictures of its folder that a picture may match instead
 * of simpview's own, and the verdict that tries them. A batch ({@code --dir}, {@code check}) and one picture
 * ({@code compare IMAGE --rubric}) both judge by these, so a picture gets the same verdict alone as in its batch.
 */
final class Alternates {

    private Alternates() {
    }

    /** An accepted alternate's panel, by its name in the rule's folder ("page1-other-method.png"). */
    record Accepted(String name, int[] panel) {
    }

    /**
     * What a picture was judged against: {@code report} of simpview's own ({@code alternate} "") or of the accepted
     * alternate of that name that it passes against.
     */
    record Judged(ComparisonReport report, String alternate) {
    }

    /**
     * The accepted alternates of {@code rule} for the page or scene of rubric key {@code key} ("page6", "pageC"):
     * a picture of the rule's folder whose name names a page or scene ({@code namer}, as submissions are named)
     * is for that one only; one that names none is for every page or scene of the rule. In the folder's order.
     * {@code read} holds each file read so far (its {@link Picture}, or the error it gave), so a folder shared by
     * several pages is read once; an unreadable alternate is said on {@code err} after {@code says} and left out.
     */
    static List<Accepted> of(RubricRule rule, String key, Function<String, Optional<String>> namer,
            Map<Path, Object> read, PrintWriter err, String says) {
        List<Accepted> accepted = new ArrayList<>();
        if (rule.alternates() == null) {
            return accepted;
        }
        List<Path> files;
        try {
            files = picturesIn(rule.alternates());
        } catch (IOException | UncheckedIOException e) {
            err.println(says + "alternates " + rule.alternates() + ": cannot be listed");
            return accepted;
        }
        for (Path file : files) {
            Optional<String> named = namer.apply(file.getFileName().toString());
            if (named.isPresent() && !named.get().equals(key)) {
                continue;
            }
            Object picture = read.computeIfAbsent(file, f -> {
                try {
                    return Picture.read(f);
                } catch (CompareException e) {
                    err.println(says + "alternate left out: " + e.getMessage());
                    return e;
                }
            });
            if (picture instanceof Picture p) {
                accepted.add(new Accepted(rule.alternates().relativize(file).toString(), p.panel()));
            }
        }
        return accepted;
    }

    /**
     * The pictures under {@code dir} (a rule's folder of accepted alternates), in natural order of their paths (page2
     * before page10), hidden ones left out.
     */
    static List<Path> picturesIn(Path dir) throws IOException {
        return FolderListing.of(dir).pictures();
    }

    /**
     * The verdict on {@code theirs} under {@code rule}: {@code own}, its report against simpview's own picture, when
     * it passes; else the report against the first of {@code alternates} that it passes against, in order; when
     * none does, {@code own}. {@code against}: the words for what simpview drew, as {@code own} has them.
     */
    static Judged judge(ComparisonReport own, Picture theirs, String against, RubricRule rule,
            List<Accepted> alternates) {
        if (own.passes()) {
            return new Judged(own, "");
        }
        for (Accepted alternate : alternates) {
            Comparison comparison = rule.compare(alternate.panel(), theirs.panel(), Comparison.N);
            ComparisonReport report = ComparisonReport.of(theirs, against, comparison, rule);
            if (report.passes()) {
                return new Judged(report, alternate.name());
            }
        }
        return new Judged(own, "");
    }
}

package simpview.window.instruments;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.OptionalInt;
import java.util.stream.Stream;
import simpview.compare.BatchRow;
import simpview.compare.CompareException;
import simpview.compare.Comparison;
import simpview.compare.ComparisonReport;
import simpview.compare.Picture;
import simpview.compare.RubricRule;
import simpview.compare.StudentTable;
import simpview.compare.SubmissionNames;
import simpview.compare.Wanted;
import simpview.pages.Assignment2;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.pages.SceneList;
import simpview.scene.SceneException;

/**
 * A folder dropped on the window: {@code simpview check} for the eight
 * pages. Every picture in the folder (and its subfolders) whose name names
 * a page is compared with that page as the window draws it (its seed and
 * scene folder), by today's defaults (8/255, one pixel of slack, 99 %), and
 * the result is the same table {@code check} prints. Runs off the EDT: the
 * window starts it on its own thread and shows the text when it is done.
 */
public final class FolderCheck {

    private static final List<String> PICTURE_ENDINGS = List.of(".png", ".jpg", ".jpeg", ".gif", ".bmp");

    private FolderCheck() {
    }

    /** The folder's pictures against the pages drawn with {@code context}, as check's table. */
    public static String text(Path folder, PageContext context) {
        RubricRule rule = RubricRule.defaults(8, 99, Comparison.DEFAULT_DEVIATION, Comparison.Metric.EXACT);
        List<BatchRow> rows = new ArrayList<>();
        Map<Integer, Object> drawn = new HashMap<>();
        for (Path file : picturesIn(folder)) {
            String relative = folder.relativize(file).toString();
            OptionalInt page = SubmissionNames.pageNumber(file.getFileName().toString());
            if (page.isEmpty() || page.getAsInt() > Assignment2.COUNT) {
                rows.add(BatchRow.skipped(relative, "no page 1 to 8 in the name"));
                continue;
            }
            int n = page.getAsInt();
            String label = label(n, context);
            Object ours = drawn.computeIfAbsent(n, k -> draw(k, context));
            if (ours instanceof String problem) {
                rows.add(BatchRow.broken(relative, label, problem, rule));
                continue;
            }
            try {
                Picture theirs = Picture.read(file);
                Comparison c = Comparison.of(((Picture) ours).panel(), theirs.panel());
                ComparisonReport report = ComparisonReport.of(theirs, "page " + n, c, rule);
                rows.add(BatchRow.compared(relative, label, report, "", rule, rule.score(c, false), ""));
            } catch (CompareException e) {
                rows.add(BatchRow.broken(relative, label, e.getMessage(), rule));
            }
        }
        List<Wanted> wanted = new ArrayList<>();
        for (int n = 1; n <= Assignment2.COUNT; n++) {
            wanted.add(new Wanted(label(n, context), rule));
        }
        if (rows.isEmpty()) {
            return "No pictures (.png, .jpg, .gif, .bmp) in " + folder + ".\n";
        }
        return StudentTable.text(rows, Wanted.missing(wanted, rows));
    }

    /** As check labels a page: "6", or "2 (seed 361)" for the seeded pages. */
    private static String label(int page, PageContext context) {
        return Assignment2.page(page).usesSeed() ? page + " (seed " + context.seed() + ")" : String.valueOf(page);
    }

    private static Object draw(int page, PageContext context) {
        try {
            BufferedImage image = new PageRenderer().renderImage(page, context);
            return Picture.ofPage(image, "simpview's page " + page);
        } catch (SceneException e) {
            return "simpview cannot draw it: " + e.getMessage();
        }
    }

    private static List<Path> picturesIn(Path folder) {
        try (Stream<Path> files = Files.walk(folder)) {
            return files.filter(Files::isRegularFile)
                    .filter(f -> PICTURE_ENDINGS.stream().anyMatch(
                            e -> f.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(e)))
                    .sorted((a, b) -> SceneList.NATURAL_ORDER.compare(folder.relativize(a).toString(),
                            folder.relativize(b).toString()))
                    .toList();
        } catch (IOException | UncheckedIOException e) {
            return List.of();
        }
    }
}

package simpview.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.TreeMap;
import java.util.function.Function;
import java.util.stream.Stream;
import simpview.app.CompareOptions.PageRange;
import simpview.compare.BatchRow;
import simpview.compare.BatchTable;
import simpview.compare.CompareException;
import simpview.compare.Comparison;
import simpview.compare.ComparisonReport;
import simpview.compare.HeatMap;
import simpview.compare.Percent;
import simpview.compare.Picture;
import simpview.compare.SubmissionNames;
import simpview.scene.simp.SceneException;

/**
 * {@code simpview compare --dir ...}: every picture in a folder (and its
 * subfolders) against the page or scene its name names, one table row each.
 * A picture that cannot be read is a row saying why; the rest go on.
 */
final class CompareBatch {

    static final String TABLE = "compare.md";
    static final String CSV = "compare.csv";
    static final String DIFFS = "diffs";
    private static final List<String> PICTURE_ENDINGS = List.of(".png", ".jpg", ".jpeg", ".gif", ".bmp");

    /** What a picture's name matched: a target, or why it was skipped. */
    private record Match(CompareTarget target, String skipped) {
    }

    private final OwnPictures own;
    private final int tolerance;
    private final double min;
    private final PrintWriter out;
    private final PrintWriter err;

    CompareBatch(OwnPictures own, int tolerance, double min, PrintWriter out, PrintWriter err) {
        this.own = own;
        this.tolerance = tolerance;
        this.min = min;
        this.out = out;
        this.err = err;
    }

    /** Pictures matched to pages by the number in their names: page3.png is page 3. */
    int pages(Path dir, PageRange pages, Path outDir) {
        return run(dir, outDir, name -> {
            OptionalInt number = SubmissionNames.pageNumber(name);
            if (number.isEmpty()) {
                return new Match(null, "no page number in the name (expected a name like page3.png)");
            }
            if (!pages.contains(number.getAsInt())) {
                return new Match(null, "page " + number.getAsInt() + " is not among --pages " + pages);
            }
            return new Match(CompareTarget.page(number.getAsInt()), null);
        });
    }

    /** Every picture against one scene file, or against the scene of a folder that its name names. */
    int scenes(Path dir, Path scene, Path outDir) {
        if (Files.isRegularFile(scene)) {
            return run(dir, outDir, name -> new Match(CompareTarget.scene(scene), null));
        }
        if (!Files.isDirectory(scene)) {
            err.println("simpview compare: --scene " + scene + ": no such file or folder");
            return Main.USAGE_ERROR;
        }
        Map<String, Path> scenes = scenesIn(scene);
        if (scenes.isEmpty()) {
            err.println("simpview compare: --scene " + scene + ": no .simp files in that folder");
            return Main.USAGE_ERROR;
        }
        return run(dir, outDir, name -> {
            Optional<String> named = SubmissionNames.sceneName(name, scenes.keySet());
            return named.map(s -> new Match(CompareTarget.scene(scenes.get(s)), null))
                    .orElseGet(() -> new Match(null, "its name names none of the scenes in " + scene));
        });
    }

    private int run(Path dir, Path outDir, Function<String, Match> matcher) {
        List<Path> pictures;
        try {
            pictures = picturesIn(dir);
        } catch (IOException | UncheckedIOException e) {
            err.println("simpview compare: --dir " + dir + ": " + (Files.isDirectory(dir) ? "cannot be listed" : "no such folder"));
            return Main.USAGE_ERROR;
        }
        List<BatchRow> rows = new ArrayList<>();
        long start = System.nanoTime();
        for (int i = 0; i < pictures.size(); i++) {
            String relative = dir.relativize(pictures.get(i)).toString();
            Match match = matcher.apply(pictures.get(i).getFileName().toString());
            BatchRow row = match.target() == null ? BatchRow.skipped(relative, match.skipped())
                    : compare(pictures.get(i), relative, match.target(), outDir);
            rows.add(row);
            err.printf("[%d/%d] %s: %s%n", i + 1, pictures.size(), relative, progress(row));
        }
        err.printf(Locale.ROOT, "%d pictures in %.2f s%n", pictures.size(), (System.nanoTime() - start) / 1e9);
        return writeTables(rows, outDir);
    }

    private static String progress(BatchRow row) {
        return switch (row.result()) {
            case PASS, FAIL -> row.result() + " " + Percent.of(row.verdict());
            case ERROR, SKIPPED -> row.result() + ": " + row.note().lines().findFirst().orElse("");
        };
    }

    private BatchRow compare(Path file, String relative, CompareTarget target, Path outDir) {
        String label = target.label(own.context());
        Picture theirs;
        Picture ours;
        try {
            ours = own.of(target);
        } catch (SceneException e) {
            return BatchRow.broken(relative, label, "simpview cannot draw it: " + e.getMessage());
        }
        try {
            theirs = Picture.read(file);
        } catch (CompareException e) {
            return BatchRow.broken(relative, label, e.getMessage());
        }
        Comparison comparison = Comparison.of(ours.panel(), theirs.panel());
        ComparisonReport report = ComparisonReport.of(theirs, target.describe(own.context()), comparison, tolerance, min);
        String diff = DIFFS + "/" + relative.replaceAll("[/\\\\]", "_").replaceFirst("\\.[^.]*$", "") + "-diff.png";
        try {
            PngFiles.writeEncoded(HeatMap.diffPng(comparison, tolerance), outDir.resolve(diff));
        } catch (IOException e) {
            BatchRow row = BatchRow.compared(relative, label, report, "");
            return new BatchRow(row.file(), row.target(), row.exact(), row.slack(), row.verdict(), row.result(),
                    row.margins(), "", "diff not written: " + e.getMessage());
        }
        return BatchRow.compared(relative, label, report, diff);
    }

    private int writeTables(List<BatchRow> rows, Path outDir) {
        String markdown = BatchTable.markdown(rows, tolerance, min);
        try {
            Files.createDirectories(outDir);
            Files.writeString(outDir.resolve(TABLE), markdown, StandardCharsets.UTF_8);
            Files.writeString(outDir.resolve(CSV), BatchTable.csv(rows), StandardCharsets.UTF_8);
        } catch (IOException e) {
            err.println("simpview compare: cannot write the table to " + outDir + ": " + e.getMessage());
            return Main.SCENE_ERROR;
        }
        out.print(markdown);
        out.println("table: " + outDir.resolve(TABLE) + " and " + outDir.resolve(CSV));
        if (rows.isEmpty()) {
            err.println("simpview compare: no pictures (.png, .jpg, .gif, .bmp) found");
            return Main.SCENE_ERROR;
        }
        boolean allPass = rows.stream().allMatch(r -> r.result() != BatchRow.Result.FAIL && r.result() != BatchRow.Result.ERROR);
        return allPass ? Main.OK : Main.SCENE_ERROR;
    }

    /** The pictures under {@code dir}, in natural order of their paths (page2 before page10). */
    static List<Path> picturesIn(Path dir) throws IOException {
        try (Stream<Path> files = Files.walk(dir)) {
            return files.filter(Files::isRegularFile)
                    .filter(f -> PICTURE_ENDINGS.stream().anyMatch(
                            e -> f.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(e)))
                    .sorted((a, b) -> NaturalOrder.compare(dir.relativize(a).toString(), dir.relativize(b).toString()))
                    .toList();
        }
    }

    private static Map<String, Path> scenesIn(Path folder) {
        Map<String, Path> scenes = new TreeMap<>();
        try (Stream<Path> files = Files.list(folder)) {
            files.filter(f -> f.getFileName().toString().endsWith(".simp") && Files.isRegularFile(f))
                    .forEach(f -> scenes.put(SubmissionNames.stem(f.getFileName().toString()), f));
        } catch (IOException e) {
            // an unreadable folder has no scenes; the caller says so
        }
        return scenes;
    }
}

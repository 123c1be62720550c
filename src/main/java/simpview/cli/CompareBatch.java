package simpview.cli;

import simpview.compare.PngFiles;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.TreeMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Function;
import java.util.stream.Stream;
import simpview.cli.CompareOptions.PageRange;
import simpview.compare.BatchRow;
import simpview.compare.BatchTable;
import simpview.compare.CompareException;
import simpview.compare.Comparison;
import simpview.compare.ComparisonReport;
import simpview.compare.HeatMap;
import simpview.compare.Percent;
import simpview.compare.Picture;
import simpview.compare.SubmissionNames;
import simpview.pages.SceneList;
import simpview.scene.SceneException;

/**
 * {@code simpview compare --dir ...}: every picture in a folder (and its
 * subfolders) against the page or scene its name names, one table row each.
 * A picture that cannot be read is a row saying why; the rest go on.
 */
public final class CompareBatch {

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
            if (number.isPresent() && SubmissionNames.namesFirstAssignment(name)) {
                return new Match(null, "a first-assignment page by its name: compare it alone, with "
                        + "compare " + name + " --assignment 1 --page " + number.getAsInt()
                        + " (the batch does not compare those yet)");
            }
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
            return ExitCode.USAGE_ERROR;
        }
        Map<String, Path> scenes = scenesIn(scene);
        if (scenes.isEmpty()) {
            err.println("simpview compare: --scene " + scene + ": no .simp files in that folder");
            return ExitCode.USAGE_ERROR;
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
            return ExitCode.USAGE_ERROR;
        }
        long start = System.nanoTime();
        List<Match> matches = new ArrayList<>();
        for (Path picture : pictures) {
            matches.add(matcher.apply(picture.getFileName().toString()));
        }
        Map<CompareTarget, Object> drawn = drawAll(matches);
        List<BatchRow> rows = compareAll(dir, pictures, matches, drawn, outDir);
        err.printf(Locale.ROOT, "%d pictures in %.2f s%n", pictures.size(), (System.nanoTime() - start) / 1e9);
        return writeTables(rows, outDir);
    }

    /** Each page or scene the pictures need, drawn once, in order (the canvas is one): its Picture or its error. */
    private Map<CompareTarget, Object> drawAll(List<Match> matches) {
        Map<CompareTarget, Object> drawn = new HashMap<>();
        for (Match match : matches) {
            if (match.target() != null && !drawn.containsKey(match.target())) {
                try {
                    drawn.put(match.target(), own.of(match.target()));
                } catch (SceneException e) {
                    drawn.put(match.target(), "simpview cannot draw it: " + e.getMessage());
                }
            }
        }
        return drawn;
    }

    /** The comparisons, on as many threads as there are cores; rows in the pictures' order. */
    private List<BatchRow> compareAll(Path dir, List<Path> pictures, List<Match> matches,
            Map<CompareTarget, Object> drawn, Path outDir) {
        AtomicInteger named = new AtomicInteger();
        ExecutorService workers = Executors.newFixedThreadPool(
                Math.max(1, Math.min(4, Runtime.getRuntime().availableProcessors())),
                task -> new Thread(task, "simpview-compare-" + named.incrementAndGet()));
        AtomicInteger finished = new AtomicInteger();
        try {
            List<Future<BatchRow>> rows = new ArrayList<>();
            for (int i = 0; i < pictures.size(); i++) {
                Path picture = pictures.get(i);
                Match match = matches.get(i);
                rows.add(workers.submit(() -> {
                    String relative = dir.relativize(picture).toString();
                    BatchRow row = match.target() == null ? BatchRow.skipped(relative, match.skipped())
                            : compare(picture, relative, match.target(), drawn.get(match.target()), outDir);
                    synchronized (err) {
                        err.printf("[%d/%d] %s: %s%n", finished.incrementAndGet(), pictures.size(), relative, progress(row));
                    }
                    return row;
                }));
            }
            List<BatchRow> done = new ArrayList<>();
            for (Future<BatchRow> row : rows) {
                done.add(row.get());
            }
            return done;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while comparing", e);
        } catch (ExecutionException e) {
            throw new IllegalStateException("a comparison failed", e.getCause());
        } finally {
            workers.shutdownNow();
        }
    }

    private static String progress(BatchRow row) {
        return switch (row.result()) {
            case PASS, FAIL -> row.result() + " " + Percent.of(row.verdict());
            case ERROR, SKIPPED -> row.result() + ": " + row.note().lines().findFirst().orElse("");
        };
    }

    /** One picture against simpview's (a Picture, or the error that kept it from being drawn). Thread-safe. */
    private BatchRow compare(Path file, String relative, CompareTarget target, Object ours, Path outDir) {
        String label = target.label(own.context());
        if (ours instanceof String problem) {
            return BatchRow.broken(relative, label, problem);
        }
        Picture theirs;
        try {
            theirs = Picture.read(file);
        } catch (CompareException e) {
            return BatchRow.broken(relative, label, e.getMessage());
        }
        Comparison comparison = Comparison.of(((Picture) ours).panel(), theirs.panel());
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
            return ExitCode.SCENE_ERROR;
        }
        out.print(markdown);
        out.println("table: " + outDir.resolve(TABLE) + " and " + outDir.resolve(CSV));
        if (rows.isEmpty()) {
            err.println("simpview compare: no pictures (.png, .jpg, .gif, .bmp) found");
            return ExitCode.SCENE_ERROR;
        }
        boolean allPass = rows.stream().allMatch(r -> r.result() != BatchRow.Result.FAIL && r.result() != BatchRow.Result.ERROR);
        return allPass ? ExitCode.OK : ExitCode.SCENE_ERROR;
    }

    /** The pictures under {@code dir}, in natural order of their paths (page2 before page10). */
    static List<Path> picturesIn(Path dir) throws IOException {
        try (Stream<Path> files = Files.walk(dir)) {
            return files.filter(Files::isRegularFile)
                    .filter(f -> PICTURE_ENDINGS.stream().anyMatch(
                            e -> f.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(e)))
                    .sorted((a, b) -> SceneList.NATURAL_ORDER.compare(dir.relativize(a).toString(), dir.relativize(b).toString()))
                    .toList();
        }
    }

    private static Map<String, Path> scenesIn(Path folder) {
        Map<String, Path> scenes = new TreeMap<>();
        try {
            SceneList.folder(folder).forEach(f -> scenes.put(SubmissionNames.stem(f.getFileName().toString()), f));
        } catch (IllegalArgumentException e) {
            // an unreadable folder has no scenes; the caller says so
        }
        return scenes;
    }
}

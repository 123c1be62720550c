package simpview.compare;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;

/**
 * {@code simpview check}'s one table for a student: each picture found, the
 * page it was matched to, PASS or FAIL, the share the verdict is on, and the
 * worst region (the largest patch that differs even with slack), in aligned
 * plain-text columns; then the hints of what a whole panel looks like
 * ({@link PanelHint}) and the notes of pictures that pass with a solid patch or fail saved as JPEG or GIF
 * ({@link BatchRow#notes}) or by their rubric's pixel limit ({@link BatchRow#pixelLimit}); then the pictures
 * that do not count (another picture of their page does) and why, the pages asked for that no picture matched, and
 * one line of counts, of the pictures that count (of the first assignment's
 * pages, of their panels).
 */
public final class StudentTable {

    private static final String[] HEADINGS = {"picture", "page", "result", "share", "worst region"};

    private StudentTable() {
    }

    public static String text(List<BatchRow> rows, List<Wanted> missing) {
        return text(rows, missing, row -> null);
    }

    /**
     * The same, with two lines after the notes for each failing picture (of a page, a scene, or the first assignment's
     * page of panels, once however many of its panels fail) for which {@code nextStep} gives a command: the picture
     * and what the command shows, then the command, the one that compares that picture alone and says where and why
     * it differs ({@code next: simpview compare page-c3.png ...}), which is all of its line after the label.
     */
    public static String text(List<BatchRow> rows, List<Wanted> missing, Function<BatchRow, String> nextStep) {
        List<String[]> lines = new ArrayList<>();
        lines.add(HEADINGS);
        for (BatchRow row : rows) {
            if (row.result() == BatchRow.Result.SKIPPED) {
                continue;
            }
            String worst;
            if (!row.compared()) {
                worst = row.note().lines().findFirst().orElse("");
            } else if (row.regions().isEmpty()) {
                worst = "none";
            } else {
                worst = row.regions().get(0).describe();
            }
            lines.add(new String[] {row.file(), GradescopeResults.name(row.target()), row.result().name(),
                row.compared() ? Percent.of(row.verdict()) : "", worst});
        }
        int[] widths = new int[HEADINGS.length];
        for (String[] line : lines) {
            for (int c = 0; c < line.length; c++) {
                widths[c] = Math.max(widths[c], line[c].length());
            }
        }
        StringBuilder out = new StringBuilder();
        for (String[] line : lines) {
            StringBuilder one = new StringBuilder();
            for (int c = 0; c < line.length; c++) {
                String cell = c == 3 ? pad(line[c], widths[c], true) : pad(line[c], widths[c], false);
                one.append(c == 0 ? "" : "  ").append(cell);
            }
            out.append(one.toString().stripTrailing()).append('\n');
        }
        PanelHint said = null;
        Set<Integer> saidAlike = new HashSet<>(); // rows whose hint was said with an earlier panel's
        for (int r = 0; r < rows.size(); r++) {
            BatchRow row = rows.get(r);
            PanelHint hint = row.panelHint();
            if (hint == null || hint == said || saidAlike.contains(r)) { // a page turned whole: one hint for its panels
                continue;
            }
            String which = hint.wholePage() ? row.page() : row.target();
            String text = hint.hint(row.size());
            List<Integer> alike = hint.wholePage() || row.panel() == 0 ? List.of() : alike(rows, r, saidAlike);
            if (alike.size() > 1) { // the same mistake in several panels of the picture: said once, for all of them
                which = row.page() + " " + PanelWords.panels(alike);
                String first = text;
                boolean sameWords = alike.stream().allMatch(k -> first.equals(hintOfPanel(rows, row.file(), k)));
                text = PanelWords.sharedHint(text, sameWords, alike);
            }
            out.append("hint: ").append(row.file()).append(" (").append(GradescopeResults.name(which)).append("): ")
                    .append(text).append('\n');
            said = hint;
        }
        Set<String> notes = new LinkedHashSet<>(); // a page of panels: its picture's note (its format) once
        for (BatchRow row : rows) {
            String limit = row.pixelLimit(false); // a FAIL whose share reaches what is needed says why it fails
            if (!limit.isEmpty()) {
                notes.add("note: " + row.file() + " (" + GradescopeResults.name(row.target()) + "): " + limit + "\n");
            }
            DiffRegion patch = row.solidPatch();
            String patchNote = patch == null ? null : ComparisonReport.solidPatchNote(patch);
            for (String note : row.notes()) {
                // a panel's own patch is said of that panel, by name; its picture's note (its format) of its page, as
                // a page of the eight is named beside its picture's
                boolean ofThisRow = !isPanel(row) || note.equals(patchNote);
                notes.add("note: " + row.file() + " (" + GradescopeResults.name(ofThisRow ? row.target() : row.page())
                        + "): " + note + "\n");
            }
        }
        notes.forEach(out::append);
        Set<String> told = new HashSet<>(); // a page of panels: its picture's command once, however many fail
        for (BatchRow row : rows) {
            String command = row.result() == BatchRow.Result.FAIL && row.counts() && !told.contains(row.file())
                    ? nextStep.apply(row) : null;
            if (command != null) {
                told.add(row.file());
                // what the command shows on a line of its own above it, so that all of the next: line after its
                // label pastes into a shell whole
                out.append("      ").append(row.file()).append(isPanel(row)
                        ? ": the pixel to look at first, in the panel that fails most, and how simpview made it:\n"
                        : ": the pixel to look at first, and how simpview made it:\n");
                out.append("next: ").append(command).append('\n');
            }
        }
        long skipped = rows.stream().filter(r -> r.result() == BatchRow.Result.SKIPPED).count();
        Map<String, String> notCounted = new LinkedHashMap<>(); // a first-assignment page: once, not per panel
        rows.stream().filter(r -> !r.counts())
                .forEach(r -> notCounted.putIfAbsent(r.file(), r.file() + ": not counted, " + r.notCounted() + "\n"));
        notCounted.values().forEach(out::append);
        // a file named like no page is said with why, so that the student can rename it
        rows.stream().filter(r -> r.result() == BatchRow.Result.SKIPPED)
                .forEach(r -> out.append(r.file()).append(": not checked, ").append(r.note()).append('\n'));
        for (Wanted wanted : missing) {
            String unreadable = wanted.whyMissing("");
            out.append("no picture of ").append(GradescopeResults.name(wanted.target()))
                    .append(unreadable.isEmpty() ? " found (name it like " + wanted.example() + ")" : " found: " + unreadable)
                    .append('\n');
        }
        List<BatchRow> counted = rows.stream()
                .filter(r -> r.counts() && r.result() != BatchRow.Result.SKIPPED).toList();
        // Every picture is counted whole, a page of the first assignment too (it passes when its four panels do),
        // and one that could not be checked is one that does not pass: so the tally is of what was handed in.
        // The first assignment's pages are also counted by their panels, which is how they are scored.
        Map<String, Boolean> passes = new LinkedHashMap<>();
        for (BatchRow row : counted) {
            passes.merge(row.file(), row.result() == BatchRow.Result.PASS, Boolean::logicalAnd);
        }
        long unchecked = counted.stream().filter(r -> !r.compared()).map(BatchRow::file).distinct().count();
        List<BatchRow> panels = counted.stream().filter(StudentTable::isPanel).toList();
        List<String> tallies = new ArrayList<>();
        // "1 of 1 pictures pass": a tally, in the plural whatever its count
        tallies.add(passes.values().stream().filter(p -> p).count() + " of " + passes.size() + " pictures pass");
        if (!panels.isEmpty()) {
            tallies.add(passing(panels) + " of " + panels.size() + " panels pass ("
                    + Count.of(panels.stream().map(BatchRow::file).distinct().count(), "page")
                    + " of the first assignment)");
        }
        if (unchecked > 0) {
            tallies.add(Count.of(unchecked, "picture") + " could not be checked (said above)");
        }
        out.append(String.format(Locale.ROOT, "%s%s%s%s%n", String.join("; ", tallies),
                notCounted.isEmpty() ? "" : "; " + Count.of(notCounted.size(), "picture") + " not counted",
                skipped == 0 ? "" : "; " + Count.of(skipped, "other file") + " not checked (each said above)",
                missing.isEmpty() ? "" : "; " + Count.of(missing.size(), "page") + " without a picture"));
        return out.toString();
    }

    /**
     * The panels of row r's picture whose hints look as row r's does (the same {@link PanelHint#brief}), row r's
     * first; the rows after it so found are added to {@code saidAlike}.
     */
    private static List<Integer> alike(List<BatchRow> rows, int r, Set<Integer> saidAlike) {
        BatchRow row = rows.get(r);
        List<Integer> panels = new ArrayList<>(List.of(row.panel()));
        for (int s = r + 1; s < rows.size(); s++) {
            BatchRow other = rows.get(s);
            PanelHint hint = other.panelHint();
            if (other.file().equals(row.file()) && other.panel() > 0 && hint != null && !hint.wholePage()
                    && hint.brief().equals(row.panelHint().brief())) {
                panels.add(other.panel());
                saidAlike.add(s);
            }
        }
        return panels;
    }

    /** The hint of panel k of the picture {@code file}, in words, or null. */
    private static String hintOfPanel(List<BatchRow> rows, String file, int k) {
        return rows.stream().filter(r -> r.file().equals(file) && r.panel() == k && r.panelHint() != null)
                .map(r -> r.panelHint().hint(r.size())).findFirst().orElse(null);
    }

    /** Whether a row is one panel of a page compared panel by panel (the first assignment's), not a whole picture. */
    private static boolean isPanel(BatchRow row) {
        return row.compared() && row.size() != Comparison.N;
    }

    private static long passing(List<BatchRow> rows) {
        return rows.stream().filter(r -> r.result() == BatchRow.Result.PASS).count();
    }

    private static String pad(String cell, int width, boolean right) {
        String spaces = " ".repeat(width - cell.length());
        return right ? spaces + cell : cell + spaces;
    }
}

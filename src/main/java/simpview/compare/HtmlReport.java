package simpview.compare;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Function;

/**
 * A batch as one web page, {@code index.html}, that a teacher opens from
 * disk: no network, no scripts or fonts from elsewhere (its style and its few
 * lines of script are in the page). A table of every submission and page
 * (sortable by any column: click its heading), and for every picture compared,
 * ours | theirs | heat map at 1:1 (the diff image, beside the page) with a
 * zoom, the heat map's legend, and the largest regions outlined on all three.
 * Rows are coloured by result, so a glance (or a screenshot) counts them.
 */
public final class HtmlReport {

    public static final String INDEX = "index.html";
    /** Row backgrounds by result: pass, fail, error, skipped, missing. */
    public static final int PASS_COLOUR = 0xD4EED4;
    public static final int FAIL_COLOUR = 0xF4CCCC;
    public static final int ERROR_COLOUR = 0xF8E0B0;
    public static final int SKIPPED_COLOUR = 0xE4E4E4;
    public static final int MISSING_COLOUR = 0xE0D4F0;
    /** The outline of a region over the pictures. */
    public static final int OUTLINE_COLOUR = 0x00E0FF;

    private HtmlReport() {
    }

    /**
     * Writes {@code htmlDir/index.html}. The diff images are those the rows name, under
     * {@code outDir} (they are linked from where they are, not copied).
     */
    public static void write(List<BatchRow> rows, List<Wanted> wanted, Path htmlDir, Path outDir) throws IOException {
        write(rows, wanted, htmlDir, outDir, JUnitResults::submission);
    }

    /**
     * The same with the submission of a file (its path in the folder) given: "" for every file of a folder that is
     * one student's however its pictures are foldered, shown as {@link JUnitResults#TOP}.
     */
    public static void write(List<BatchRow> rows, List<Wanted> wanted, Path htmlDir, Path outDir,
            Function<String, String> submissionOf) throws IOException {
        List<Map.Entry<String, Wanted>> missing = Wanted.missingBySubmission(wanted, rows, submissionOf);
        write(rows, missing, htmlDir, outDir, submissionOf, SubmissionTotals.of(rows, missing, submissionOf));
    }

    /**
     * The same with the pages each submission lacks ({@link Wanted#missingBySubmission}) and each submission's
     * total given: the batch's, whose submissions may be pictures of their own (one scene for every picture).
     */
    public static void write(List<BatchRow> rows, List<Map.Entry<String, Wanted>> missing, Path htmlDir, Path outDir,
            Function<String, String> submissionOf, List<SubmissionTotals.Total> totals) throws IOException {
        OutputFiles.writeString(htmlDir.resolve(INDEX), page(rows, missing, htmlDir, outDir, submissionOf, totals));
    }

    static String page(List<BatchRow> rows, List<Map.Entry<String, Wanted>> missing, Path htmlDir, Path outDir) {
        return page(rows, missing, htmlDir, outDir, JUnitResults::submission);
    }

    static String page(List<BatchRow> rows, List<Map.Entry<String, Wanted>> missing, Path htmlDir, Path outDir,
            Function<String, String> submissionOf) {
        return page(rows, missing, htmlDir, outDir, submissionOf, SubmissionTotals.of(rows, missing, submissionOf));
    }

    static String page(List<BatchRow> rows, List<Map.Entry<String, Wanted>> missing, Path htmlDir, Path outDir,
            Function<String, String> submissionOf, List<SubmissionTotals.Total> totals) {
        StringBuilder h = new StringBuilder();
        h.append("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n")
                .append("<title>simpview compare: ").append(esc(BatchTable.summary(rows, missing))).append("</title>\n")
                .append("<style>\n").append(STYLE).append("</style>\n</head>\n<body>\n");
        h.append("<h1>simpview compare</h1>\n<p id=\"summary\">").append(esc(BatchTable.summary(rows, missing)))
                .append("</p>\n");
        legend(h);
        table(h, rows, missing, submissionOf);
        h.append("<p class=\"hint\">Click a column's heading to sort by it (again: the other way); "
                + "index.html#sort=4-down opens it sorted by share, lowest last. "
                + "Shares are of the 650x650 panel's pixels, in percent.</p>\n");
        totals(h, totals);
        int index = 0;
        for (BatchRow row : rows) {
            if (row.compared()) {
                detail(h, row, index, htmlDir, outDir);
            }
            index++;
        }
        h.append("<script>\n").append(SCRIPT).append("</script>\n</body>\n</html>\n");
        return h.toString();
    }

    private static void legend(StringBuilder h) {
        h.append("<div id=\"legend\"><b>Heat map:</b> ");
        swatch(h, 0x303030, "identical (simpview's picture, dimmed)");
        swatch(h, HeatMap.WITHIN, "differs within the tolerance");
        swatch(h, HeatMap.SLACK_ONLY, "beyond it, but matches with slack (an edge one pixel off), or by FLIP");
        swatch(h, 0xE00000, "differs even with slack, or above FLIP's threshold (brighter: more)");
        swatch(h, OUTLINE_COLOUR, "outline: the largest regions that differ");
        h.append("</div>\n");
    }

    private static void swatch(StringBuilder h, int rgb, String what) {
        h.append(String.format(Locale.ROOT, "<span class=\"swatch\" style=\"background:#%06x\"></span>%s ", rgb, esc(what)));
    }

    private static void table(StringBuilder h, List<BatchRow> rows, List<Map.Entry<String, Wanted>> missing,
            Function<String, String> submissionOf) {
        h.append("<table id=\"results\">\n<thead><tr>");
        String[] headings = {"submission", "picture", "page", "result", "share", "identical", "failing pixels",
            "score", "details"};
        for (int c = 0; c < headings.length; c++) {
            h.append("<th data-col=\"").append(c).append("\">").append(headings[c]).append("</th>");
        }
        h.append("</tr></thead>\n<tbody>\n");
        int index = 0;
        for (BatchRow row : rows) {
            // one that does not count (another picture of its page does) is no failure here, as in the tallies
            String result = row.result().name() + (row.counts() ? "" : ", not counted");
            h.append("<tr class=\"row ").append(row.counts() ? result.toLowerCase(Locale.ROOT) : "notcounted")
                    .append("\">");
            String submission = submissionOf.apply(row.file());
            cell(h, submission.isEmpty() ? JUnitResults.TOP : submission, null);
            cell(h, row.file(), null);
            cell(h, row.target().isEmpty() ? "" : GradescopeResults.name(row.target()), null);
            cell(h, result, null);
            cell(h, row.compared() ? Percent.number(row.verdict()) : "", row.compared() ? row.verdict() : -1);
            cell(h, row.compared() ? Percent.number(row.exact().identical()) : "", row.compared() ? row.exact().identical() : -1);
            cell(h, row.compared() ? String.format(Locale.ROOT, "%,d", row.failing()) : "", row.compared() ? row.failing() : -1);
            cell(h, row.rule() == null ? ""
                    : GradescopeResults.points(row.score()) + " / " + GradescopeResults.points(row.rule().points()),
                    row.rule() == null ? -1 : row.score());
            if (row.compared()) {
                h.append("<td><a href=\"#p").append(index).append("\">show</a></td>");
            } else {
                cell(h, row.note().lines().findFirst().orElse(""), null);
            }
            h.append("</tr>\n");
            index++;
        }
        for (Map.Entry<String, Wanted> lack : missing) {
            Wanted wanted = lack.getValue();
            h.append("<tr class=\"row missing\">");
            cell(h, lack.getKey().isEmpty() ? JUnitResults.TOP : lack.getKey(), null);
            cell(h, "", null);
            cell(h, GradescopeResults.name(wanted.target()), null);
            cell(h, "MISSING", null);
            cell(h, "", -1.0);
            cell(h, "", -1.0);
            cell(h, "", -1.0);
            cell(h, "0 / " + GradescopeResults.points(wanted.rule().points()), 0.0);
            cell(h, BatchTable.missingNote(lack.getKey(), wanted), null);
            h.append("</tr>\n");
        }
        h.append("</tbody>\n</table>\n");
    }

    /**
     * Each submission's total ({@link SubmissionTotals}): what a gradebook is given, after the table of rows; nothing
     * when there is none.
     */
    private static void totals(StringBuilder h, List<SubmissionTotals.Total> totals) {
        if (totals.isEmpty()) {
            return;
        }
        h.append("<h2>Each submission's total</h2>\n<p class=\"hint\">The sum of its scores (each page counted once) "
                + "out of what its pages are worth, as results.json scores the submission graded alone.</p>\n")
                .append("<table id=\"totals\">\n<thead><tr>");
        for (String heading : SubmissionTotals.headings()) {
            h.append("<th>").append(esc(heading)).append("</th>");
        }
        h.append("</tr></thead>\n<tbody>\n");
        List<List<String>> lines = SubmissionTotals.cells(totals);
        for (int i = 0; i < totals.size(); i++) {
            SubmissionTotals.Total total = totals.get(i);
            List<String> cells = lines.get(i);
            Number[] values = {total.score(), total.maxScore(), total.passed(), total.failed(), total.errors(),
                total.missing()};
            h.append("<tr class=\"total\">");
            cell(h, cells.get(0), null);
            for (int c = 1; c < cells.size(); c++) {
                cell(h, cells.get(c), values[c - 1]);
            }
            h.append("</tr>\n");
        }
        h.append("</tbody>\n</table>\n");
    }

    private static void cell(StringBuilder h, String text, Number sortValue) {
        h.append("<td");
        if (sortValue != null) {
            h.append(" data-v=\"").append(sortValue).append('"');
        }
        h.append('>').append(esc(text)).append("</td>");
    }

    private static void detail(StringBuilder h, BatchRow row, int index, Path htmlDir, Path outDir) {
        h.append("<section class=\"detail\" id=\"p").append(index).append("\">\n<h2>")
                .append(esc(row.file())).append(" &mdash; ").append(esc(GradescopeResults.name(row.target())))
                .append(" &mdash; ").append(row.result().name()).append("</h2>\n<pre>")
                .append(esc(GradescopeResults.output(row))).append("</pre>\n");
        if (row.diff().isEmpty() || outDir == null) {
            h.append("<p>No diff image was written for it (see --diffs).</p>\n</section>\n");
            return;
        }
        // a URL relative to the page, not a file path: a name may hold '#', '?', '%' or spaces
        String src = UrlPath.of(htmlDir.toAbsolutePath().normalize()
                .relativize(outDir.resolve(row.diff()).toAbsolutePath().normalize()));
        h.append("<p class=\"zoom\">simpview's | theirs | heat map, zoom: ");
        for (int z : new int[] {1, 2, 4, 8}) {
            h.append("<button type=\"button\" data-zoom=\"").append(z).append("\">").append(z).append("x</button> ");
        }
        int n = row.size();
        h.append("</p>\n<div class=\"view\"><div class=\"diff\" style=\"width:").append(HeatMap.diffWidth(n))
                .append("px;height:").append(n).append("px\">");
        h.append("<img alt=\"simpview's, theirs and the heat map\" width=\"").append(HeatMap.diffWidth(n))
                .append("\" height=\"").append(n).append("\" src=\"").append(esc(src)).append("\">");
        for (DiffRegion region : row.regions()) {
            for (int panel = 0; panel < 3; panel++) {
                int left = panel * (n + HeatMap.GAP) + region.left();
                int top = n - 1 - region.top();
                h.append(String.format(Locale.ROOT, "<div class=\"region\" style=\"left:%dpx;top:%dpx;width:%dpx;height:%dpx\" "
                        + "title=\"%s\"></div>", left - 1, top - 1, region.right() - region.left() + 1,
                        region.top() - region.bottom() + 1, esc(region.describe())));
            }
        }
        h.append("</div></div>\n</section>\n");
    }

    static String esc(String text) {
        return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }

    private static final String STYLE = String.format(Locale.ROOT, """
            body { font-family: sans-serif; margin: 16px; background: #ffffff; color: #111111; }
            h1 { font-size: 20px; margin: 0 0 8px 0; }
            h2 { font-size: 16px; margin: 24px 0 4px 0; }
            #legend { margin: 8px 0; }
            .swatch { display: inline-block; width: 14px; height: 14px; margin: 0 4px 0 12px; vertical-align: middle;
                      border: 1px solid #000000; }
            table { border-collapse: separate; border-spacing: 0 3px; }
            th { text-align: left; padding: 4px 10px; background: #ffffff; cursor: pointer; user-select: none;
                 border-bottom: 2px solid #444444; }
            th.up::after { content: " \\25B2"; } th.down::after { content: " \\25BC"; }
            td { padding: 4px 10px; white-space: nowrap; }
            td[data-v] { text-align: right; }
            tr.pass td { background: #%06x; } tr.fail td { background: #%06x; } tr.error td { background: #%06x; }
            tr.skipped td, tr.notcounted td { background: #%06x; } tr.missing td { background: #%06x; }
            pre { background: #f4f4f4; padding: 6px; white-space: pre-wrap; overflow-wrap: anywhere; }
            .view { overflow: auto; max-width: 100%%; border: 1px solid #888888; }
            .diff { position: relative; transform-origin: 0 0; }
            .diff img { display: block; image-rendering: pixelated; }
            .region { position: absolute; box-sizing: content-box; border: 1px solid #%06x; pointer-events: auto; }
            .hint { color: #555555; font-size: 13px; }
            #totals th { cursor: default; } #totals td { border-bottom: 1px solid #dddddd; }
            """, PASS_COLOUR, FAIL_COLOUR, ERROR_COLOUR, SKIPPED_COLOUR, MISSING_COLOUR, OUTLINE_COLOUR);

    private static final String SCRIPT = """
            (function () {
              var table = document.getElementById('results');
              var heads = table.tHead.rows[0].cells;
              function value(row, col) {
                var cell = row.cells[col];
                return cell.hasAttribute('data-v') ? parseFloat(cell.getAttribute('data-v')) : cell.textContent;
              }
              function sort(col, up) {
                for (var k = 0; k < heads.length; k++) { heads[k].classList.remove('up', 'down'); }
                heads[col].classList.add(up ? 'up' : 'down');
                var body = table.tBodies[0], rows = Array.prototype.slice.call(body.rows);
                rows.sort(function (a, b) {
                  var x = value(a, col), y = value(b, col);
                  var d = typeof x === 'number' && typeof y === 'number' ? x - y : String(x).localeCompare(String(y), undefined, {numeric: true});
                  return up ? d : -d;
                });
                rows.forEach(function (r) { body.appendChild(r); });
              }
              for (var c = 0; c < heads.length; c++) {
                heads[c].addEventListener('click', function (e) {
                  var th = e.currentTarget;
                  sort(+th.getAttribute('data-col'), !th.classList.contains('up'));
                });
              }
              // index.html#sort=4-down opens sorted: by column 4 (share), largest first.
              var asked = /sort=(\\d+)-(up|down)/.exec(location.hash);
              if (asked && +asked[1] < heads.length) { sort(+asked[1], asked[2] === 'up'); }
              var buttons = document.querySelectorAll('button[data-zoom]');
              for (var b = 0; b < buttons.length; b++) {
                buttons[b].addEventListener('click', function (e) {
                  var z = +e.currentTarget.getAttribute('data-zoom');
                  var diff = e.currentTarget.parentNode.nextElementSibling.firstChild;
                  diff.style.transform = 'scale(' + z + ')';
                  // Its own picture's height (650 px for a page, 300 for a first-assignment panel): offsetHeight
                  // is the unscaled one. The scale does not grow the view, so the view is told its new height.
                  diff.parentNode.style.height = (diff.offsetHeight * z + 2) + 'px';
                  diff.parentNode.scrollLeft = 0;
                });
              }
            })();
            """;
}

package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The reports' links to the diff images, for pictures (and folders) whose names hold characters a URL gives a
 * meaning to: each link, read back as a browser reads it (HTML attribute unescaped, then resolved as a URL
 * against the page and percent-decoded), is the diff image's file on disk.
 */
class ReportLinksTest {

    /** '#' starts a fragment, '?' a query, '%' an escape; a space and ')' end a Markdown link; é is not ASCII. */
    private static final List<String> NAMES = List.of("alice/page1 #2.png", "bob & co/page2?.png", "é/pagé3 100%.png",
            "dan/page4 (final).png", "eve/50%25 #x.png");

    @TempDir
    Path dir;

    private List<BatchRow> rows(Path outDir) throws Exception {
        int[] stripes = GradingFixtures.stripes(0);
        List<BatchRow> rows = new ArrayList<>();
        for (String name : NAMES) {
            rows.add(GradingFixtures.row(name, "1", stripes, GradingFixtures.spoiled(stripes, 100), GradingFixtures.defaults(),
                    false, outDir));
        }
        return rows;
    }

    @Test
    void theWebReportsImageSourcesAreTheDiffImages() throws Exception {
        // The report in a folder of its own, beside an out folder whose name needs encoding too.
        Path outDir = dir.resolve("out #1 é");
        Path htmlDir = dir.resolve("web");
        List<BatchRow> rows = rows(outDir);
        HtmlReport.write(rows, List.of(), htmlDir, outDir);
        String html = Files.readString(htmlDir.resolve(HtmlReport.INDEX));

        List<String> sources = attributes(html, "src");
        assertEquals(NAMES.size(), sources.size(), "one image per picture: " + sources);
        for (int i = 0; i < rows.size(); i++) {
            Path file = outDir.resolve(rows.get(i).diff());
            assertTrue(Files.isRegularFile(file), file.toString());
            assertEquals(file.toRealPath(), opened(htmlDir.resolve(HtmlReport.INDEX), sources.get(i)).toRealPath(),
                    "src=\"" + sources.get(i) + "\"");
        }
        for (String href : attributes(html, "href")) {
            assertTrue(href.matches("#p[0-9]+"), "the other links are to the page's own views: " + href);
        }
    }

    @Test
    void theMarkdownTablesLinksAreTheDiffImages() throws Exception {
        Path outDir = dir.resolve("report");
        List<BatchRow> rows = rows(outDir);
        String table = BatchTable.markdown(rows, 8, 99);
        Matcher link = Pattern.compile("\\[diff\\]\\(([^)\\s]*)\\)").matcher(table);
        List<String> targets = new ArrayList<>();
        while (link.find()) {
            targets.add(link.group(1));
        }
        assertEquals(NAMES.size(), targets.size(), "a whole link (no space or ')' inside it) per picture:\n" + table);
        for (int i = 0; i < rows.size(); i++) {
            // the table is written in the out folder, as compare.md
            assertEquals(outDir.resolve(rows.get(i).diff()).toRealPath(),
                    opened(outDir.resolve("compare.md"), targets.get(i)).toRealPath(), "(" + targets.get(i) + ")");
        }
    }

    @Test
    void eachSegmentIsEncodedAndTheSlashesKept() {
        assertEquals("diffs/alice_page1%20%232-diff.png", UrlPath.of("diffs/alice_page1 #2-diff.png"));
        assertEquals("%C3%A9%3F%25%26%28%29%3A%2B", UrlPath.segment("é?%&():+"));
        assertEquals("a%5Cb.png", UrlPath.of(Path.of("a\\b.png")), "a Linux name may hold a backslash");
        assertEquals("../a%20b/c.png", UrlPath.of(Path.of("..", "a b", "c.png")));
    }

    /** The file a browser opens for {@code url} on the page {@code page}: the URL resolved against it, decoded. */
    private static Path opened(Path page, String url) throws Exception {
        URI relative = new URI(url); // a space or a lone '%' would be refused here
        assertNull(relative.getRawFragment(), "no fragment: " + url);
        assertNull(relative.getRawQuery(), "no query: " + url);
        return Path.of(page.toUri().resolve(relative));
    }

    /** Every value of the attribute in the page, HTML-unescaped. */
    private static List<String> attributes(String html, String name) {
        List<String> values = new ArrayList<>();
        Matcher m = Pattern.compile(" " + name + "=\"([^\"]*)\"").matcher(html);
        while (m.find()) {
            values.add(m.group(1).replace("&quot;", "\"").replace("&lt;", "<").replace("&gt;", ">")
                    .replace("&#39;", "'").replace("&amp;", "&"));
        }
        return values;
    }
}

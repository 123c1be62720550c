package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.image.BufferedImage;
import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The web report in a real browser: headless Chromium opens index.html from
 * disk, and its screenshot must show the table (one band of the result's
 * colour per row, in order) and the pictures (the grey gaps of the diff
 * image); its DOM, after the page's script ran, must hold one row per
 * picture and missing page, and sort when asked; a diff image whose name
 * holds '#' loads, and each view's zoom fits its own picture (a page's or a
 * first-assignment panel's). Without Chromium the test
 * is skipped, saying so; under CI=true that absence fails it.
 */
class HtmlReportBrowserTest {

    private static final int WIDTH = 1400;
    private static final int HEIGHT = 1600;

    @TempDir
    static Path dir;

    private static Path chromium;
    private static Path report;

    @BeforeAll
    static void writeReport() throws Exception {
        chromium = findChromium().orElse(null);
        if (chromium == null) {
            String why = "chromium is not installed (.ci/setup installs it): the web report is not opened in a browser";
            if ("true".equals(System.getenv("CI"))) {
                fail(why + ", and CI=true");
            }
            Assumptions.assumeTrue(false, why);
        }
        int[] stripes = GradingFixtures.stripes(0);
        RubricRule rule = GradingFixtures.defaults();
        report = dir.resolve("report");
        List<BatchRow> rows = List.of(
                GradingFixtures.row("alice/page1.png", "1", stripes, stripes, rule, false, report),
                GradingFixtures.row("alice/page2.png", "2", stripes, GradingFixtures.spoiled(stripes, 30_000), rule, false, report),
                BatchRow.broken("bob/page1.png", "1", "bob/page1.png: cannot be read as a picture", rule));
        HtmlReport.write(rows, List.of(new Wanted("1", rule), new Wanted("2", rule), new Wanted("3", rule)), report, report);
    }

    private static Optional<Path> findChromium() {
        for (String folder : System.getenv().getOrDefault("PATH", "").split(File.pathSeparator)) {
            for (String name : List.of("chromium", "chromium-browser", "google-chrome")) {
                Path candidate = Path.of(folder, name);
                if (Files.isExecutable(candidate)) {
                    return Optional.of(candidate);
                }
            }
        }
        return Optional.empty();
    }

    /** Runs headless Chromium on the report with the given arguments; returns what it printed on stdout. */
    private static String chromium(String fragment, String... args) throws Exception {
        return chromium(report.resolve(HtmlReport.INDEX), fragment, args);
    }

    /** The same on another page. */
    private static String chromium(Path page, String fragment, String... args) throws Exception {
        List<String> command = new ArrayList<>(List.of(chromium.toString(), "--headless", "--no-sandbox", "--disable-gpu",
                "--hide-scrollbars", "--force-device-scale-factor=1", "--no-first-run", "--disable-extensions",
                "--user-data-dir=" + Files.createTempDirectory(dir, "profile"), "--window-size=" + WIDTH + "," + HEIGHT));
        command.addAll(List.of(args));
        command.add(page.toUri() + fragment);
        Path stdout = Files.createTempFile(dir, "stdout", ".txt");
        ProcessBuilder builder = new ProcessBuilder(command).redirectOutput(stdout.toFile())
                .redirectError(ProcessBuilder.Redirect.DISCARD);
        // Chromium keeps its crash reporter's settings and its caches under these, not under --user-data-dir:
        // pointed into the test's folder, a run leaves nothing in the user's home.
        builder.environment().put("XDG_CONFIG_HOME", Files.createTempDirectory(dir, "config").toString());
        builder.environment().put("XDG_CACHE_HOME", Files.createTempDirectory(dir, "cache").toString());
        Process process = builder.start();
        if (!process.waitFor(90, TimeUnit.SECONDS)) {
            process.destroyForcibly();
            fail("chromium did not finish within 90 s: " + command);
        }
        assertEquals(0, process.exitValue(), "chromium's exit code: " + command);
        return Files.readString(stdout, StandardCharsets.UTF_8);
    }

    @Test
    void theScreenshotShowsOneBandPerRowAndThePictures() throws Exception {
        Path shot = dir.resolve("shot.png");
        chromium("", "--screenshot=" + shot);
        BufferedImage image = ImageIO.read(shot.toFile());
        assertEquals(WIDTH, image.getWidth());

        Set<Integer> colours = new HashSet<>();
        for (int y = 0; y < image.getHeight(); y += 3) {
            for (int x = 0; x < image.getWidth(); x += 3) {
                colours.add(image.getRGB(x, y) & 0xFFFFFF);
            }
        }
        assertTrue(colours.size() > 20, "not blank: " + colours.size() + " colours");

        // Down a column through the first cells' left padding (the body has 16 px of margin, a cell 10 px of
        // padding, so x = 20 meets no text): the row bands, each a run of its result's colour.
        List<Integer> bands = new ArrayList<>();
        int previous = -1;
        for (int y = 0; y < image.getHeight(); y++) {
            int rgb = image.getRGB(20, y) & 0xFFFFFF;
            boolean rowColour = rgb == HtmlReport.PASS_COLOUR || rgb == HtmlReport.FAIL_COLOUR
                    || rgb == HtmlReport.ERROR_COLOUR || rgb == HtmlReport.MISSING_COLOUR || rgb == HtmlReport.SKIPPED_COLOUR;
            if (rowColour && rgb != previous) {
                bands.add(rgb);
            }
            previous = rowColour ? rgb : -1;
        }
        // alice lacks page 3; bob (whose page 1 is broken) lacks pages 2 and 3.
        assertEquals(List.of(HtmlReport.PASS_COLOUR, HtmlReport.FAIL_COLOUR, HtmlReport.ERROR_COLOUR, HtmlReport.MISSING_COLOUR,
                HtmlReport.MISSING_COLOUR, HtmlReport.MISSING_COLOUR), bands, "one band per row, in the table's order: " + hex(bands));

        // The diff image of the first picture: its grey gaps between the three panels, 10 px wide, in one column.
        assertTrue(longestRun(image, HeatMap.GAP_COLOUR) >= 200, "the diff image is shown: a grey gap "
                + longestRun(image, HeatMap.GAP_COLOUR) + " px tall");
    }

    @Test
    void theDomHoldsEveryRowAndSortsWhenAsked() throws Exception {
        // Opened sorted by share (column 4), lowest first: the page's script ran and reordered the rows,
        // which it writes in the batch's order (pass, fail, error, then the missing pages).
        String dom = chromium("#sort=4-up", "--dump-dom");
        assertEquals(6, count(dom, "<tr class=\"row "), "three pictures, alice's page 3 and bob's pages 2 and 3");
        assertEquals(2, count(dom, "<section class=\"detail\""), "a view for each picture compared");
        assertEquals(3, count(dom, "class=\"region\""), "page 2's one region, outlined on its three panels");
        assertFalse(dom.contains("http://") || dom.contains("https://"), "nothing from the network");
        List<String> order = new ArrayList<>();
        Matcher m = Pattern.compile("<tr class=\"row (\\w+)\">").matcher(dom);
        while (m.find()) {
            order.add(m.group(1));
        }
        assertEquals(List.of("error", "missing", "missing", "missing", "fail", "pass"), order,
                "no share first (a stable sort keeps their order), then 92.9 %, then 100 %");
        assertTrue(dom.contains("<th data-col=\"4\" class=\"up\">"), "the heading shows the sort");
    }

    @Test
    void anImageWhoseNameHoldsAHashLoads() throws Exception {
        // Unencoded, "diffs/carol_page1 #2 é%-diff.png" is the file "diffs/carol_page1 " and a fragment: no picture.
        Path hashed = dir.resolve("hashed #1");
        int[] stripes = GradingFixtures.stripes(0);
        BatchRow row = GradingFixtures.row("carol/page1 #2 é%.png", "1", stripes, stripes, GradingFixtures.defaults(),
                false, hashed);
        HtmlReport.write(List.of(row), List.of(), hashed, hashed);
        Path shot = dir.resolve("hashed.png");
        chromium(hashed.resolve(HtmlReport.INDEX), "", "--screenshot=" + shot);
        BufferedImage image = ImageIO.read(shot.toFile());
        assertTrue(longestRun(image, HeatMap.GAP_COLOUR) >= 200, "the diff image " + row.diff() + " is shown: a grey gap "
                + longestRun(image, HeatMap.GAP_COLOUR) + " px tall");
    }

    @Test
    void eachViewZoomsToItsOwnPicturesHeight() throws Exception {
        // A page's view (650 px tall) and a first-assignment panel's (300 px): each 2x zoom's view must be as tall
        // as its own picture at 2x (with the view's 2 px), not as a page's.
        Path zoomed = dir.resolve("zoomed");
        RubricRule rule = GradingFixtures.defaults();
        int[] stripes = GradingFixtures.stripes(0);
        int side = 300;
        int[] panel = new int[side * side];
        for (int i = 0; i < panel.length; i++) {
            panel[i] = i % side % 4 == 0 ? 0xFFFFFF : 0;
        }
        Comparison small = Comparison.of(panel, panel, side, 0, Comparison.Metric.EXACT, Comparison.FLIP_THRESHOLD);
        Files.createDirectories(zoomed.resolve("diffs"));
        Files.write(zoomed.resolve("diffs/a1-panel1-diff.png"), HeatMap.diffPng(small, 8));
        List<BatchRow> rows = List.of(GradingFixtures.row("alice/page1.png", "1", stripes, stripes, rule, false, zoomed),
                BatchRow.panel("alice/a1-page1.png", "A1 page 1 panel 1 (DDA)", small, rule, 1, "diffs/a1-panel1-diff.png",
                        "panel 1", null));
        HtmlReport.write(rows, List.of(), zoomed, zoomed);
        // The report's own script, then one that presses each view's 2x button and writes down what it did.
        Path page = zoomed.resolve("zoom.html");
        Files.writeString(page, Files.readString(zoomed.resolve(HtmlReport.INDEX)).replace("</body>", """
                <script>
                var found = [];
                document.querySelectorAll('section.detail').forEach(function (view) {
                  view.querySelector('button[data-zoom="2"]').click();
                  var box = view.querySelector('.view');
                  found.push(box.querySelector('img').getAttribute('height') + ' '
                      + Math.round(box.firstChild.getBoundingClientRect().height) + ' ' + box.style.height);
                });
                var out = document.createElement('pre');
                out.id = 'zoomed';
                out.textContent = found.join(';');
                document.body.appendChild(out);
                </script>
                </body>"""));
        Matcher found = Pattern.compile("<pre id=\"zoomed\">([^<]*)</pre>").matcher(chromium(page, "", "--dump-dom"));
        assertTrue(found.find(), "the measuring script ran");
        // picture height, its height on screen at 2x, the view's height
        assertEquals("650 1300 1302px;300 600 602px", found.group(1));
    }

    private static int count(String text, String what) {
        int n = 0;
        for (int at = text.indexOf(what); at >= 0; at = text.indexOf(what, at + 1)) {
            n++;
        }
        return n;
    }

    private static int longestRun(BufferedImage image, int rgb) {
        int best = 0;
        for (int x = 0; x < image.getWidth(); x++) {
            int run = 0;
            for (int y = 0; y < image.getHeight(); y++) {
                run = (image.getRGB(x, y) & 0xFFFFFF) == rgb ? run + 1 : 0;
                best = Math.max(best, run);
            }
        }
        return best;
    }

    private static String hex(List<Integer> colours) {
        return colours.stream().map(c -> String.format("#%06x", c)).toList().toString();
    }
}

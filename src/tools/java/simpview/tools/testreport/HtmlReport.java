package simpview.tools.testreport;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

/** index.html: the counts, every failure with its trace, every skip with its reason, then each class. */
public final class HtmlReport {

    private HtmlReport() {
    }

    public static Path write(TestResults results, Path folder) throws IOException {
        Files.createDirectories(folder);
        StringBuilder html = new StringBuilder(8192);
        html.append("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>simpview tests</title>\n")
                .append("<style>body{font-family:sans-serif;margin:2em}td,th{padding:2px 8px;text-align:left}")
                .append(".FAILED{color:#b00}.SKIPPED{color:#a60}pre{background:#f4f4f4;padding:8px;overflow:auto}")
                .append("</style></head><body>\n<h1>simpview tests</h1>\n<p>")
                .append(escape(TestSummary.countsLine(results))).append("</p>\n");
        section(html, results, TestCase.Outcome.FAILED, "Failed");
        section(html, results, TestCase.Outcome.SKIPPED, "Skipped");
        classes(html, results);
        html.append("</body></html>\n");
        Path index = folder.resolve("index.html");
        Files.writeString(index, html, StandardCharsets.UTF_8);
        return index;
    }

    private static void section(StringBuilder html, TestResults results, TestCase.Outcome outcome, String heading) {
        if (results.count(outcome) == 0) {
            return;
        }
        html.append("<h2 class=\"").append(outcome).append("\">").append(heading).append("</h2>\n");
        for (TestCase c : results.with(outcome)) {
            html.append("<h3>").append(escape(c.title())).append("</h3>\n<p>").append(escape(c.message()))
                    .append("</p>\n");
            if (!c.detail().isEmpty()) {
                html.append("<pre>").append(escape(c.detail())).append("</pre>\n");
            }
        }
    }

    private static void classes(StringBuilder html, TestResults results) {
        Map<String, int[]> byClass = new TreeMap<>();
        Map<String, Double> seconds = new TreeMap<>();
        for (TestCase c : results.cases()) {
            byClass.computeIfAbsent(c.className(), k -> new int[3])[c.outcome().ordinal()]++;
            seconds.merge(c.className(), c.seconds(), Double::sum);
        }
        html.append("<h2>Classes</h2>\n<table>\n<tr><th>class</th><th>passed</th><th>failed</th>")
                .append("<th>skipped</th><th>seconds</th></tr>\n");
        byClass.forEach((name, counts) -> html.append("<tr><td>").append(escape(name)).append("</td><td>")
                .append(counts[0]).append("</td><td>").append(counts[1]).append("</td><td>").append(counts[2])
                .append("</td><td>").append(String.format(Locale.ROOT, "%.3f", seconds.get(name)))
                .append("</td></tr>\n"));
        html.append("</table>\n");
    }

    static String escape(String text) {
        StringBuilder out = new StringBuilder(text.length());
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            switch (c) {
                case '<' -> out.append("&lt;");
                case '>' -> out.append("&gt;");
                case '&' -> out.append("&amp;");
                case '"' -> out.append("&quot;");
                default -> out.append(c);
            }
        }
        return out.toString();
    }
}

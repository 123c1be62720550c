package simpview.compare;

import java.io.StringWriter;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Function;
import javax.xml.stream.XMLOutputFactory;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamWriter;

/**
 * A batch as JUnit XML, which CI systems and GitHub Classroom's runners read:
 * {@code <testsuites>} holding one {@code <testsuite>} per submission (the
 * first folder of the pictures' paths, "submission" for pictures at the top), one
 * {@code <testcase>} per picture, named by its page, with {@code classname}
 * the submission. A picture below the minimum has a {@code <failure>} whose
 * message is the shares; one that passes, a {@code <system-out>} with its feedback when it has a hint or a note;
 * one that cannot be compared an {@code <error>}; one
 * that matches no page, or that does not count (another picture of its page
 * in the submission does, {@link OnePerPage}), is {@code <skipped>}; a page
 * asked for but not found is a failure too. Written with the JDK's XML writer, so every name and text is
 * escaped as XML wants.
 */
public final class JUnitResults {

    /** The submission of pictures at the top of the folder (one student's folder). */
    public static final String TOP = "submission";

    private JUnitResults() {
    }

    /** {@code wanted}: every page or scene asked for; each submission lacking one gets a failing test for it. */
    public static String xml(List<BatchRow> rows, List<Wanted> wanted, double seconds) {
        return xml(rows, wanted, seconds, JUnitResults::submission);
    }

    /**
     * The same with the submission of a file (its path in the folder) given: "" for every file of a folder that is
     * one student's however its pictures are foldered, which is then the one suite {@link #TOP}.
     */
    public static String xml(List<BatchRow> rows, List<Wanted> wanted, double seconds,
            Function<String, String> submissionOf) {
        Map<String, List<BatchRow>> suites = new LinkedHashMap<>();
        for (BatchRow row : rows) {
            suites.computeIfAbsent(submissionOf.apply(row.file()), k -> new ArrayList<>()).add(row);
        }
        // a submission that handed in only files simpview does not read lacks every page
        wanted.forEach(w -> w.unreadable()
                .forEach(file -> suites.computeIfAbsent(submissionOf.apply(file), k -> new ArrayList<>())));
        // so does a first-level folder holding no picture (her pages zipped)
        Wanted.foldersWithoutPictures(wanted).forEach(folder -> suites.computeIfAbsent(folder, k -> new ArrayList<>()));
        if (suites.isEmpty() && !wanted.isEmpty()) {
            suites.put(TOP, new ArrayList<>());
        }
        StringWriter text = new StringWriter();
        try {
            XMLStreamWriter xml = XMLOutputFactory.newFactory().createXMLStreamWriter(text);
            xml.writeStartDocument("UTF-8", "1.0");
            xml.writeCharacters("\n");
            xml.writeStartElement("testsuites");
            xml.writeAttribute("name", "simpview compare");
            int failures = 0;
            int errors = 0;
            int skipped = 0;
            for (BatchRow row : rows) {
                failures += shown(row) == BatchRow.Result.FAIL ? 1 : 0;
                errors += shown(row) == BatchRow.Result.ERROR ? 1 : 0;
                skipped += shown(row) == BatchRow.Result.SKIPPED ? 1 : 0;
            }
            Map<String, List<Wanted>> notFound = new LinkedHashMap<>();
            suites.forEach((submission, its) -> notFound.put(submission,
                    Wanted.asked(submission, its, suites.size(), wanted) ? Wanted.missing(wanted, its) : List.of()));
            int missingCount = 0;
            for (List<Wanted> lacks : notFound.values()) {
                missingCount += lacks.size();
            }
            xml.writeAttribute("tests", String.valueOf(rows.size() + missingCount));
            xml.writeAttribute("failures", String.valueOf(failures + missingCount));
            xml.writeAttribute("errors", String.valueOf(errors));
            xml.writeAttribute("skipped", String.valueOf(skipped));
            xml.writeAttribute("time", String.format(Locale.ROOT, "%.3f", seconds));
            int id = 0;
            for (Map.Entry<String, List<BatchRow>> suite : suites.entrySet()) {
                writeSuite(xml, id++, suite.getKey(), suite.getValue(), notFound.get(suite.getKey()));
            }
            xml.writeCharacters("\n");
            xml.writeEndElement();
            xml.writeCharacters("\n");
            xml.writeEndDocument();
            xml.close();
        } catch (XMLStreamException e) {
            throw new IllegalStateException("writing JUnit XML to a string failed", e);
        }
        return legal(text.toString());
    }

    /**
     * The text with every character XML 1.0 does not allow, escaped or not (a control character in a file name:
     * "page1\u0001.png"), made U+FFFD: the JDK's writer escapes markup but passes those through, and one such name
     * made the whole class's file unreadable to every XML reader. The writer makes no such character itself.
     */
    static String legal(String text) {
        StringBuilder out = new StringBuilder(text.length());
        text.codePoints().forEach(c -> {
            boolean allowed = c == 0x9 || c == 0xA || c == 0xD || c >= 0x20 && c <= 0xD7FF
                    || c >= 0xE000 && c <= 0xFFFD || c >= 0x10000 && c <= 0x10FFFF;
            out.appendCodePoint(allowed ? c : 0xFFFD);
        });
        return out.toString();
    }

    private static void writeSuite(XMLStreamWriter xml, int id, String submission, List<BatchRow> rows,
            List<Wanted> notFound) throws XMLStreamException {
        String name = submission.isEmpty() ? TOP : submission; // the whole folder: one student's
        xml.writeCharacters("\n  ");
        xml.writeStartElement("testsuite");
        xml.writeAttribute("name", name);
        xml.writeAttribute("id", String.valueOf(id));
        xml.writeAttribute("tests", String.valueOf(rows.size() + notFound.size()));
        xml.writeAttribute("failures", String.valueOf(rows.stream().filter(r -> shown(r) == BatchRow.Result.FAIL).count()
                + notFound.size()));
        xml.writeAttribute("errors", String.valueOf(rows.stream().filter(r -> shown(r) == BatchRow.Result.ERROR).count()));
        xml.writeAttribute("skipped", String.valueOf(rows.stream().filter(r -> shown(r) == BatchRow.Result.SKIPPED).count()));
        for (BatchRow row : rows) {
            xml.writeCharacters("\n    ");
            xml.writeStartElement("testcase");
            xml.writeAttribute("name", row.target().isEmpty() ? row.file()
                    : GradescopeResults.name(row.target()) + " (" + row.file() + ")");
            xml.writeAttribute("classname", name);
            switch (shown(row)) {
                case PASS -> {
                    if (worthTelling(row)) {
                        xml.writeStartElement("system-out");
                        xml.writeCharacters(GradescopeResults.output(row));
                        xml.writeEndElement();
                    }
                }
                case FAIL -> element(xml, "failure", shares(row), "below the minimum", GradescopeResults.output(row));
                case ERROR -> element(xml, "error", row.note().lines().findFirst().orElse(""), "not compared", row.note());
                case SKIPPED -> {
                    xml.writeStartElement("skipped");
                    xml.writeAttribute("message", row.counts() ? row.note() : "not counted: " + row.notCounted());
                    xml.writeEndElement();
                }
            }
            xml.writeEndElement();
        }
        for (Wanted wanted : notFound) {
            xml.writeCharacters("\n    ");
            xml.writeStartElement("testcase");
            xml.writeAttribute("name", GradescopeResults.name(wanted.target()) + " (no picture)");
            xml.writeAttribute("classname", name);
            String unreadable = wanted.whyMissing(submission);
            element(xml, "failure", "no picture of " + GradescopeResults.name(wanted.target()) + " found"
                    + (unreadable.isEmpty() ? "" : "; " + unreadable), "missing",
                    "No picture's name names " + GradescopeResults.name(wanted.target()) + "."
                            + (unreadable.isEmpty() ? "" : " " + Sentence.ended(unreadable)));
            xml.writeEndElement();
        }
        xml.writeCharacters("\n  ");
        xml.writeEndElement();
    }

    private static void element(XMLStreamWriter xml, String tag, String message, String type, String body)
            throws XMLStreamException {
        xml.writeStartElement(tag);
        xml.writeAttribute("message", message);
        xml.writeAttribute("type", type);
        xml.writeCharacters(body);
        xml.writeEndElement();
    }

    /**
     * Whether a picture that passes has something to be told all the same, which its testcase's
     * {@code <system-out>} says (the feedback a runner shows): a hint of what its whole panel looks like, a note
     * ({@link BatchRow#notes}), or the accepted alternate it matched.
     */
    private static boolean worthTelling(BatchRow row) {
        return row.panelHint() != null || !row.notes().isEmpty() || !row.alternate().isEmpty();
    }

    /** A row's result as a testcase shows it: one that does not count is skipped, whatever it came to. */
    private static BatchRow.Result shown(BatchRow row) {
        return row.counts() ? row.result() : BatchRow.Result.SKIPPED;
    }

    /** E.g. "92.90 % within 8/255 with 1 px slack, 99.00 % needed". */
    private static String shares(BatchRow row) {
        return String.format(Locale.ROOT, "%s %s, %s needed%s", Percent.of(row.verdict()),
                row.verdictName(), Percent.of(row.rule().minShare() / 100),
                row.rule().maxFailing() >= 0 ? "; " + Count.with(row.failing(), "pixel", "fails", "fail")
                        + String.format(Locale.ROOT, ", at most %,d allowed", row.rule().maxFailing()) : "");
    }

    /** The submission a picture belongs to: the first folder of its path, or "." at the top. */
    public static String submission(String file) {
        String path = file.replace('\\', '/');
        int slash = path.indexOf('/');
        String folder = slash < 0 ? "" : path.substring(0, slash);
        // a Windows zip's name leading out of the folder (..\page1.png) or from a drive (C:\page1.png): no folder
        boolean outside = folder.isEmpty() || folder.equals(".") || folder.equals("..") || folder.matches("[A-Za-z]:");
        return outside ? TOP : folder;
    }
}

package simpview.tools.testreport;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.xml.parsers.DocumentBuilder;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.parsers.ParserConfigurationException;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;
import org.xml.sax.SAXException;

/** The tests of every JUnit XML report (TEST-*.xml) in one folder. */
public final class TestResults {

    private final List<TestCase> cases;

    private TestResults(List<TestCase> cases) {
        this.cases = List.copyOf(cases);
    }

    public static TestResults read(Path folder) throws IOException {
        List<TestCase> cases = new ArrayList<>();
        if (Files.isDirectory(folder)) {
            try (DirectoryStream<Path> files = Files.newDirectoryStream(folder, "TEST-*.xml")) {
                for (Path file : files) {
                    readFile(file, cases);
                }
            }
        }
        return new TestResults(cases);
    }

    public List<TestCase> cases() {
        return cases;
    }

    public List<TestCase> with(TestCase.Outcome outcome) {
        return cases.stream().filter(c -> c.outcome() == outcome).toList();
    }

    public int count(TestCase.Outcome outcome) {
        return with(outcome).size();
    }

    private static void readFile(Path file, List<TestCase> cases) throws IOException {
        Document document;
        try {
            DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
            factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            DocumentBuilder builder = factory.newDocumentBuilder();
            document = builder.parse(file.toFile());
        } catch (ParserConfigurationException | SAXException e) {
            throw new IOException(file + ": not a JUnit XML report: " + e.getMessage(), e);
        }
        NodeList testcases = document.getElementsByTagName("testcase");
        for (int i = 0; i < testcases.getLength(); i++) {
            cases.add(testCase((Element) testcases.item(i)));
        }
    }

    private static TestCase testCase(Element e) {
        double seconds = parseSeconds(e.getAttribute("time"));
        Element problem = first(e, "failure");
        if (problem == null) {
            problem = first(e, "error");
        }
        if (problem != null) {
            return new TestCase(e.getAttribute("classname"), e.getAttribute("name"), seconds,
                    TestCase.Outcome.FAILED, problem.getAttribute("message"), problem.getTextContent().strip());
        }
        Element skipped = first(e, "skipped");
        if (skipped != null) {
            String message = skipped.getAttribute("message");
            return new TestCase(e.getAttribute("classname"), e.getAttribute("name"), seconds,
                    TestCase.Outcome.SKIPPED, message.isEmpty() ? skipped.getTextContent().strip() : message, "");
        }
        return new TestCase(e.getAttribute("classname"), e.getAttribute("name"), seconds,
                TestCase.Outcome.PASSED, "", "");
    }

    private static Element first(Element parent, String tag) {
        NodeList found = parent.getElementsByTagName(tag);
        return found.getLength() == 0 ? null : (Element) found.item(0);
    }

    private static double parseSeconds(String text) {
        try {
            return text.isEmpty() ? 0 : Double.parseDouble(text.replace(",", ""));
        } catch (NumberFormatException e) {
            return 0;
        }
    }
}

package simpview.tools.testreport;

/**
 * One test as a JUnit XML report records it.
 *
 * @param className the class (or container) that holds it
 * @param name its display name
 * @param seconds how long it ran
 * @param outcome passed, failed or skipped
 * @param message the failure's or skip's message ("" when none)
 * @param detail the failure's stack trace ("" when none)
 */
public record TestCase(String className, String name, double seconds, Outcome outcome, String message,
        String detail) {

    /** What became of a test. */
    public enum Outcome { PASSED, FAILED, SKIPPED }

    /** "Class > name", as the summary lists it. */
    public String title() {
        return className + " > " + name;
    }
}

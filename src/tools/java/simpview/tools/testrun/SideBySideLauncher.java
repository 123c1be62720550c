package simpview.tools.testrun;

import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.ServiceLoader;
import java.util.Set;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.platform.engine.TestEngine;
import org.junit.platform.engine.discovery.ClassNameFilter;
import org.junit.platform.engine.discovery.DiscoverySelectors;
import org.junit.platform.launcher.EngineFilter;
import org.junit.platform.launcher.Launcher;
import org.junit.platform.launcher.LauncherDiscoveryRequest;
import org.junit.platform.launcher.core.LauncherDiscoveryRequestBuilder;
import org.junit.platform.launcher.core.LauncherFactory;
import org.junit.platform.launcher.listeners.SummaryGeneratingListener;
import org.junit.platform.launcher.listeners.TestExecutionSummary;
import org.junit.platform.reporting.legacy.xml.LegacyXmlReportGeneratingListener;

/**
 * The Gradle 4.4 build's test task: {@code SideBySideLauncher REPORTS CLASS_REGEX ROOT...} runs the tests found
 * under the class-path roots ROOT, of the classes whose full names CLASS_REGEX matches, with every test engine
 * on the class path (JUnit Jupiter and jqwik) at once, each on a thread of its own, and writes each engine's
 * JUnit XML into REPORTS as the console launcher does ({@code TEST-junit-jupiter.xml}, {@code TEST-jqwik.xml}).
 *
 * <p>Why not the console launcher: the JUnit Platform runs one engine after another, and jqwik runs its
 * properties one at a time. On a machine of two cores the properties (about 29 s) then ran alone at the end
 * with one core idle. Side by side, they fill whatever core Jupiter leaves idle (its window tests run alone, for
 * the X server's sake). The engines share nothing but the
 * JVM: each has its own launcher, discovery request and listeners, and its properties and tests run as they would
 * alone (Jupiter two classes at a time, as {@code junit-platform.properties} says; jqwik one property at a time).
 * The threads are {@code test-engine-ID}.
 *
 * <p>Prints how long the run took and each engine's counts, and every failure with the start of its stack trace;
 * exits 1 when a test failed (or an engine could not run), 2 when no test was found, else 0.
 */
public final class SideBySideLauncher {

    /** Stack-trace lines printed per failure: enough to find the failing line, short enough to read. */
    private static final int TRACE_LINES = 12;

    private SideBySideLauncher() {
    }

    public static void main(String[] args) throws InterruptedException {
        if (args.length < 3) {
            System.err.println("usage: SideBySideLauncher REPORTS_DIR CLASS_NAME_REGEX CLASSPATH_ROOT...");
            System.exit(2);
        }
        Path reports = Path.of(args[0]);
        String classes = args[1];
        Set<Path> roots = new LinkedHashSet<>();
        for (int i = 2; i < args.length; i++) {
            roots.add(Path.of(args[i]));
        }
        long start = System.nanoTime();
        List<EngineRun> runs = new ArrayList<>();
        for (TestEngine engine : ServiceLoader.load(TestEngine.class)) {
            runs.add(new EngineRun(engine.getId(), request(engine.getId(), roots, classes), reports));
        }
        for (EngineRun run : runs) {
            run.thread.start();
        }
        for (EngineRun run : runs) {
            run.thread.join();
        }
        System.exit(report(runs, (System.nanoTime() - start) / 1_000_000, new PrintWriter(System.out, true,
                StandardCharsets.UTF_8)));
    }

    private static LauncherDiscoveryRequest request(String engine, Set<Path> roots, String classes) {
        return LauncherDiscoveryRequestBuilder.request()
                .selectors(DiscoverySelectors.selectClasspathRoots(roots))
                .filters(EngineFilter.includeEngines(engine), ClassNameFilter.includeClassNamePatterns(classes))
                .build();
    }

    /** Prints the run's summary and failures; the exit code. */
    private static int report(List<EngineRun> runs, long millis, PrintWriter out) {
        out.println();
        out.println("Test run finished after " + millis + " ms, the engines side by side:");
        long found = 0;
        boolean failed = false;
        for (EngineRun run : runs) {
            TestExecutionSummary s = run.summary.getSummary();
            found += s.getTestsFoundCount();
            out.printf("  %-14s %5d tests found, %5d successful, %3d failed, %3d skipped, %3d aborted, in %.1f s%n",
                    run.engine, s.getTestsFoundCount(), s.getTestsSucceededCount(), s.getTotalFailureCount(),
                    s.getTestsSkippedCount(), s.getTestsAbortedCount(),
                    (s.getTimeFinished() - s.getTimeStarted()) / 1000.0);
            if (s.getTotalFailureCount() > 0) {
                failed = true;
                s.printFailuresTo(out, TRACE_LINES);
            }
            if (run.crash.get() != null) {
                failed = true;
                out.println("  " + run.engine + " could not run:");
                run.crash.get().printStackTrace(out);
            }
        }
        out.flush();
        return failed ? 1 : found == 0 ? 2 : 0;
    }

    /** One engine's run: its thread, its listeners, and what stopped it, if anything did. */
    private static final class EngineRun {
        final String engine;
        final SummaryGeneratingListener summary = new SummaryGeneratingListener();
        final AtomicReference<Throwable> crash = new AtomicReference<>();
        final Thread thread;

        EngineRun(String engine, LauncherDiscoveryRequest request, Path reports) {
            this.engine = engine;
            LegacyXmlReportGeneratingListener xml = new LegacyXmlReportGeneratingListener(reports,
                    new PrintWriter(System.err, true, StandardCharsets.UTF_8));
            this.thread = new Thread(() -> {
                try {
                    Launcher launcher = LauncherFactory.create();
                    launcher.execute(request, summary, xml);
                } catch (Throwable e) {
                    crash.set(e);
                }
            }, "test-engine-" + engine);
        }
    }
}

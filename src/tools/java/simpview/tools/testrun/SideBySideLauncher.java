package simpview.tools.testrun;

import java.io.PrintWriter;
import java.lang.annotation.Annotation;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.ServiceLoader;
import java.util.Set;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.platform.engine.FilterResult;
import org.junit.platform.engine.TestDescriptor;
import org.junit.platform.engine.TestEngine;
import org.junit.platform.engine.TestSource;
import org.junit.platform.engine.TestTag;
import org.junit.platform.engine.discovery.ClassNameFilter;
import org.junit.platform.engine.discovery.DiscoverySelectors;
import org.junit.platform.engine.support.descriptor.ClassSource;
import org.junit.platform.engine.support.descriptor.MethodSource;
import org.junit.platform.launcher.EngineFilter;
import org.junit.platform.launcher.LauncherDiscoveryRequest;
import org.junit.platform.launcher.PostDiscoveryFilter;
import org.junit.platform.launcher.core.LauncherDiscoveryRequestBuilder;
import org.junit.platform.launcher.core.LauncherFactory;
import org.junit.platform.launcher.listeners.SummaryGeneratingListener;
import org.junit.platform.launcher.listeners.TestExecutionSummary;
import org.junit.platform.reporting.legacy.xml.LegacyXmlReportGeneratingListener;

/**
 * The Gradle 4.4 build's test task: {@code SideBySideLauncher REPORTS CLASS_REGEX ROOT...} runs the tests found
 * under the class-path roots ROOT, of the classes whose full names CLASS_REGEX matches, with every test engine
 * on the class path (JUnit Jupiter and jqwik) on two lanes at once, and writes each part's JUnit XML into
 * REPORTS as the console launcher does ({@code TEST-junit-jupiter.xml}, {@code TEST-jqwik.xml}; Jupiter's
 * classes that run alone in {@code TEST-junit-jupiter-alone.xml}, its timed tests in
 * {@code TEST-junit-jupiter-timed.xml}).
 *
 * <p>Why not the console launcher: the JUnit Platform runs one engine after another, jqwik runs its properties
 * one at a time, and Jupiter runs its {@code @Isolated} classes (the window tests, for the X server's sake) one
 * at a time after all its others. On a machine of two cores each of these ran with a core idle. Here the
 * lanes are:
 * <ul>
 * <li>{@code test-lane-shared}: Jupiter's classes that may share the machine, two at a time, as
 * {@code junit-platform.properties} says;
 * <li>{@code test-lane-alone}: every other engine (jqwik's properties), then Jupiter's {@code @Isolated}
 * classes, one at a time.
 * </ul>
 * The isolated classes still have the X server, the pointer and the focus to themselves: no test of the other
 * lane opens a window. What a test measures in time (how long the window's event thread stalls, how soon a
 * saved file is redrawn) would measure the other lane too: a test tagged {@code timed}, or of a class so
 * tagged, runs after both lanes, on the main thread, with the machine to itself. Each part has its own
 * launcher, discovery request and listeners, and its tests run as they would alone.
 *
 * <p>Prints how long the run took and each part's counts, and every failure with the start of its stack trace;
 * exits 1 when a test failed (or a part could not run), 2 when no test was found, else 0.
 */
public final class SideBySideLauncher {

    private static final String JUPITER = "junit-jupiter";
    private static final String ISOLATED = "org.junit.jupiter.api.parallel.Isolated";
    private static final String TIMED_TAG = "timed";

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
        List<EngineRun> shared = new ArrayList<>();
        List<EngineRun> alone = new ArrayList<>();
        List<EngineRun> isolated = new ArrayList<>();
        List<EngineRun> timed = new ArrayList<>();
        for (TestEngine engine : ServiceLoader.load(TestEngine.class)) {
            String id = engine.getId();
            if (id.equals(JUPITER)) {
                shared.add(new EngineRun(id, request(id, roots, classes, Sharing.SHARED), reports));
                isolated.add(new EngineRun(id + "-alone", request(id, roots, classes, Sharing.ALONE), reports));
                timed.add(new EngineRun(id + "-timed", request(id, roots, classes, Sharing.TIMED), reports));
            } else {
                alone.add(new EngineRun(id, request(id, roots, classes, Sharing.ANY), reports));
            }
        }
        alone.addAll(isolated); // after the other engines: the window tests, one class at a time
        Thread sharedLane = lane("shared", shared);
        Thread aloneLane = lane("alone", alone);
        sharedLane.start();
        aloneLane.start();
        sharedLane.join();
        aloneLane.join();
        timed.forEach(EngineRun::run);
        List<EngineRun> runs = new ArrayList<>(shared);
        runs.addAll(alone);
        runs.addAll(timed);
        System.exit(report(runs, (System.nanoTime() - start) / 1_000_000, new PrintWriter(System.out, true,
                StandardCharsets.UTF_8)));
    }

    /** A thread that runs {@code runs} one after another. */
    private static Thread lane(String name, List<EngineRun> runs) {
        return new Thread(() -> runs.forEach(EngineRun::run), "test-lane-" + name);
    }

    private static LauncherDiscoveryRequest request(String engine, Set<Path> roots, String classes, Sharing sharing) {
        return LauncherDiscoveryRequestBuilder.request()
                .selectors(DiscoverySelectors.selectClasspathRoots(roots))
                .filters(EngineFilter.includeEngines(engine), ClassNameFilter.includeClassNamePatterns(classes),
                        sharing.filter())
                .build();
    }

    /**
     * Which of an engine's tests a part runs: those of classes that may share the machine, those of classes that
     * run alone ({@code @Isolated}), those that time what they test ({@code @Tag("timed")}, on the test or its
     * class), or all.
     */
    private enum Sharing {
        SHARED, ALONE, TIMED, ANY;

        PostDiscoveryFilter filter() {
            return test -> {
                Sharing its = of(test);
                return this == ANY || this == its ? FilterResult.included(null)
                        : FilterResult.excluded("it runs in the part of the " + its.name().toLowerCase(Locale.ROOT));
            };
        }

        /**
         * Where a test runs: timed if it or an enclosing descriptor is tagged so; else alone if its class (or a
         * class enclosing it) is {@code @Isolated}, itself or by inheritance; else shared. The annotation is
         * matched by name: the build's tools do not compile against Jupiter.
         */
        private static Sharing of(TestDescriptor test) {
            boolean isolated = false;
            for (Optional<TestDescriptor> d = Optional.of(test); d.isPresent(); d = d.get().getParent()) {
                if (d.get().getTags().contains(TestTag.create(TIMED_TAG))) {
                    return TIMED;
                }
                Optional<TestSource> source = d.get().getSource();
                if (source.isPresent() && source.get() instanceof ClassSource c) {
                    isolated |= isolated(c.getJavaClass());
                } else if (source.isPresent() && source.get() instanceof MethodSource m) {
                    isolated |= isolated(m.getJavaClass());
                }
            }
            return isolated ? ALONE : SHARED;
        }

        private static boolean isolated(Class<?> type) {
            for (Class<?> t = type; t != null; t = t.getEnclosingClass()) {
                for (Annotation a : t.getAnnotations()) {
                    if (a.annotationType().getName().equals(ISOLATED)) {
                        return true;
                    }
                }
            }
            return false;
        }
    }

    /** Prints the run's summary and failures; the exit code. */
    private static int report(List<EngineRun> runs, long millis, PrintWriter out) {
        out.println();
        out.println("Test run finished after " + millis + " ms, on two lanes side by side:");
        long found = 0;
        boolean failed = false;
        for (EngineRun run : runs) {
            TestExecutionSummary s = run.summary.getSummary();
            found += s.getTestsFoundCount();
            out.printf("  %-20s %5d tests found, %5d successful, %3d failed, %3d skipped, %3d aborted, in %.1f s%n",
                    run.part, s.getTestsFoundCount(), s.getTestsSucceededCount(), s.getTotalFailureCount(),
                    s.getTestsSkippedCount(), s.getTestsAbortedCount(),
                    (s.getTimeFinished() - s.getTimeStarted()) / 1000.0);
            if (s.getTotalFailureCount() > 0) {
                failed = true;
                s.printFailuresTo(out, TRACE_LINES);
            }
            if (run.crash.get() != null) {
                failed = true;
                out.println("  " + run.part + " could not run:");
                run.crash.get().printStackTrace(out);
            }
        }
        out.flush();
        return failed ? 1 : found == 0 ? 2 : 0;
    }

    /**
     * One part of the run: an engine's tests (or some of them), its listeners, and what stopped it, if anything
     * did. Its XML goes into a folder of its own, then into the reports' folder under the part's name.
     */
    private static final class EngineRun {
        final String part;
        final SummaryGeneratingListener summary = new SummaryGeneratingListener();
        final AtomicReference<Throwable> crash = new AtomicReference<>();
        private final LauncherDiscoveryRequest request;
        private final Path reports;

        EngineRun(String part, LauncherDiscoveryRequest request, Path reports) {
            this.part = part;
            this.request = request;
            this.reports = reports;
        }

        void run() {
            try {
                Path own = Files.createDirectories(reports.resolve("part-" + part));
                LegacyXmlReportGeneratingListener xml = new LegacyXmlReportGeneratingListener(own,
                        new PrintWriter(System.err, true, StandardCharsets.UTF_8));
                LauncherFactory.create().execute(request, summary, xml);
                try (DirectoryStream<Path> files = Files.newDirectoryStream(own, "TEST-*.xml")) {
                    for (Path file : files) {
                        Files.move(file, reports.resolve("TEST-" + part + ".xml"), StandardCopyOption.REPLACE_EXISTING);
                    }
                }
                Files.delete(own);
            } catch (Throwable e) {
                crash.set(e);
            }
        }
    }
}

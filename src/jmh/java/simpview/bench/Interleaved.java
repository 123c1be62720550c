package simpview.bench;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.lang.management.ManagementFactory;
import java.lang.reflect.Field;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.TearDown;

/**
 * Two or more builds of simpview measured against each other in one process,
 * invocation by invocation, so that a shared host's bursts of load fall on
 * all of them alike: the ratio is what carries over, not the times.
 *
 * <p>Each build's classes (the {@code build/classes/java/jmh} and
 * {@code main} folders of a build, given as its {@code build/classes/java}
 * folder) get a class loader of their own, so each build's code is compiled
 * and profiled apart. One JMH benchmark class of each is set up as JMH would
 * ({@code @Param} fields at their first value or as given, the trial and
 * iteration set-ups once), warmed, then the builds take turns, the order
 * rotated by one every round, so that each build takes each place in turn
 * and, of three builds or more, none follows itself: in its turn a build's
 * benchmark method is called once untimed, then {@link #TIMED_IN_A_TURN}
 * times timed, the invocation set-ups run untimed before each call. It
 * prints each build's median, 10th percentile and best call, the
 * medians' ratios to the first build's, and the ratio taken turn by turn
 * with a 90 % interval ({@link #pairedRatio}). (With the order reversed every
 * round instead, the first and the last build had every other turn right
 * after one of their own, and the builds between them never: on A4 page-g
 * the second of three ran 2-8 % slower than the others, copies of one build
 * alike; docs/performance-log.md, session 21.)
 *
 * <p>The JIT compiles each build once per process, and how well it does
 * varies from process to process by several per cent with the same code; so
 * run it in a few processes ({@code --processes N} runs them one after
 * another and sums them up, {@link #inProcesses}) and compare the figures
 * across them (including, once, a build against a copy of itself).
 *
 * <p>Run: {@code java -cp <jmh runtime classpath> simpview.bench.Interleaved
 * [--processes N] CLASS METHOD SECONDS PARAMS DIR...}, CLASS a benchmark class as
 * {@code simpview.bench.LitPages}, PARAMS as {@code scene=a3/pageI,threads=1}
 * (or "" for the defaults), each DIR a build's {@code build/classes/java},
 * perhaps followed by parameters of its own that override PARAMS for it
 * ({@code build/classes/java@threads=2,turned=false}), so that one build
 * can also be measured against itself set up another way.
 * The course's files are found as the benchmarks find them
 * ({@code -Dsimpview.courseSimp}). Give it the JVM options simpview's start
 * scripts and the JMH runs have (build.gradle's {@code drawingJvmArgs}:
 * {@code -XX:+UseParallelGC -XX:-UseAdaptiveSizePolicy
 * -XX:-UseCompressedOops}): with the JVM's defaults the pages draw 7-15 %
 * slower.
 */
public final class Interleaved {

    /**
     * Calls of a build timed one after another in its turn, after one
     * untimed call. A benchmark drawing on two threads leaves its worker
     * spinning for a while after each call, waiting for the next picture
     * (DrawingThreads); the next build's first call shares the cores with
     * that spinning worker, and starts its own parked one. Its later calls
     * are drawn as a benchmark's back-to-back calls are.
     */
    private static final int TIMED_IN_A_TURN = 3;

    /** The bootstrap's resamples of the rotations, and its seed ({@link #pairedRatio}). */
    private static final int RESAMPLES = 2000;
    private static final long RESAMPLE_SEED = 47;

    private Interleaved() {
    }

    /** One build's benchmark object and its methods. */
    private record LoadedBuild(String name, Object state, Method benchmark, List<Method> perInvocation,
            List<Method> tearDowns) {

        void call() throws ReflectiveOperationException {
            for (Method m : perInvocation) {
                m.invoke(state);
            }
            benchmark.invoke(state);
        }
    }

    /** Loads simpview's classes from its own build, everything else (JMH, the JDK, libraries) from its parent. */
    private static final class OwnFirst extends URLClassLoader {

        OwnFirst(URL[] urls, ClassLoader parent) {
            super(urls, parent);
        }

        @Override
        protected Class<?> loadClass(String name, boolean resolve) throws ClassNotFoundException {
            if (!name.startsWith("simpview.") || name.startsWith(Interleaved.class.getName())) {
                return super.loadClass(name, resolve);
            }
            synchronized (getClassLoadingLock(name)) {
                Class<?> c = findLoadedClass(name);
                if (c == null) {
                    try {
                        c = findClass(name);
                    } catch (ClassNotFoundException e) {
                        c = super.loadClass(name, false);
                    }
                }
                if (resolve) {
                    resolveClass(c);
                }
                return c;
            }
        }
    }

    public static void main(String[] args) throws Exception {
        if (args.length >= 2 && args[0].equals("--processes")) {
            inProcesses(Integer.parseInt(args[1]), Arrays.copyOfRange(args, 2, args.length));
            return;
        }
        if (args.length < 5) {
            System.err.println("usage: Interleaved [--processes N] CLASS METHOD SECONDS PARAMS DIR...");
            System.exit(2);
        }
        double seconds = Double.parseDouble(args[2]);
        List<LoadedBuild> builds = new ArrayList<>();
        for (int i = 4; i < args.length; i++) {
            String[] dirAndOwn = args[i].split("@", 2);
            String params = dirAndOwn.length == 1 ? args[3]
                    : args[3].isEmpty() ? dirAndOwn[1] : args[3] + "," + dirAndOwn[1];
            builds.add(load(dirAndOwn[0], args[0], args[1], params, args[i]));
        }
        long warmUntil = System.nanoTime() + (long) (Math.max(4, seconds / 3) * 1e9);
        while (System.nanoTime() < warmUntil) {
            for (LoadedBuild b : builds) {
                for (int k = 0; k < 20; k++) {
                    b.call();
                }
            }
        }
        List<long[]> samples = new ArrayList<>();
        for (int i = 0; i < builds.size(); i++) {
            samples.add(new long[1024]);
        }
        int rounds = 0;
        long until = System.nanoTime() + (long) (seconds * 1e9);
        while (System.nanoTime() < until) {
            for (int j = 0; j < builds.size(); j++) {
                int i = (j + rounds / TIMED_IN_A_TURN) % builds.size();
                LoadedBuild b = builds.get(i);
                for (int call = 0; call <= TIMED_IN_A_TURN; call++) {
                    for (Method m : b.perInvocation()) {
                        m.invoke(b.state());
                    }
                    long start = System.nanoTime();
                    b.benchmark().invoke(b.state());
                    long took = System.nanoTime() - start;
                    if (call == 0) {
                        continue; // the turn's first call, untimed
                    }
                    long[] s = samples.get(i);
                    int at = rounds + call - 1;
                    if (at >= s.length) {
                        s = Arrays.copyOf(s, 2 * s.length);
                        samples.set(i, s);
                    }
                    s[at] = took;
                }
            }
            rounds += TIMED_IN_A_TURN;
        }
        double first = 0;
        for (int i = 0; i < builds.size(); i++) {
            long[] s = Arrays.copyOf(samples.get(i), rounds);
            Arrays.sort(s);
            double median = s[rounds / 2] / 1e6;
            if (i == 0) {
                first = median;
            }
            String paired = i == 0 ? "" : pairedRatio(samples.get(i), samples.get(0), rounds);
            // read back by FIGURES
            System.out.printf(Locale.ROOT, "%-24s calls %d  median %.4f ms  p10 %.4f  best %.4f  median / first's %.3f%s%n",
                    builds.get(i).name(), rounds, median, s[rounds / 10] / 1e6, s[0] / 1e6, median / first, paired);
        }
        for (LoadedBuild b : builds) {
            for (Method m : b.tearDowns()) {
                m.invoke(b.state());
            }
        }
    }

    /**
     * A build's figures as {@link #main} prints them: its name, its median's
     * ratio to the first build's, and the ratio turn by turn ({@link #pairedRatio}),
     * which the first build has not.
     */
    private static final Pattern FIGURES =
            Pattern.compile("^(\\S+)\\s+calls \\d+ .* median / first's ([0-9.]+)(?:  by turns ([0-9.]+) \\[)?");

    /**
     * The same measurement in {@code count} processes, one after another,
     * each a JVM with this one's options and class path, each printing its
     * figures as it ends; then, for each build but the first, the median of
     * its ratios turn by turn over the processes, and each process's. How
     * well the JIT compiles a build varies from process to process by more
     * than the host's noise within one (session 48 saw two modes a tenth
     * apart, the same change faster in three processes of five and slower in
     * two), so a change is judged over several.
     */
    private static void inProcesses(int count, String[] args) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        command.addAll(ManagementFactory.getRuntimeMXBean().getInputArguments());
        command.add("-cp");
        command.add(System.getProperty("java.class.path"));
        command.add(Interleaved.class.getName());
        command.addAll(List.of(args));
        Map<String, List<Double>> byTurns = new LinkedHashMap<>();
        Map<String, List<Double>> ofMedians = new LinkedHashMap<>();
        for (int p = 1; p <= count; p++) {
            System.out.printf(Locale.ROOT, "process %d of %d%n", p, count);
            Process child = new ProcessBuilder(command).redirectErrorStream(true).start();
            try (BufferedReader out = new BufferedReader(
                    new InputStreamReader(child.getInputStream(), StandardCharsets.UTF_8))) {
                for (String line = out.readLine(); line != null; line = out.readLine()) {
                    System.out.println(line);
                    Matcher m = FIGURES.matcher(line);
                    if (m.find() && m.group(3) != null) {
                        byTurns.computeIfAbsent(m.group(1), b -> new ArrayList<>()).add(Double.valueOf(m.group(3)));
                        ofMedians.computeIfAbsent(m.group(1), b -> new ArrayList<>()).add(Double.valueOf(m.group(2)));
                    }
                }
            }
            if (child.waitFor() != 0) {
                throw new IllegalStateException("process " + p + " of " + count + " failed: " + command);
            }
        }
        for (Map.Entry<String, List<Double>> b : byTurns.entrySet()) {
            List<Double> each = b.getValue();
            System.out.printf(Locale.ROOT, "%-24s over %d processes: by turns %.3f (each %s), median / first's %.3f%n",
                    b.getKey(), each.size(), medianOf(each), each.stream()
                            .map(r -> String.format(Locale.ROOT, "%.3f", r)).collect(Collectors.joining(" ")),
                    medianOf(ofMedians.get(b.getKey())));
        }
    }

    /** The median of {@code values}: the middle one, or the mean of the middle two. */
    private static double medianOf(List<Double> values) {
        double[] sorted = values.stream().mapToDouble(Double::doubleValue).sorted().toArray();
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    }

    /**
     * The build's time against the first build's, turn by turn: in each
     * rotation both took a turn of {@link #TIMED_IN_A_TURN} calls within
     * moments of each other, so a burst of the host's load falls on both.
     * As text: in each rotation the ratio of the two turns' medians, the
     * median of those ratios, and a 90 % interval for it by the bootstrap (the rotations
     * drawn again with replacement, {@link #RESAMPLES} times, from a fixed
     * seed). The interval speaks of the host's noise in this process only:
     * how well the JIT compiled each build varies from process to process,
     * which only other processes, and a copy of a build, show.
     */
    private static String pairedRatio(long[] build, long[] first, int calls) {
        int turns = calls / TIMED_IN_A_TURN;
        if (turns < 2) {
            return "";
        }
        double[] ratios = new double[turns];
        for (int t = 0; t < turns; t++) {
            ratios[t] = (double) turnMedian(build, t) / turnMedian(first, t);
        }
        double[] sorted = ratios.clone();
        Arrays.sort(sorted);
        double median = sorted[turns / 2];
        double[] medians = new double[RESAMPLES];
        double[] drawn = new double[turns];
        SplittableRandom random = new SplittableRandom(RESAMPLE_SEED);
        for (int r = 0; r < RESAMPLES; r++) {
            for (int t = 0; t < turns; t++) {
                drawn[t] = ratios[random.nextInt(turns)];
            }
            Arrays.sort(drawn);
            medians[r] = drawn[turns / 2];
        }
        Arrays.sort(medians);
        return String.format(Locale.ROOT, "  by turns %.3f [%.3f, %.3f]", median, medians[RESAMPLES / 20],
                medians[RESAMPLES - 1 - RESAMPLES / 20]);
    }

    /** The median of one turn's timed calls (turn t holds calls t * TIMED_IN_A_TURN on). */
    private static long turnMedian(long[] samples, int t) {
        long[] turn = Arrays.copyOfRange(samples, t * TIMED_IN_A_TURN, (t + 1) * TIMED_IN_A_TURN);
        Arrays.sort(turn);
        return turn[TIMED_IN_A_TURN / 2];
    }

    private static LoadedBuild load(String dir, String className, String method, String params, String label)
            throws ReflectiveOperationException, MalformedURLException {
        File classes = new File(dir);
        URL[] urls = {new File(classes, "jmh").toURI().toURL(), new File(classes, "main").toURI().toURL()};
        ClassLoader loader = new OwnFirst(urls, Interleaved.class.getClassLoader());
        Class<?> type = Class.forName(className, true, loader);
        Object state = type.getDeclaredConstructor().newInstance();
        Map<String, String> values = new LinkedHashMap<>();
        for (Field f : type.getFields()) {
            Param p = f.getAnnotation(Param.class);
            if (p != null && p.value().length > 0) {
                values.put(f.getName(), p.value()[0]);
            }
        }
        for (String given : params.isEmpty() ? new String[0] : params.split(",")) {
            String[] kv = given.split("=", 2);
            if (kv.length != 2) {
                throw new IllegalArgumentException("a parameter is name=value, not " + given);
            }
            if (values.containsKey(kv[0])) { // a parameter an older build lacks keeps its default there
                values.put(kv[0], kv[1]);
            }
        }
        for (Map.Entry<String, String> e : values.entrySet()) {
            set(type.getField(e.getKey()), state, e.getValue());
        }
        List<Method> perInvocation = new ArrayList<>();
        List<Method> tearDowns = new ArrayList<>();
        for (Level level : new Level[] {Level.Trial, Level.Iteration, Level.Invocation}) {
            for (Method m : type.getMethods()) {
                Setup setup = m.getAnnotation(Setup.class);
                if (setup != null && setup.value() == level) {
                    if (level == Level.Invocation) {
                        perInvocation.add(m);
                    } else {
                        invoke(m, state);
                    }
                }
            }
        }
        for (Method m : type.getMethods()) {
            if (m.getAnnotation(TearDown.class) != null) {
                tearDowns.add(m);
            }
        }
        String name = nameOf(classes) + (label.contains("@") ? label.substring(label.indexOf('@')) : "");
        return new LoadedBuild(name, state, type.getMethod(method),
                perInvocation, tearDowns);
    }

    /** A build's name: its folder, less a trailing build/classes/java or classes/java. */
    private static String nameOf(File classes) {
        String path = classes.getAbsolutePath().replace(File.separatorChar, '/');
        for (String tail : new String[] {"/build/classes/java", "/classes/java"}) {
            if (path.endsWith(tail)) {
                path = path.substring(0, path.length() - tail.length());
                break;
            }
        }
        return path.substring(path.lastIndexOf('/') + 1);
    }

    private static void invoke(Method m, Object state) throws ReflectiveOperationException {
        try {
            m.invoke(state);
        } catch (InvocationTargetException e) {
            throw new IllegalStateException(m.getName() + " failed", e.getCause());
        }
    }

    private static void set(Field f, Object state, String value) throws IllegalAccessException {
        Class<?> t = f.getType();
        Object v = t == int.class ? Integer.valueOf(value)
                : t == boolean.class ? Boolean.valueOf(value)
                : t == double.class ? Double.valueOf(value)
                : t == long.class ? Long.valueOf(value)
                : value;
        f.set(state, v);
    }
}

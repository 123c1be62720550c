package simpview.cli;

import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import simpview.surface.DrawingThreads;

/** {@code --threads N}, for every command that draws: how many threads draw each picture's bands. */
final class ThreadsOption {

    /** More threads than this would only cost their set-up: a band is then a few rows. */
    static final int MOST = 64;

    @Spec(Spec.Target.MIXEE)
    private CommandSpec spec;

    @Option(names = "--threads", paramLabel = "N",
            description = "threads that draw each picture, 1 to " + MOST + " (default: one per processor); "
                    + "every picture is the same to the bit at any N")
    private Integer threads;

    /** The count asked for, or one per processor; a count out of range is a usage error. */
    int count() {
        if (threads == null) {
            return Math.min(MOST, Runtime.getRuntime().availableProcessors());
        }
        if (threads < 1 || threads > MOST) {
            throw new ParameterException(spec.commandLine(), "--threads must be 1 to " + MOST + ", not " + threads);
        }
        return threads;
    }

    /** The threads, for the caller to close: as many as given, or one per processor ({@link #count}). */
    DrawingThreads open() {
        return DrawingThreads.of(count());
    }
}

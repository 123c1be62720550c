package simpview.testing;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.params.provider.Arguments;

/**
 * The thread counts every picture test draws at: one (the caller's thread,
 * drawing as it reads), two (this machine's cores) and seven (more threads
 * than cores, and bands of uneven height). Every picture must be the same
 * at each, to the bit.
 */
public final class ThreadCounts {

    public static final List<Integer> ALL = List.of(1, 2, 7);

    private ThreadCounts() {
    }

    /** Each case at each thread count, as the arguments (case, threads). */
    public static <T> Stream<Arguments> each(List<T> cases) {
        List<Arguments> all = new ArrayList<>();
        for (T c : cases) {
            for (int threads : ALL) {
                all.add(Arguments.of(c, threads));
            }
        }
        return all.stream();
    }
}

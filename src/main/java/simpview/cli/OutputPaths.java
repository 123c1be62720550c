package simpview.cli;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import simpview.compare.OutputFiles;

/**
 * The files one run of a command reads and those it writes, so that it
 * writes none it reads (a student's picture overwritten by its own diff) and
 * none twice (two reports named one file: one would be lost). Two names are
 * one file when {@link OutputFiles#identity} says so. A clash is a usage
 * error (exit 2), found before anything is written. It also keeps which of
 * them the run has written, so that at its end, failed or not, a FIFO among
 * those it did not write is opened and closed ({@link #releaseUnwritten}).
 */
final class OutputPaths {

    /** The name that means standard output where an option takes it (--primitives), and a file nowhere. */
    static final String STANDARD_OUTPUT = "-";

    /** The files read, each with what it is to the run: "the picture to compare". */
    private final Map<Path, String> read = new HashMap<>();
    /** The files written, each with the option that names it. */
    private final Map<Path, String> written = new HashMap<>();
    /** Files the run may write besides those: a batch's diff images, each written or not by how its picture fares. */
    private final Set<Path> mayWrite = new HashSet<>();
    /** The files of either kind the run has written so far; told from any thread (a batch's comparing threads). */
    private final Set<Path> done = ConcurrentHashMap.newKeySet();

    /** {@code file} (null: none) is read by the run, as {@code what}: "the rubric", "a picture to compare". */
    OutputPaths reads(Path file, String what) {
        if (file != null) {
            read.putIfAbsent(OutputFiles.identity(file), what);
        }
        return this;
    }

    /**
     * {@code file} (null: none) is written by {@code option} ("--diff"), and
     * no other file of the run is written there.
     *
     * @throws UsageProblem when the run reads that file, or writes it already, or when it is named {@code -},
     *     which names standard output for --primitives (not given here) and would elsewhere be a file of that
     *     name in the working folder
     */
    OutputPaths writes(Path file, String option) {
        if (file == null) {
            return this;
        }
        if (file.toString().equals(STANDARD_OUTPUT)) {
            throw new UsageProblem(option + " " + file + ": simpview writes it to a file, not to standard output ('"
                    + STANDARD_OUTPUT + "' is standard output for --primitives only): name a file, or /dev/stdout "
                    + "to pipe it");
        }
        notRead(file, option);
        String other = written.putIfAbsent(OutputFiles.identity(file), option);
        if (other != null) {
            throw new UsageProblem(other.equals(option)
                    ? option + " would write " + file + " twice; give each its own name"
                    : other + " and " + option + " both write " + file + "; give each its own file");
        }
        return this;
    }

    /** {@code file} has been written whole: {@link #releaseUnwritten} leaves it alone. */
    void wrote(Path file) {
        done.add(OutputFiles.identity(file));
    }

    /**
     * At the end of a run, failed or not: each file it was to write
     * ({@link #writes}) or might have written ({@link #mayWrite}) and did not
     * that is a FIFO is opened and closed ({@link OutputFiles#release}), so
     * that its reader sees the end of the file and is not left waiting: a
     * page that failed among several, the pages after a folder that could not
     * be written, the diff image of a picture that passed. Files written are
     * not opened again (a reader that opens its FIFO anew would get an empty
     * file); regular files are left as they are.
     */
    void releaseUnwritten() {
        for (Path file : written.keySet()) {
            releaseUnlessWritten(file);
        }
        for (Path file : mayWrite) {
            releaseUnlessWritten(file);
        }
    }

    private void releaseUnlessWritten(Path file) {
        if (!done.contains(file)) {
            OutputFiles.release(file);
        }
    }

    /**
     * {@code file} (null: none) may be written by {@code option}, as other
     * files of it may be (a batch's diff images: their names are its
     * pictures'), but it is none the run reads; {@link #releaseUnwritten}
     * releases it if the run does not write it.
     *
     * @throws UsageProblem when the run reads that file
     */
    OutputPaths mayWrite(Path file, String option) {
        notRead(file, option);
        if (file != null) {
            mayWrite.add(OutputFiles.identity(file));
        }
        return this;
    }

    /**
     * {@code file} (null: none) is none the run reads.
     *
     * @throws UsageProblem when the run reads that file
     */
    private OutputPaths notRead(Path file, String option) {
        if (file == null) {
            return this;
        }
        String what = read.get(OutputFiles.identity(file));
        if (what != null) {
            throw new UsageProblem(option + ": " + file + " is " + what + "; writing there would overwrite it");
        }
        return this;
    }
}

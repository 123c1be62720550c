package simpview.cli;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import simpview.compare.OutputFiles;

/**
 * The files one run of a command reads and those it writes, so that it
 * writes none it reads (a student's picture overwritten by its own diff) and
 * none twice (two reports named one file: one would be lost). Two names are
 * one file when {@link OutputFiles#identity} says so. A clash is a usage
 * error (exit 2), found before anything is written.
 */
final class OutputPaths {

    /** The files read, each with what it is to the run: "the picture to compare". */
    private final Map<Path, String> read = new HashMap<>();
    /** The files written, each with the option that names it. */
    private final Map<Path, String> written = new HashMap<>();

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
     * @throws UsageProblem when the run reads that file, or writes it already
     */
    OutputPaths writes(Path file, String option) {
        if (file == null) {
            return this;
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

    /**
     * After a run that failed: each file it was to write ({@link #writes})
     * that is a FIFO is opened and closed ({@link OutputFiles#release}), so
     * that a reader waiting on one it never wrote sees the end of the file
     * and the run cannot leave it waiting; regular files are left as they are.
     */
    void releaseAfterFailure() {
        written.keySet().forEach(OutputFiles::release);
    }

    /**
     * {@code file} (null: none) may be written by {@code option}, as other
     * files of it may be (a batch's diff images: their names are its
     * pictures'), but it is none the run reads.
     *
     * @throws UsageProblem when the run reads that file
     */
    OutputPaths notRead(Path file, String option) {
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

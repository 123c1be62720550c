package simpview.cli;

import java.io.IOException;
import java.nio.file.Path;
import simpview.cli.CompareBatch.DiffImages;
import simpview.compare.PngFiles;

/**
 * Where a batch's diff images go ({@code outDir} null: nowhere), which pictures get one, and their names;
 * {@code files} is told each one written.
 */
record DiffPlan(Path outDir, DiffImages which, DiffNames names, OutputPaths files) {

    /** What a row's note starts with when its diff image could not be written; the reason follows. */
    static final String NOT_WRITTEN = "diff not written: ";

    /** Whether a picture (or panel) that passes or not gets a diff image. */
    boolean writes(boolean passes) {
        return outDir != null && which != DiffImages.NONE && !(which == DiffImages.FAILING && passes);
    }

    /** Writes the diff image {@code name} in {@link #outDir}. */
    void write(String name, byte[] png) throws IOException {
        Path file = outDir.resolve(name);
        PngFiles.writeEncoded(png, file);
        files.wrote(file);
    }
}

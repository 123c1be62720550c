package simpview.window.render;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.BooleanSupplier;

/** Counts a file's lines (its newlines, and a last line without one), for the progress bar's fraction. */
public final class LineCount {

    private LineCount() {
    }

    /** The number of lines, or -1 when the file cannot be read or {@code stop} says so first. */
    static long of(Path file, BooleanSupplier stop) {
        byte[] buffer = new byte[1 << 16];
        long lines = 0;
        boolean pending = false;
        try (InputStream in = Files.newInputStream(file)) {
            for (int n = in.read(buffer); n > 0; n = in.read(buffer)) {
                if (stop.getAsBoolean()) {
                    return -1;
                }
                for (int i = 0; i < n; i++) {
                    if (buffer[i] == '\n') {
                        lines++;
                    }
                }
                pending = buffer[n - 1] != '\n';
            }
        } catch (IOException | SecurityException e) {
            return -1;
        }
        return pending ? lines + 1 : lines;
    }
}

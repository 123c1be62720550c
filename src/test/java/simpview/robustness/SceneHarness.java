package simpview.robustness;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import net.jqwik.api.lifecycle.LifecycleContext;
import net.jqwik.api.lifecycle.SkipExecutionHook;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;

/**
 * Runs SIMP scenes the way a page does (a 750x750 canvas, scissor, z-buffer
 * and depth cue) under a 2-second watchdog, and judges how they end: either
 * {@link ScenePipeline#drawDepthCued} returns, or it throws a {@link SceneException}
 * that says where the problem is. Anything else fails.
 */
final class SceneHarness {

    static final long LIMIT_MS = 2000;

    private final PageCanvas canvas = new PageCanvas();

    /** How a scene ended: null if it rendered, else its error (already checked for a sound location). */
    SceneException run(Path top) throws Exception {
        canvas.clear();
        SceneException error = Watchdog.withinMillis(LIMIT_MS, "scene " + top + describe(top), stop -> {
            SceneMonitor monitor = new SceneMonitor() {
                @Override
                public boolean cancelled() {
                    return stop.get();
                }
            };
            try {
                ScenePipeline.drawDepthCued(top, canvas.depthCued(Rgb.WHITE, Rgb.BLACK), monitor);
                return null;
            } catch (SceneException e) {
                return e;
            }
        });
        if (error != null) {
            checkLocation(error);
        }
        checkMargins();
        return error;
    }

    private static String describe(Path top) {
        try {
            String text = Files.readString(top, StandardCharsets.ISO_8859_1);
            return text.length() > 2000 ? "" : ":\n" + text;
        } catch (IOException e) {
            return "";
        }
    }

    /**
     * A file that is not text: none of its bytes is shown, and the offset the
     * message names is a byte no text holds, on the line and at the column
     * it names.
     */
    private static void checkNotText(SceneException e, String where) throws IOException {
        assertEquals("", e.lineText(), "a binary line is not shown" + where);
        Matcher m = Pattern
                .compile("^not (?:a text file|UTF-8 text): byte 0x([0-9A-F]{2}) at offset (\\d+) \\(line (\\d+)\\)")
                .matcher(e.problem());
        assertTrue(m.find(), "the byte, its offset and its line" + where);
        byte[] bytes = Files.readAllBytes(e.file());
        int offset = Integer.parseInt(m.group(2));
        assertTrue(offset < bytes.length, "an offset within the file" + where);
        int v = bytes[offset] & 0xFF;
        assertEquals(Integer.parseInt(m.group(1), 16), v, "the byte named is the byte at that offset" + where);
        assertTrue(v < 0x20 && v != '\t' && v != '\r' && v != '\n' && v != '\f' || v >= 0x7F,
                "a byte no UTF-8 text holds" + where);
        int line = 1;
        for (int i = 0; i < offset; i++) {
            line += bytes[i] == '\n' ? 1 : 0;
        }
        assertEquals(e.line(), line, "on the line named" + where);
        assertEquals(line, Integer.parseInt(m.group(3)), where);
        int start = offset;
        while (start > 0 && bytes[start - 1] != '\n') {
            start--;
        }
        if (start == 0 && bytes.length >= 3 && bytes[0] == (byte) 0xEF && bytes[1] == (byte) 0xBB
                && bytes[2] == (byte) 0xBF) {
            start = 3;
        }
        int column = 1;
        for (int i = start; i < offset; i++) {
            column += (bytes[i] & 0xC0) == 0x80 ? 0 : 1;
        }
        assertEquals(column, e.column(), "the byte's column, in characters from its line's start" + where);
    }

    /**
     * A sound error: a file; line 1 or more (0 only when the file as a whole
     * is at fault: missing or unreadable), within the file; the line shown as
     * it stands there; a column from 0 to one past the line's end; a message.
     */
    static void checkLocation(SceneException e) throws IOException {
        String where = "\n--- the error was:\n" + e.getMessage();
        assertNotNull(e.file(), "the error names no file" + where);
        assertTrue(e.line() >= 0, "negative line" + where);
        assertTrue(e.column() >= 0, "negative column" + where);
        assertTrue(e.problem() != null && !e.problem().isBlank(), "no problem stated" + where);
        assertTrue(e.getMessage().contains(e.file().toString()), "the message does not name the file" + where);
        boolean readable = Files.isRegularFile(e.file()) && Files.isReadable(e.file());
        if (e.line() == 0) {
            assertTrue(!readable, "line 0 for a readable file: the problem is on some line of it" + where);
            return;
        }
        assertTrue(readable, "a line number in a file that cannot be read" + where);
        String[] lines = new String(Files.readAllBytes(e.file()), StandardCharsets.UTF_8).split("\n", -1);
        assertTrue(e.line() <= lines.length, "line " + e.line() + " of a file with " + lines.length + " lines" + where);
        String raw = lines[e.line() - 1];
        String stripped = raw.endsWith("\r") ? raw.substring(0, raw.length() - 1) : raw;
        String shown = e.lineText();
        if (e.problem().startsWith("not a text file: ") || e.problem().startsWith("not UTF-8 text: ")) {
            checkNotText(e, where);
            return;
        }
        if (!shown.equals(raw) && !shown.equals(stripped)) {
            assertEquals(stripped, shown, "the line shown is not line " + e.line() + " of the file" + where);
        }
        int length = stripped.codePointCount(0, stripped.length());
        assertTrue(e.column() <= length + 1,
                "column " + e.column() + " beyond the end of a line of " + length + " characters" + where);
        if (e.column() >= 1 && e.column() <= length) {
            int c = stripped.codePointAt(stripped.offsetByCodePoints(0, e.column() - 1));
            assertTrue(c != ' ' && c != '\t', "the column points at a blank, not at the offending text" + where);
        }
    }

    private void checkMargins() {
        int size = PageCanvas.SIZE;
        int m = PageCanvas.MARGIN;
        int[] px = GeometryFuzzProperties.pixels(canvas);
        for (int y = 0; y < size; y++) {
            boolean band = y < m || y >= size - m;
            for (int x = 0; x < size; x = !band && x == m - 1 ? size - m : x + 1) {
                if ((px[y * size + x] & 0xFFFFFF) != 0xFFFFFF) {
                    fail("a scene wrote on the margin at " + x + "," + y);
                }
            }
        }
    }

    static Path write(Path file, String text) {
        try {
            Files.createDirectories(file.getParent());
            Files.write(file, text.getBytes(StandardCharsets.UTF_8));
            return file;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    static void deleteTree(Path dir) {
        if (dir == null || !Files.exists(dir)) {
            return;
        }
        try (Stream<Path> s = Files.walk(dir)) {
            s.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}

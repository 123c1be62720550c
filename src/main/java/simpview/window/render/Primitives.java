package simpview.window.render;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import simpview.stage.PrimitiveLog;

/**
 * The primitives of a finished picture in drawing order, as the inspector
 * and the stepping line name them: "page7.simp:118 polygon (...)" for a
 * scene's (the command's text read from its file when first asked for), or
 * the page's own names (page 3's triangles).
 */
public final class Primitives {

    static final Primitives NONE = new Primitives(List.of(), null);
    /** Files larger than this are not read again for their lines' text. */
    private static final long LARGEST_TO_QUOTE = 16L << 20;

    private final List<String> names;
    private final PrimitiveLog log;
    private final Map<Path, List<String>> lines = new HashMap<>();

    private Primitives(List<String> names, PrimitiveLog log) {
        this.names = names;
        this.log = log;
    }

    static Primitives named(List<String> names) {
        return new Primitives(List.copyOf(names), null);
    }

    static Primitives logged(PrimitiveLog log) {
        return new Primitives(List.of(), log);
    }

    public int size() {
        return log != null ? log.size() : names.size();
    }

    /** "page7.simp:118 polygon (...)", or the page's name for it. */
    public String describe(int primitive) {
        if (log == null) {
            return names.get(primitive);
        }
        Path file = log.file(primitive);
        int line = log.line(primitive);
        String text = lineText(file, line);
        return file.getFileName() + ":" + line + (text.isEmpty() ? "" : " " + text);
    }

    /**
     * Where a scene's primitive was given: its file's whole path and the
     * line, "/home/me/course-simp/cube.simp:20"; null for a page's own.
     */
    public String place(int primitive) {
        if (log == null || primitive < 0 || primitive >= log.size()) {
            return null;
        }
        return log.file(primitive).toAbsolutePath() + ":" + log.line(primitive);
    }

    /** Its projected vertices, panel x and y in turn, or null when not known. */
    public double[] outline(int primitive) {
        return log == null ? null : log.outline(primitive);
    }

    private String lineText(Path file, int line) {
        List<String> text = lines.computeIfAbsent(file, Primitives::read);
        return line >= 1 && line <= text.size() ? text.get(line - 1).strip() : "";
    }

    private static List<String> read(Path file) {
        try {
            if (Files.size(file) > LARGEST_TO_QUOTE) {
                return List.of();
            }
            return Files.readAllLines(file, StandardCharsets.ISO_8859_1);
        } catch (IOException e) {
            return List.of();
        }
    }
}

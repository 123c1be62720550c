package simpview.inspect;

import java.io.BufferedReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import simpview.scene.simp.SourcePlace;

/** The text of scene files' lines, read when a report names them (only the lines asked for are kept). */
final class SourceText {

    private final Map<SourcePlace, String> lines = new HashMap<>();

    /** The line, stripped; empty when it cannot be read. */
    String line(SourcePlace place) {
        return lines.computeIfAbsent(place, SourceText::read);
    }

    private static String read(SourcePlace place) {
        try (BufferedReader in = Files.newBufferedReader(place.file(), StandardCharsets.ISO_8859_1)) {
            String text = null;
            for (int k = 0; k < place.line(); k++) {
                text = in.readLine();
                if (text == null) {
                    return "";
                }
            }
            return text == null ? "" : text.strip();
        } catch (IOException | RuntimeException e) {
            return "";
        }
    }

    /**
     * "page7.simp:6 › cubeline.simp:12 › cube.simp:7 polygon ...": each
     * place, the innermost with its command's text, and an .obj face's
     * {@code obj} command with its own.
     */
    String describe(List<SourcePlace> chain) {
        StringBuilder sb = new StringBuilder();
        for (int k = 0; k < chain.size(); k++) {
            SourcePlace p = chain.get(k);
            sb.append(k == 0 ? "" : " › ").append(p);
            boolean last = k == chain.size() - 1;
            boolean objCommand = !last && isObj(chain.get(k + 1).file());
            if (last || objCommand) {
                String text = line(p);
                if (!text.isEmpty()) {
                    sb.append(' ').append(text);
                }
            }
        }
        return sb.toString();
    }

    static boolean isObj(Path file) {
        return file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".obj");
    }
}

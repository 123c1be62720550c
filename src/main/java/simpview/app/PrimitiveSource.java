package simpview.app;

import java.nio.file.Path;

/**
 * Where one drawn primitive came from.
 *
 * @param file the scene file holding its command, or null (a page that is not a scene)
 * @param line the command's 1-based line, or 0
 * @param text the command as written, or a description
 * @param outline its projected vertices, panel x and y in turn (2 for a line, 3 for a triangle)
 */
record PrimitiveSource(Path file, int line, String text, double[] outline) {

    /** "page7.simp:118 polygon (...)", or the description alone. */
    String describe() {
        return file == null ? text : file.getFileName() + ":" + line + " " + text;
    }
}

package simpview.scene.simp;

import java.util.Locale;
import java.util.Map;

/**
 * Words other scene languages and graphics libraries give what a SIMP
 * command does, as students bring them along: C's {@code #include} and
 * Python's {@code import} for {@code file}, OpenGL's push and pop for the
 * brackets, "triangle" for {@code polygon}, and "//" to start a comment.
 * An unknown command that is one of them is told the SIMP word, which no
 * spelling near it would find.
 */
final class WordsElsewhere {

    private static final Map<String, String> SIMP_WORD = Map.ofEntries(
            Map.entry("include", "file"), Map.entry("import", "file"), Map.entry("load", "file"),
            Map.entry("source", "file"),
            Map.entry("push", "{"), Map.entry("pushmatrix", "{"), Map.entry("glpushmatrix", "{"),
            Map.entry("pop", "}"), Map.entry("popmatrix", "}"), Map.entry("glpopmatrix", "}"),
            Map.entry("triangle", "polygon"), Map.entry("tri", "polygon"), Map.entry("face", "polygon"),
            Map.entry("wireframe", "wire"), Map.entry("outline", "wire"), Map.entry("solid", "filled"),
            Map.entry("model", "obj"), Map.entry("mesh", "obj"), Map.entry("loadobj", "obj"),
            Map.entry("perspective", "camera"), Map.entry("frustum", "camera"),
            Map.entry("fog", "depth"), Map.entry("pointlight", "light"), Map.entry("material", "surface"),
            Map.entry("smooth", "gouraud' or 'phong"));

    private static final String COLOUR = " (a colour is no command: a vertex carries its own in its point, (x, y, z,"
            + " r, g, b), and in a lit scene surface r g b gives the colour of the vertices after it)";

    /** How other languages start a comment: C's and Java's, SQL's and Lua's, Lisp's and assembly's, TeX's. */
    private static final String[] COMMENT_MARKS = {"//", "/*", "--", ";", "%"};

    private WordsElsewhere() {
    }

    /**
     * " (SIMP's word for that is 'file')" when {@code word}, in any case, is
     * another language's word for a SIMP command; what a colour is for
     * "color" and "colour"; how a comment starts for a word that starts as
     * another language's comment ("//"); else "".
     */
    static String hint(String word) {
        for (String mark : COMMENT_MARKS) {
            if (word.startsWith(mark)) {
                return " (a comment starts with '#' here, not with '" + mark + "')";
            }
        }
        String lower = word.toLowerCase(Locale.ROOT);
        if (lower.equals("color") || lower.equals("colour") || lower.equals("rgb")) {
            return COLOUR;
        }
        String simp = SIMP_WORD.get(lower);
        return simp == null ? "" : " (SIMP's word for that is '" + simp + "')";
    }
}

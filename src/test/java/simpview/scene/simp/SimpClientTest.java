package simpview.scene.simp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.geometry.Camera;
import simpview.geometry.Matrix4;
import simpview.geometry.Vertex;
import simpview.scene.SceneException;

/** Transforms, the matrix stack and the style, through the real reader and client. */
class SimpClientTest {

    @TempDir
    Path dir;
    private SceneFixture scene;

    @BeforeEach
    void setUp() {
        scene = new SceneFixture(dir);
    }

    private static void assertPanelVertex(double wx, double wy, double wz, Vertex v) {
        assertEquals(Camera.PARALLEL.panelX(wx, wz), v.x(), 1e-12, "x");
        assertEquals(Camera.PARALLEL.panelY(wy, wz), v.y(), 1e-12, "y");
        assertEquals(wz, v.z(), 1e-12, "z");
    }

    private Matrix4 ctmAfter(String... lines) throws Exception {
        scene.write("s", lines);
        return scene.run("s").client.ctm();
    }

    @Test
    void rotateZQuarterTurnTakesXToY() throws Exception {
        Matrix4 m = ctmAfter("rotate Z 90");
        assertEquals(Vertex.of(0, 1, 0), m.apply(Vertex.of(1, 0, 0)));
    }

    @Test
    void rotateXQuarterTurnTakesYToZ() throws Exception {
        Matrix4 m = ctmAfter("rotate X 90");
        assertEquals(Vertex.of(0, 0, 1), m.apply(Vertex.of(0, 1, 0)));
    }

    @Test
    void rotateYQuarterTurnTakesZToX() throws Exception {
        Matrix4 m = ctmAfter("rotate Y 90");
        assertEquals(Vertex.of(1, 0, 0), m.apply(Vertex.of(0, 0, 1)));
    }

    @Test
    void transformsComposeOnTheRight() throws Exception {
        // CTM = T * S: the scale acts on the point first, then the translation.
        scene.write("s", "translate 10 0 -5", "scale 2 3 4", "line (1, 1, -1) (0, 0, 0)");
        scene.run("s");
        assertEquals(1, scene.lines.size());
        assertPanelVertex(12, 3, -9, scene.lines.get(0)[0]);
        assertPanelVertex(10, 0, -5, scene.lines.get(0)[1]);
    }

    @Test
    void braceRestoresTheCtm() throws Exception {
        scene.write("s", "translate 0 0 -10", "{", "\ttranslate 50 0 0", "\tscale 2 2 2", "\tline (1,0,0) (0,1,0)",
                "}", "line (1,0,0) (0,1,0)");
        scene.run("s");
        assertPanelVertex(52, 0, -10, scene.lines.get(0)[0]);
        assertPanelVertex(1, 0, -10, scene.lines.get(1)[0]);
        assertEquals(Matrix4.translation(0, 0, -10), scene.client.ctm());
    }

    @Test
    void unmatchedCloseBraceIsAnError() throws Exception {
        scene.write("s", "{", "}", "  }");
        SceneException e = scene.failure("s");
        assertEquals(3, e.line());
        assertEquals(3, e.column());
        assertEquals("'}' has no '{' to match: the matrix stack is empty", e.problem());
        assertEquals("  }", e.lineText());
    }

    /**
     * A transform whose CTM overflows the doubles is an error at that command: otherwise every point after it
     * is Infinity or NaN and the picture is silently blank. Scales back down do not bring it back (Infinity
     * times 1e-200 is Infinity), so the error is at the command that overflowed, in an included file too.
     */
    @Test
    void aTransformThatOverflowsTheCtmIsAnErrorWhereItStands() throws Exception {
        scene.write("big", "scale 1e200 1e200 1e200", "  scale 1e200 1e200 1e200", "scale 1e-200 1e-200 1e-200",
                "polygon (-50,-50,-10)(50,-50,-10)(0,50,-10)");
        SceneException e = scene.failure("big");
        assertEquals(2, e.line());
        assertEquals(3, e.column());
        assertEquals("the transform overflows: after this scale the matrix holds Infinity, beyond the largest number a"
                + " double holds (about 1.8e308), so every point it transformed would be lost: make its scales and"
                + " translations smaller", e.problem());
        scene.write("far", "translate 1e308 0 0", "translate -1e308 0 0", "translate 1e308 0 0", "translate 1e308 0 0");
        scene.write("s", "{", "file far", "}");
        e = scene.failure("s");
        assertEquals(4, e.line());
        assertEquals(1, e.column());
        assertEquals("s.simp:2", e.includedFrom());
        assertTrue(e.problem().startsWith("the transform overflows: after this translate the matrix holds Infinity,"),
                e.problem());
        // Two products that overflow opposite ways in one entry make a NaN and no Infinity: named as such.
        scene.write("turned", "scale 1e300 1 1", "rotate Z 45", "translate 1e10 1e10 0");
        assertTrue(scene.failure("turned").problem().startsWith("the transform overflows: after this translate the"
                + " matrix holds NaN (Infinity minus Infinity), beyond"));
        // Large but finite: drawn.
        scene.write("fine", "scale 1e200 1e200 1e200", "scale 1e100 1e100 1e100", "scale 1e-300 1e-300 1e-300",
                "polygon (-50,-50,-10)(50,-50,-10)(0,50,-10)");
        scene.run("fine");
        assertEquals(1, scene.filled.size());
    }

    /**
     * A vertex whose numbers are finite but that a finite CTM takes beyond the doubles is not drawn, and the
     * scene says so, naming the first such primitive and how many more there were; the rest is drawn.
     */
    @Test
    void aVertexTheCtmTakesBeyondTheDoublesIsNamedAndNotDrawn() throws Exception {
        scene.write("s", "polygon (-50,-50,-10)(50,-50,-10)(0,50,-10)", "scale 10 1 1",
                "polygon (-50,-50,-10)(1e308,-50,-10)(0,50,-10)", "line (0,0,-10)(1e308,0,-10)",
                "line (0,0,-10)(1,1,-10)");
        scene.run("s");
        assertEquals(1, scene.filled.size());
        assertEquals(1, scene.lines.size());
        // a depth-cued scene has no camera, so no camera space
        assertEquals(List.of("s.simp:3 polygon: a vertex comes out infinite or NaN after the transforms (its numbers"
                + " are finite, but the CTM takes them beyond about 1.8e308), so this primitive was not drawn, nor 1 more"
                + " like it"), scene.warnings);
    }

    /**
     * A vertex finite after the transforms but too far out for the panel's scale (650 pixels to 200 units
     * overflows beyond about 2.7e305), or a filled triangle whose area there overflows (some 1e154 across), was
     * dropped by the rasterizers without a word; the scene names the first and counts the rest, and still draws
     * a triangle as far out whose area fits and a wire one whose only lines are drawn.
     */
    @Test
    void aVertexTooFarOutForThePanelIsNamedAndNotDrawn() throws Exception {
        scene.write("s", "line (0,0,-10)(1,1,-10)", "line (-3e305 0 -10) (50 50 -10)",
                "polygon (-1e200,-1e200,-10) (1e200,-1e200,-10) (0,1e200,-10)",
                "polygon (-1e305,-50,-10) (50,-50,-10) (0,50,-10)", "wire",
                "polygon (-1e200,-1e200,-10) (1e200,-1e200,-10) (0,1e200,-10)");
        scene.run("s");
        assertEquals(1, scene.lines.size());
        assertEquals(1, scene.filled.size(), "the 1e305 triangle's area fits");
        assertEquals(1, scene.wire.size());
        assertEquals(List.of("s.simp:2 line: a vertex lies too far out to draw: its numbers and the CTM's are"
                + " finite, but its panel coordinates (650 pixels to 200 units), or the filled triangle's area there,"
                + " go beyond about 1.8e308, so this primitive was not drawn, nor 1 more like it"), scene.warnings);
    }

    @Test
    void unclosedBraceIsOnlyAWarning() throws Exception {
        scene.write("s", "{", "{", "}", "line (0,0,-1) (1,1,-1)");
        scene.run("s");
        assertEquals(1, scene.lines.size());
        assertEquals(List.of("s.simp:1: '{' never closed by the end of the scene"), scene.warnings);
    }

    /** The warning names the file and line of the outermost '{' left open, in an included file too. */
    @Test
    void anUnclosedBraceIsNamedWhereItStands() throws Exception {
        scene.write("inner", "# opens three, closes one", "{", "{", "{", "line (0,0,-1) (1,1,-1)", "}");
        scene.write("s", "{", "}", "file inner");
        scene.run("s");
        assertEquals(List.of("inner.simp:2: '{' never closed by the end of the scene, nor the 1 opened after it"),
                scene.warnings);
    }

    /**
     * An included file whose last '}' is missing: the including file's '}' closes the included file's '{', the
     * CTM after it is not the one meant, and the '{' left open at the end is the including file's, which is
     * closed as written. The warning names the included file's '{' and the '}' that closed it.
     */
    @Test
    void anIncludedFileThatLeavesABraceOpenIsNamed() throws Exception {
        Files.createDirectories(dir.resolve("parts"));
        scene.write("parts/open", "{", "  translate 3 0 0", "  line (0,0,-1) (1,1,-1)");
        scene.write("s", "{", "  translate 0 0 -10", "  file \"parts/open\"", "}", "line (0,0,-1) (1,1,-1)");
        scene.run("s");
        assertEquals(List.of("parts/open.simp:1: this '{' is still open at the end of parts/open.simp, so the '}' at"
                + " s.simp:4 closes it, not the '{' it was written for: each file closes the '{' it opens; is a '}'"
                + " missing at the end of parts/open.simp?", "s.simp:1: '{' never closed by the end of the scene"), scene.warnings);
        assertPanelVertex(0, 0, -11, scene.lines.get(1)[0]);
    }

    /** An included file with a '}' too many closes the including file's '{': the error that follows says so. */
    @Test
    void anIncludedFileThatClosesTheIncludersBraceIsNamed() throws Exception {
        scene.write("extra", "{", "line (0,0,-1) (1,1,-1)", "}", "}");
        scene.write("s", "{", "file extra", "line (0,0,-1) (1,1,-1)", "}");
        SceneException e = scene.failure("s");
        assertEquals(4, e.line());
        assertEquals("'}' has no '{' to match: the matrix stack is empty (extra.simp:4: this '}' closes the '{' at"
                + " s.simp:1, opened before extra.simp was included, so the '}' written for that '{' closes another,"
                + " or none: each file closes the '{' it opens; is this '}' one too many?)", e.problem());
        // braces that match within each file, a file included twice, say nothing
        scene.write("fine", "{", "line (0,0,-1) (1,1,-1)", "}");
        scene.write("s", "{", "file fine", "file fine", "}", "{", "{", "file fine", "}", "}");
        scene.run("s");
        assertEquals(List.of(), scene.warnings);
    }

    @Test
    void styleStartsFilledAndIsNotSavedByBraces() throws Exception {
        scene.write("s", "polygon (0,0,-1) (1,0,-1) (0,1,-1)", "{", "wire", "}", "polygon (0,0,-1) (1,0,-1) (0,1,-1)");
        scene.run("s");
        assertEquals(1, scene.filled.size());
        assertEquals(1, scene.wire.size());
        assertEquals(SimpClient.Style.WIRE, scene.client.style());
    }

    @Test
    void styleCrossesFileBoundariesBothWays() throws Exception {
        scene.write("setwire", "wire");
        scene.write("draw", "polygon (0,0,-1) (1,0,-1) (0,1,-1)", "filled");
        scene.write("s", "file \"setwire\"", "polygon (0,0,-1) (1,0,-1) (0,1,-1)", "wire", "file draw",
                "polygon (0,0,-1) (1,0,-1) (0,1,-1)");
        scene.run("s");
        assertEquals(2, scene.wire.size(), "the style set inside setwire.simp holds after it; draw.simp inherits wire");
        assertEquals(1, scene.filled.size(), "the 'filled' at the end of draw.simp holds after it");
    }

    @Test
    void includedFileDrawsWithTheCtmOfTheIncludingLine() throws Exception {
        scene.write("unit", "line (1,0,0) (0,0,0)");
        scene.write("s", "translate 0 0 -20", "{", "scale 5 5 5", "file \"unit\"", "}", "file unit");
        scene.run("s");
        assertPanelVertex(5, 0, -20, scene.lines.get(0)[0]);
        assertPanelVertex(1, 0, -20, scene.lines.get(1)[0]);
    }

    @Test
    void includedFileIsFoundBesideTheIncludingFile() throws Exception {
        Files.createDirectories(dir.resolve("parts/deeper"));
        scene.write("parts/deeper/leaf", "line (0,0,-1) (1,1,-1)");
        scene.write("parts/mid", "file \"deeper/leaf\"");
        scene.write("s", "file \"parts/mid\"");
        scene.run("s");
        assertEquals(1, scene.lines.size());
    }

    @Test
    void coloursTravelWithTheirVertices() throws Exception {
        scene.write("s", "line (0,0,-1) (1,0,0) (10,0,-1) (0,0.5,1)", "line (0,0,-1) (10,0,-1)");
        scene.run("s");
        Vertex[] coloured = scene.lines.get(0);
        assertEquals(1, coloured[0].r());
        assertEquals(0, coloured[0].g());
        assertEquals(0.5, coloured[1].g());
        Vertex plain = scene.lines.get(1)[1];
        assertEquals(1, plain.r());
        assertEquals(1, plain.g());
        assertEquals(1, plain.b());
    }

    @Test
    void tenThousandNestedBracesWork() throws Exception {
        int depth = 10_000;
        String[] lines = new String[2 * depth + 2];
        for (int i = 0; i < depth; i++) {
            lines[i] = "{";
            lines[depth + 2 + i] = "}";
        }
        lines[depth] = "translate 1 0 0";
        lines[depth + 1] = "line (0,0,-1) (1,0,-1)";
        scene.write("s", lines);
        scene.run("s");
        assertEquals(1, scene.lines.size());
        assertEquals(Matrix4.identity(), scene.client.ctm());
        assertTrue(scene.warnings.isEmpty());
    }

    @Test
    void bracesNestAcrossTenThousandTranslations() throws IOException, SceneException {
        StringBuilder body = new StringBuilder();
        for (int i = 0; i < 10_000; i++) {
            body.append("{\ntranslate 0.001 0 0\n");
        }
        body.append("line (0,0,-1) (0,0,-2)\n");
        body.append("}\n".repeat(10_000));
        Files.writeString(dir.resolve("s.simp"), body);
        scene.run("s");
        assertPanelVertex(10, 0, -1, scene.lines.get(0)[0]);
        assertEquals(Matrix4.identity(), scene.client.ctm());
    }
}

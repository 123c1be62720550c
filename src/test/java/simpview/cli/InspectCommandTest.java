package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code simpview inspect}: its JSON read back by a parser of the test's own, its text, and its errors. */
class InspectCommandTest {

    private static final Set<String> OUTCOMES = Set.of("written", "depth-failed", "scissored", "clipped", "culled",
            "blended");

    @TempDir
    Path dir;

    private Path write(String name, String text) throws Exception {
        Path file = dir.resolve(name);
        Files.writeString(file, text);
        return file;
    }

    @Test
    @SuppressWarnings("unchecked")
    void jsonOfADepthCuedScene() throws Exception {
        write("leaf.simp", "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n");
        Path scene = write("top.simp", "polygon (-90, -90, -100) (90, -90, -100) (0, 90, -100)\nfile \"leaf\"\n"
                + "polygon (-90, -90, -190) (90, -90, -190) (0, 90, -190)\n");
        CliRun run = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,300", "--json");
        assertEquals(0, run.exitCode(), run.err());
        Map<String, Object> json = (Map<String, Object>) new MiniJson(run.out().strip()).value();
        Map<String, Object> pixel = (Map<String, Object>) json.get("pixel");
        assertEquals(325.0, pixel.get("x"));
        assertEquals(300.0, pixel.get("y"));
        List<Object> rgb = (List<Object>) pixel.get("rgb");
        assertEquals(3, rgb.size());
        double depth = (Double) pixel.get("depth");
        assertEquals(-10, depth, 1e-9);
        List<Object> history = (List<Object>) json.get("history");
        assertEquals(3, history.size());
        List<String> outcomes = new ArrayList<>();
        for (Object o : history) {
            Map<String, Object> e = (Map<String, Object>) o;
            assertTrue(OUTCOMES.contains(e.get("outcome")), "outcome " + e.get("outcome"));
            outcomes.add((String) e.get("outcome"));
            assertTrue(e.containsKey("primitive") && e.containsKey("z") && e.containsKey("rgb"));
        }
        assertEquals(List.of("written", "written", "depth-failed"), outcomes);
        Map<String, Object> second = (Map<String, Object>) history.get(1);
        assertEquals(List.of("top.simp:2", "leaf.simp:1"), second.get("chain"));
        assertEquals(2.0, second.get("primitive"));
        Map<String, Object> explain = (Map<String, Object>) json.get("explain");
        assertEquals(rgb, explain.get("final_rgb"));
        assertEquals(rgb, second.get("rgb"));
    }

    /**
     * A triangle turned about Y, its middle column at z = -100 exactly: cued
     * 0.5, which is 127.5 and rounds to 128, but the span's level came out
     * 127.49999999999999 and the pixel 127. The explanation used to show
     * t 0.5 and cued 0.5 beside a final 127 with no word why; it now says.
     */
    @Test
    void explainSaysWhyALevelOnATieRoundedTheOtherWay() throws Exception {
        Path scene = write("turned.simp", "translate 50 -50 -100\nrotate Y 45\n"
                + "polygon (-30, -30, 0) (30, -30, 0) (0, 30, 0)\n");
        CliRun run = CliRun.of("inspect", "--scene", scene.toString(), "--at", "487,251", "--explain");
        assertEquals(0, run.exitCode(), run.err());
        assertTrue(run.out().contains("final_rgb: (127, 127, 127)"), run.out());
        assertTrue(run.out().contains("note: cued * 255 = 127.5 would round to 128, but the level written is"
                + " 127.49999999999999"), run.out());
        CliRun plain = CliRun.of("inspect", "--scene", scene.toString(), "--at", "487,200", "--explain");
        assertFalse(plain.out().contains("note:"), plain.out());
    }

    /**
     * A pixel of a scene in its vertices' own colours, as render --own-colors
     * draws it: the red corner's colour, not the depth cue's grey. inspect
     * had no --own-colors, so it explained another picture than the one drawn.
     */
    @Test
    void aPixelInTheVerticesOwnColours() throws Exception {
        Path scene = write("red.simp", "polygon (-80, -80, -100, 1, 0, 0) (80, -80, -100, 1, 0, 0) (0, 80, -100, 1, 0, 0)\n");
        CliRun own = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,300", "--own-colors", "--explain");
        assertEquals(0, own.exitCode(), own.err());
        assertTrue(own.out().contains("rgb (255, 0, 0)"), own.out());
        assertTrue(own.out().contains("the vertices' own colours, interpolated (no depth cue)"), own.out());
        CliRun cued = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,300");
        assertTrue(cued.out().contains("rgb (128, 128, 128)"), cued.out());
        CliRun lit = CliRun.of("inspect", "--scene", write("lit.simp", "camera -1 -1 1 1 -1 -100\n").toString(),
                "--at", "1,1", "--own-colors");
        assertEquals(ExitCode.USAGE_ERROR, lit.exitCode(), lit.out());
        assertTrue(lit.err().contains("--own-colors is for depth-cued scenes"), lit.err());
    }

    @Test
    @SuppressWarnings("unchecked")
    void jsonOfALitScene() throws Exception {
        Path scene = write("lit.simp", "camera -1 -1 1 1 -1 -100\nambient 0.2 0.2 0.2\n{\ntranslate 0 10 0\n"
                + "light 1 1 1 1 0\n}\npolygon (-5, -5, -10) (5, -5, -10) (0, 5, -10)\n");
        CliRun run = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,325", "--explain", "--json");
        assertEquals(0, run.exitCode(), run.err());
        Map<String, Object> json = (Map<String, Object>) new MiniJson(run.out().strip()).value();
        Map<String, Object> explain = (Map<String, Object>) json.get("explain");
        assertEquals("phong", explain.get("shading"));
        assertEquals(1, ((List<Object>) explain.get("lights")).size());
        assertEquals(((Map<String, Object>) json.get("pixel")).get("rgb"), explain.get("final_rgb"));
        assertFalse(json.containsKey("history"), "--explain alone leaves the history out");
    }

    @Test
    void textNamesTheChainAndTheVertices() throws Exception {
        write("leaf.simp", "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n");
        Path scene = write("top.simp", "# top\nfile leaf\n");
        CliRun run = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,300");
        assertEquals(0, run.exitCode(), run.err());
        assertTrue(run.out().contains("drawn by primitive 1: top.simp:2 › leaf.simp:1 polygon"), run.out());
        assertTrue(run.out().contains("history: 1 write attempted"), run.out());
        assertTrue(run.out().contains("vertices of primitive 1:"), run.out());
        assertTrue(run.out().contains("final_rgb: "), run.out());
    }

    /**
     * --vertices --primitive N names the command N is, with its include
     * chain, as the history names a write: on the command line nothing else
     * tells which triangle N is when it made no write at the pixel.
     */
    @Test
    void theVertexTableNamesItsPrimitivesCommand() throws Exception {
        write("leaf.simp", "polygon (-90, -90, -20) (-80, -90, -20) (-85, -80, -20)\n");
        Path scene = write("top.simp", "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\nfile leaf\n");
        CliRun text = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,300", "--vertices", "--primitive", "2");
        assertEquals(0, text.exitCode(), text.err());
        assertTrue(text.out().contains("vertices of primitive 2:\n  primitive: 2\n  command: top.simp:2 › leaf.simp:1 "
                + "polygon (-90, -90, -20) (-80, -90, -20) (-85, -80, -20)\n"), text.out());
        CliRun json = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,300", "--vertices", "--primitive", "2",
                "--json");
        assertTrue(json.out().contains("\"vertices\": {\"primitive\": 2, \"command\": \"top.simp:2 › leaf.simp:1 polygon"),
                json.out());
    }

    @Test
    void aPrimitiveByItsNumberAndOneTheSceneHasNot() throws Exception {
        Path scene = write("two.simp", "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n"
                + "polygon (-90, -90, -20) (-80, -90, -20) (-85, -80, -20)\n");
        CliRun second = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,300", "--vertices", "--primitive", "2");
        assertEquals(0, second.exitCode(), second.err());
        assertTrue(second.out().contains("vertices of primitive 2:"), second.out());
        assertTrue(second.out().contains("written: (-90, -90, -20)"), second.out());
        CliRun none = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,300", "--vertices", "--primitive", "3");
        assertEquals(ExitCode.USAGE_ERROR, none.exitCode(), none.out());
        assertTrue(none.err().startsWith("simpview: --primitive 3: the scene has no primitive 3"), none.err());
        assertEquals("", none.out());
        // a scene that stops at an error before the primitive asked for says so, not that it has none
        Path broken = write("broken.simp", "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n"
                + "polygon (1, 2, 3) (4, 5, 6)\n");
        CliRun stopped = CliRun.of("inspect", "--scene", broken.toString(), "--at", "325,300", "--vertices",
                "--primitive", "2");
        assertEquals(ExitCode.SCENE_ERROR, stopped.exitCode(), stopped.err());
        assertTrue(stopped.err().startsWith("--primitive 2: the scene stops at an error before its primitive 2:"),
                stopped.err());
        assertTrue(stopped.err().contains("broken.simp:2:"), stopped.err());
        CliRun zero = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,300", "--vertices", "--primitive", "0");
        assertEquals(ExitCode.USAGE_ERROR, zero.exitCode(), zero.err());
    }

    /**
     * Two lit triangles at the centre: the first, red, at z = -20; the
     * second, nearer, at z = -10, green. With ambient 1 and no light each is
     * its own kd. --explain --primitive 1 works out the red write that the
     * green one covered; a primitive that made no write there says so.
     */
    @Test
    void theExplanationOfAWriteThatDidNotStay() throws Exception {
        Path scene = write("lit.simp", "camera -1 -1 1 1 -1 -100\nambient 1 1 1\n"
                + "surface 1 0 0\npolygon (-10, -10, -20) (10, -10, -20) (0, 10, -20)\n"
                + "surface 0 1 0\npolygon (-5, -5, -10) (5, -5, -10) (0, 5, -10)\n"
                + "polygon (5, 5, -10) (6, 5, -10) (5.5, 6, -10)\n");
        CliRun first = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,320", "--explain", "--primitive", "1");
        assertEquals(0, first.exitCode(), first.err());
        assertTrue(first.out().contains("explain (primitive 1, written here, under primitive 2, the pixel's):\n"),
                first.out());
        assertTrue(first.out().contains("  kd: (1, 0, 0)\n"), first.out());
        assertTrue(first.out().contains("  final_rgb: (255, 0, 0)\n"), first.out());
        assertTrue(first.out().contains("rgb (0, 255, 0)"), "the pixel is the green one's: " + first.out());
        CliRun json = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,320", "--explain", "--primitive", "1",
                "--json");
        assertEquals(0, json.exitCode(), json.err());
        assertTrue(json.out().contains("\"explained\": {\"primitive\": 1, \"outcome\": \"written\"}, \"explain\": {\"z\": -20"),
                json.out());
        CliRun none = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,320", "--explain", "--primitive", "3");
        assertEquals(0, none.exitCode(), none.err());
        assertTrue(none.out().contains("explain (primitive 3): it made no write at this pixel"), none.out());
        CliRun owner = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,320", "--explain", "--primitive", "2");
        assertTrue(owner.out().contains("explain (primitive 2):\n"), "the owner's, as without --primitive: " + owner.out());
    }

    /**
     * A write the depth test threw away in a scene drawn in its own colours
     * came with its vertices' colour, not the depth cue's: the explanation
     * says so, as the history gives it.
     */
    @Test
    void aLostWriteInOwnColoursIsNotCalledTheCuesColour() throws Exception {
        Path scene = write("own.simp", "polygon (-50, -50, -50, 0, 0, 1) (50, -50, -50, 0, 0, 1) (0, 50, -50, 0, 0, 1)\n"
                + "polygon (-50, -50, -60, 1, 1, 0) (50, -50, -60, 1, 1, 0) (0, 50, -60, 1, 1, 0)\n");
        CliRun own = CliRun.of("inspect", "--scene", scene.toString(), "--own-colors", "--at", "325,300", "--explain",
                "--primitive", "2");
        assertEquals(0, own.exitCode(), own.err());
        assertTrue(own.out().contains("explain (primitive 2, depth-failed here, under primitive 1, the pixel's): "
                + "rgb (255, 255, 0), its vertices' own colours at the pixel; not worked out term by term"), own.out());
        assertFalse(own.out().contains("depth cue"), own.out());
        CliRun cued = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,300", "--explain",
                "--primitive", "2");
        assertTrue(cued.out().contains("), the depth cue's colour at its depth; not worked out"), cued.out());
    }

    /**
     * A write the scissor dropped (z beyond 0) was made at the pixel:
     * --explain --primitive says what became of it, as the history does, not
     * that the primitive made no write there while its vertex table says it
     * covers the pixel.
     */
    @Test
    void aScissoredWriteIsExplainedAsOne() throws Exception {
        Path scene = write("near.simp", "polygon (-50, -50, 20) (50, -50, 20) (0, 50, -20)\n"
                + "polygon (60, 60, -10) (70, 60, -10) (65, 70, -10)\n");
        CliRun text = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,200", "--explain",
                "--primitive", "1");
        assertEquals(0, text.exitCode(), text.err());
        assertTrue(text.out().contains("explain (primitive 1, scissored here): z 15."), text.out());
        assertTrue(text.out().contains("outside the view's depth range (z 0 to -200), so it never reached the "
                + "z-buffer"), text.out());
        CliRun json = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,200", "--explain",
                "--primitive", "1", "--json");
        assertTrue(json.out().contains("\"explained\": {\"primitive\": 1, \"outcome\": \"scissored\"}, \"explain\": null"),
                json.out());
        CliRun none = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,200", "--explain",
                "--primitive", "2");
        assertTrue(none.out().contains("explain (primitive 2): it made no write at this pixel"), none.out());
    }

    /**
     * --own-colors does nothing to the first assignment's pages: inspect
     * refuses it there, as render and compare do, instead of taking it
     * without a word.
     */
    @Test
    void ownColoursWithTheFirstAssignmentIsAUsageError() {
        CliRun run = CliRun.of("inspect", "--assignment", "1", "--page", "4", "--at", "200,550", "--own-colors");
        assertEquals(ExitCode.USAGE_ERROR, run.exitCode(), run.out() + run.err());
        assertTrue(run.err().startsWith("simpview: --own-colors goes with --scene only"), run.err());
        assertFalse(run.showsStackTrace(), run.err());
    }

    /** The warning of a depth-cued scene's unused vertex colours names the option, as render's does, not a Java method. */
    @Test
    void theOwnColoursWarningNamesTheOption() throws Exception {
        Path scene = write("coloured.simp", "polygon (-50, -50, -50, 1, 0, 0) (50, -50, -50, 1, 0, 0) (0, 50, -50, 1, 0, 0)\n");
        CliRun run = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,300");
        assertEquals(0, run.exitCode(), run.err());
        assertTrue(run.err().contains("--own-colors (render, compare, check, inspect)"), run.err());
        assertFalse(run.err().contains("withOwnColours"), run.err());
    }

    @Test
    void aCulledPrimitiveIsNoWriteAndADepthCuedOneIsCulledByItsBox() throws Exception {
        Path scene = write("behind.simp", "polygon (0 0 10) (50 0 10) (0 50 10)\n");
        CliRun run = CliRun.of("inspect", "--scene", scene.toString(), "--at", "400,400", "--history");
        assertEquals(0, run.exitCode(), run.err());
        assertTrue(run.out().contains("history: 0 writes attempted, and 1 primitive culled or clipped that would "
                + "have covered the pixel, in drawing order"), run.out());
        assertTrue(run.out().contains("culled: every vertex beyond the view box's near side (z = 0); seen straight "
                + "down z, it covers the pixel"), run.out());
    }

    @Test
    void aPixelOutsideThePanelIsAUsageError() throws Exception {
        Path scene = write("s.simp", "polygon (0, 0, -1) (1, 0, -1) (0, 1, -1)\n");
        for (String at : new String[] {"650,10", "-1,3", "3", "a,b"}) {
            CliRun run = CliRun.of("inspect", "--scene", scene.toString(), "--at", at);
            assertEquals(2, run.exitCode(), at);
            assertTrue(run.err().contains("--at"), run.err());
            assertFalse(run.showsStackTrace(), run.err());
        }
        CliRun outside = CliRun.of("inspect", "--scene", scene.toString(), "--at", "650,10");
        assertTrue(outside.err().contains("--at '650,10' is outside the panel: x is 650, and x and y are 0 to 649"),
                outside.err());
        // A whole number too large for an int is still a place outside the panel, not "not a number".
        for (String far : new String[] {"99999999999,1", "1,-99999999999999999999"}) {
            CliRun run = CliRun.of("inspect", "--scene", scene.toString(), "--at", far);
            assertEquals(2, run.exitCode(), far);
            assertTrue(run.err().contains("--at '" + far + "' is outside the panel"), run.err());
        }
        // Digits of another script are the numbers they are, as in every number option: full-width 3 is 3.
        CliRun wide = CliRun.of("inspect", "--scene", scene.toString(), "--at", "\uFF13,4");
        assertEquals(0, wide.exitCode(), wide.err());
        assertTrue(wide.out().contains("(3, 4)"), wide.out());
        // The pixel as the inspector writes it, and as the window's Go to pixel takes it, is one too.
        for (String at : new String[] {"(3, 4)", "3 4"}) {
            CliRun pair = CliRun.of("inspect", "--scene", scene.toString(), "--at", at);
            assertEquals(0, pair.exitCode(), pair.err());
            assertTrue(pair.out().startsWith("pixel (3, 4) of the panel"), pair.out());
        }
        CliRun half = CliRun.of("inspect", "--scene", scene.toString(), "--at", "(3, 4");
        assertEquals(2, half.exitCode(), half.err());
        assertTrue(half.err().contains("--at '(3, 4' is not a pixel: its '(' is not closed; give x and y, two whole "
                + "numbers in panel coordinates"), half.err());
    }

    @Test
    void depthCueColoursForALitSceneAreAUsageError() throws Exception {
        Path scene = write("lit.simp", "camera -1 -1 1 1 -1 -100\npolygon (-5, -5, -10) (5, -5, -10) (0, 5, -10)\n");
        CliRun run = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,325", "--near-color", "0,1,0");
        assertEquals(2, run.exitCode(), run.err());
        assertTrue(run.err().contains("is lit (lit.simp:1 camera)"), run.err());
    }

    /**
     * A scene that stops with an error is inspected as far as the error, as
     * the page shows it drawn that far: the history, then the error (exit 1).
     * Of two writes at one depth the second fails, and the text says why.
     */
    @Test
    @SuppressWarnings("unchecked")
    void aSceneWithAnErrorIsInspectedAsFarAsTheError() throws Exception {
        Path scene = write("broken.simp", "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n"
                + "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\nbogus 1 2\n");
        CliRun text = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,325", "--history");
        assertEquals(ExitCode.SCENE_ERROR, text.exitCode(), text.err());
        assertTrue(text.out().contains("history: 2 writes attempted"), text.out());
        assertTrue(text.out().contains("stored depth -10 of primitive 1, as deep: a write must be strictly nearer, "
                + "so the first of the two stays"), text.out());
        assertTrue(text.out().contains("the scene stops with an error here, as the page does, so the history ends:\n"
                + "  " + scene + ":3:1: unknown command 'bogus'"), text.out());
        CliRun json = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,325", "--json");
        assertEquals(ExitCode.SCENE_ERROR, json.exitCode());
        Map<String, Object> parsed = (Map<String, Object>) new MiniJson(json.out().strip()).value();
        assertTrue(((String) parsed.get("error")).startsWith(scene + ":3:1: unknown command 'bogus'"), json.out());
        assertEquals(2, ((List<Object>) parsed.get("history")).size());
        assertTrue(json.err().contains("unknown command 'bogus'"), json.err());
        Map<String, Object> whole = (Map<String, Object>) new MiniJson(CliRun.of("inspect", "--scene",
                write("whole.simp", "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n").toString(), "--at",
                "325,325", "--json").out().strip()).value();
        assertTrue(whole.containsKey("error") && whole.get("error") == null, "a scene drawn to its end: error null");
    }

    /** A vertex too far out for an int pixel is said so, not printed as -2147483648; --page names its 4 to 8. */
    @Test
    void aVertexFarOutsideAndAPageBeyondTheScenes() throws Exception {
        Path scene = write("far.simp", "polygon (-1e300, -50, -10) (50, -50, -10) (0, 50, -10)\n");
        CliRun run = CliRun.of("inspect", "--scene", scene.toString(), "--at", "325,325", "--vertices");
        assertEquals(0, run.exitCode(), run.err());
        assertTrue(run.out().contains("pixel: none: too far outside the panel to name"), run.out());
        assertFalse(run.out().contains("-2147483648"), run.out());
        CliRun page = CliRun.of("inspect", "--page", "9", "--at", "10,10");
        assertEquals(ExitCode.USAGE_ERROR, page.exitCode());
        assertTrue(page.err().contains("--page must be 4 to 8 (the pages drawn from scene files), not 9"), page.err());
    }

    @Test
    void pagesThatAreNotScenesAndMissingScenes() throws Exception {
        CliRun page = CliRun.of("inspect", "--page", "2", "--at", "10,10");
        assertEquals(2, page.exitCode());
        assertTrue(page.err().contains("inspect reads pages 4 to 8 and scenes"), page.err());
        CliRun missing = CliRun.of("inspect", "--scene", dir.resolve("none.simp").toString(), "--at", "10,10");
        assertEquals(1, missing.exitCode());
        assertTrue(missing.err().contains("none.simp"), missing.err());
        assertFalse(missing.showsStackTrace(), missing.err());
        Path empty = Files.createDirectories(dir.resolve("empty"));
        CliRun course = CliRun.of("inspect", "--page", "7", "--simp-dir", empty.toString(), "--at", "325,400");
        assertEquals(1, course.exitCode());
        assertTrue(course.err().contains("page7.simp was not found in " + empty.toAbsolutePath().normalize()
                + "; name the folder of the course's scene files with --simp-dir DIR"), course.err());
    }

    @Test
    @SuppressWarnings("unchecked")
    void theFirstAssignmentsPagesInPageCoordinates() throws Exception {
        // Page 1's antialiased panel (4): its centre, panel pixel (150, 150), is image column 550, row 549.
        CliRun run = CliRun.of("inspect", "--assignment", "1", "--page", "1", "--at", "550,200", "--json");
        assertEquals(0, run.exitCode(), run.err());
        Map<String, Object> json = (Map<String, Object>) new MiniJson(run.out().strip()).value();
        Map<String, Object> panel = (Map<String, Object>) json.get("panel");
        assertEquals(4.0, panel.get("number"));
        assertEquals("antialiased", panel.get("drawer"));
        assertEquals(150.0, panel.get("x"));
        assertEquals(150.0, panel.get("y"));
        List<Object> history = (List<Object>) json.get("history");
        assertEquals(90, history.size());
        Map<String, Object> last = (Map<String, Object>) history.get(history.size() - 1);
        assertEquals("blended", last.get("outcome"));
        assertTrue((Double) last.get("coverage") > 0);
        assertEquals(((Map<String, Object>) json.get("pixel")).get("rgb"), last.get("new"));
        assertEquals(List.of(150.0, 150.0), ((List<Object>) last.get("vertices")).get(0));
        CliRun text = CliRun.of("inspect", "--assignment", "1", "--page", "5", "--at", "250,560");
        assertEquals(0, text.exitCode(), text.err());
        assertTrue(text.out().contains("panel 1 (ghost (white, opacity 0.14))"), text.out());
        assertTrue(text.out().contains("blended with coverage 0.140000, rgb (255, 255, 255)"), text.out());
        // The 92-degree spoke (line 24) in the Bresenham panel (2), at panel pixel (146, 275): SPEC's rule
        // (the rounded ends) has moved to column 145 at row 272; the course's (the given ends) moves at row 279.
        CliRun bySpec = CliRun.of("inspect", "--assignment", "1", "--page", "1", "--at", "546,675", "--json");
        Map<String, Object> spec = (Map<String, Object>) new MiniJson(bySpec.out().strip()).value();
        assertEquals("spec", spec.get("rule"));
        assertEquals("Bresenham", ((Map<String, Object>) spec.get("panel")).get("drawer"));
        assertEquals(List.of(), spec.get("history"));
        CliRun byCourse = CliRun.of("inspect", "--assignment", "1", "--page", "1", "--at", "546,675", "--a1-rule",
                "course", "--json");
        Map<String, Object> course = (Map<String, Object>) new MiniJson(byCourse.out().strip()).value();
        assertEquals("course", course.get("rule"));
        assertEquals("Bresenham (the course's pictures' rule)", ((Map<String, Object>) course.get("panel")).get("drawer"));
        List<Object> spoke = (List<Object>) course.get("history");
        assertEquals(1, spoke.size());
        assertEquals(24.0, ((Map<String, Object>) spoke.get(0)).get("primitive"));
        assertEquals(2, CliRun.of("inspect", "--page", "5", "--at", "3,3", "--a1-rule", "course").exitCode(),
                "--a1-rule is for the first assignment");
        CliRun off = CliRun.of("inspect", "--assignment", "1", "--page", "1", "--at", "750,10");
        assertEquals(2, off.exitCode());
        assertTrue(off.err().contains("--at '750,10' is outside the page: x is 750, and x and y are 0 to 749"),
                off.err());
        CliRun page = CliRun.of("inspect", "--assignment", "1", "--page", "6", "--at", "10,10");
        assertEquals(2, page.exitCode());
        assertTrue(page.err().contains("--page must be 1 to 5 for the first assignment"), page.err());
    }

    /**
     * A white pixel of the first assignment's page outside its panels is in the page's margins (the 50 px around
     * the four) or in a gutter between two panels, named; page coordinates, y up from the bottom-left.
     */
    @Test
    void aPixelBetweenPanelsIsInAGutterNotTheMargins() {
        String[][] places = {
            {"350,400", "the white gutter between panels 1 and 2"}, // x 350-399 between the columns, y in the top row
            {"375,200", "the white gutter between panels 3 and 4"},
            {"200,375", "the white gutter between panels 1 and 3"},
            {"600,360", "the white gutter between panels 2 and 4"},
            {"370,370", "the white gutter between the four panels"},
            {"20,400", "the page's white margins"},
            {"375,720", "the page's white margins"}}; // above the gutter, in the top margin
        for (String[] place : places) {
            CliRun run = CliRun.of("inspect", "--assignment", "1", "--page", "2", "--at", place[0]);
            assertEquals(0, run.exitCode(), run.err());
            assertTrue(run.out().contains("\nin " + place[1] + ": nothing is drawn here\n"), place[0] + ": " + run.out());
        }
    }

    /** A small JSON reader: objects, arrays, strings, numbers (as Double), true, false, null. */
    static final class MiniJson {
        private final String s;
        private int i;

        MiniJson(String s) {
            this.s = s;
        }

        Object value() {
            Object v = next();
            space();
            if (i != s.length()) {
                throw new IllegalArgumentException("trailing text at " + i);
            }
            return v;
        }

        private Object next() {
            space();
            char c = s.charAt(i);
            if (c == '{') {
                Map<String, Object> m = new LinkedHashMap<>();
                i++;
                space();
                if (s.charAt(i) == '}') {
                    i++;
                    return m;
                }
                while (true) {
                    space();
                    String key = (String) next();
                    space();
                    expect(':');
                    m.put(key, next());
                    space();
                    if (s.charAt(i) == ',') {
                        i++;
                    } else {
                        expect('}');
                        return m;
                    }
                }
            }
            if (c == '[') {
                List<Object> list = new ArrayList<>();
                i++;
                space();
                if (s.charAt(i) == ']') {
                    i++;
                    return list;
                }
                while (true) {
                    list.add(next());
                    space();
                    if (s.charAt(i) == ',') {
                        i++;
                    } else {
                        expect(']');
                        return list;
                    }
                }
            }
            if (c == '"') {
                StringBuilder sb = new StringBuilder();
                i++;
                while (s.charAt(i) != '"') {
                    char d = s.charAt(i++);
                    if (d == '\\') {
                        char e = s.charAt(i++);
                        switch (e) {
                            case 'n' -> sb.append('\n');
                            case 't' -> sb.append('\t');
                            case 'r' -> sb.append('\r');
                            case 'u' -> {
                                sb.append((char) Integer.parseInt(s.substring(i, i + 4), 16));
                                i += 4;
                            }
                            default -> sb.append(e);
                        }
                    } else {
                        sb.append(d);
                    }
                }
                i++;
                return sb.toString();
            }
            for (String word : new String[] {"true", "false", "null"}) {
                if (s.startsWith(word, i)) {
                    i += word.length();
                    return word.equals("null") ? null : Boolean.valueOf(word);
                }
            }
            int start = i;
            while (i < s.length() && "+-0123456789.eE".indexOf(s.charAt(i)) >= 0) {
                i++;
            }
            if (start == i) {
                throw new IllegalArgumentException("unexpected '" + c + "' at " + i);
            }
            return Double.parseDouble(s.substring(start, i));
        }

        private void space() {
            while (i < s.length() && Character.isWhitespace(s.charAt(i))) {
                i++;
            }
        }

        private void expect(char c) {
            if (s.charAt(i) != c) {
                throw new IllegalArgumentException("expected '" + c + "' at " + i + ", found '" + s.charAt(i) + "'");
            }
            i++;
        }
    }
}

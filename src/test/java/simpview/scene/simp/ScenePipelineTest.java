package simpview.scene.simp;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.Supplier;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.raster.FragmentSink;
import simpview.scene.SceneException;
import simpview.scene.text.LineSource;
import simpview.shading.FragmentStage;
import simpview.shading.LitState;
import simpview.stage.PrimitiveTrace;
import simpview.surface.Drawable;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;

/** The one way from a scene file to its pixels: which rules, and what a user is told. */
class ScenePipelineTest {

    @TempDir
    Path dir;

    private final List<String> warnings = new ArrayList<>();
    private final SceneMonitor monitor = new SceneMonitor() {
        @Override
        public void warning(String message) {
            warnings.add(message);
        }
    };

    private Path write(String name, String... lines) throws IOException {
        return Files.writeString(dir.resolve(name), String.join("\n", lines) + "\n");
    }

    private ScenePipeline.Drawn draw(Path file, PageCanvas canvas, ScenePipeline.Rules rules) throws SceneException {
        canvas.clear();
        return ScenePipeline.draw(file, canvas, ScenePipeline.Options.byCommands(new SceneLibrary()).withRules(rules),
                monitor);
    }

    @Test
    void aLitCommandBeforeAnyPrimitiveTurnsTheSceneLitWhereItStands() throws Exception {
        Path scene = write("a.simp", "translate 0 0 -5", "ambient 1 1 1", "polygon (-50 -50 0) (50 -50 0) (0 50 0)");
        PageCanvas byCommands = new PageCanvas();
        ScenePipeline.Drawn drawn = draw(scene, byCommands, ScenePipeline.Rules.BY_COMMANDS);
        assertTrue(drawn.lit());
        assertEquals("a.simp:2 ambient", drawn.litBecause());
        PageCanvas lit = new PageCanvas();
        draw(scene, lit, ScenePipeline.Rules.LIT);
        assertArrayEquals(lit.image().getRGB(0, 0, 750, 750, null, 0, 750),
                byCommands.image().getRGB(0, 0, 750, 750, null, 0, 750), "the same picture as lit from the start");
    }

    @Test
    void aWatchedLitSceneGivesItsFragmentStagesBackForTheNextPicture() throws Exception {
        Path scene = write("watched.simp", "translate 0 0 -5", "ambient 1 1 1", "polygon (-50 -50 0) (50 -50 0) (0 50 0)");
        PageCanvas canvas = new PageCanvas();
        List<FragmentStage> watched = new ArrayList<>();
        SceneMonitor watching = new SceneMonitor() {
            @Override
            public DrawingWatch watch() {
                return new DrawingWatch() {
                    @Override
                    public Drawable depthCued(PageCanvas c, Rgb near, Rgb far, boolean ownColours) {
                        throw new AssertionError("the scene is lit");
                    }

                    @Override
                    public FragmentSink fragments(FragmentStage stage) {
                        watched.add(stage);
                        return stage;
                    }

                    @Override
                    public void began(Supplier<List<SourcePlace>> chain, LitState lit) {
                    }
                };
            }
        };
        canvas.clear();
        ScenePipeline.draw(scene, canvas, ScenePipeline.Options.lit(new SceneLibrary()), watching);
        assertEquals(1, watched.size());
        List<FragmentStage> kept = canvas.drawingThreads().takeKept(FragmentStage.class);
        assertEquals(watched, kept, "the watched picture's stage, given back to the threads");
    }

    @Test
    void aLitCommandAfterAPrimitiveDrawsTheSceneAgainLit() throws Exception {
        Path scene = write("late.simp", "polygon (-50 -50 -5) (50 -50 -5) (0 50 -5)", "surface 0 0 1",
                "ambient 1 1 1", "polygon (-90 -90 -9) (-60 -90 -9) (-75 -60 -9)");
        PageCanvas byCommands = new PageCanvas();
        ScenePipeline.Drawn drawn = draw(scene, byCommands, ScenePipeline.Rules.BY_COMMANDS);
        assertTrue(drawn.lit());
        assertEquals("late.simp:2 surface", drawn.litBecause());
        PageCanvas lit = new PageCanvas();
        draw(scene, lit, ScenePipeline.Rules.LIT);
        assertArrayEquals(lit.image().getRGB(0, 0, 750, 750, null, 0, 750),
                byCommands.image().getRGB(0, 0, 750, 750, null, 0, 750), "nothing of the depth-cued start is left");
        assertEquals(List.of(scene), drawn.files());
    }

    @Test
    void withDepthCueColoursALitSceneIsNotDrawnAndSaysWhy() throws Exception {
        Path scene = write("lit.simp", "# a lit scene", "camera -1 -1 1 1 -1 -100", "polygon (0 0 -5) (1 0 -5) (0 1 -5)");
        PageCanvas canvas = new PageCanvas();
        ScenePipeline.Drawn drawn = draw(scene, canvas, ScenePipeline.Rules.DEPTH_CUED_OR_NOTHING);
        assertFalse(drawn.drawn());
        assertTrue(drawn.lit());
        assertEquals("lit.simp:2 camera", drawn.litBecause());
    }

    @Test
    void thePagesIgnoreLitCommandsWithAWarning() throws Exception {
        Path scene = write("page.simp", "ambient 1 1 1", "polygon (-50 -50 -50) (50 -50 -50) (0 50 -50)");
        ScenePipeline.Drawn drawn = draw(scene, new PageCanvas(), ScenePipeline.Rules.DEPTH_CUED);
        assertFalse(drawn.lit());
        assertEquals(List.of("page.simp:1 ambient: commands of lit scenes were ignored in this depth-cued drawing"
                + " (the first of them)"), warnings);
    }

    @Test
    void anEmptySceneSaysItDrewNothing() throws Exception {
        Path scene = write("empty.simp", "# nothing here yet", "", "wire");
        draw(scene, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of("empty.simp drew nothing: no line, polygon or obj in it or in the files it includes"),
                warnings);
    }

    /**
     * A scene whose every primitive is culled says so, and, when one plane of the view has them all outside it,
     * where they lie: at z above 0 (a student who looks down +z), beyond the far plane. A lit scene without a
     * camera is seen through the parallel box, and is told of that box, not of a camera it does not have.
     */
    @Test
    void aSceneWhosePrimitivesAreAllCulledSaysSo() throws Exception {
        String nearSide = ": every one lies at z above 0, in front of the near plane z = 0: you look down the -z axis,"
                + " so what is seen has z from 0 to -200";
        String box = " (x and y from -100 to 100, z from 0 near to -200 far), so it was culled";
        Path behind = write("behind.simp", "polygon (0 0 10) (50 0 10) (0 50 10)", "line (0 0 5) (10 10 5)");
        draw(behind, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of("behind.simp drew nothing: every one of its 2 primitives lies wholly outside the view"
                + box + nearSide), warnings);
        warnings.clear();
        Path litNoCamera = write("bright.simp", "ambient 1 1 1", "polygon (0 0 10) (50 0 10) (0 50 10)",
                "line (0 0 5) (10 10 5)");
        draw(litNoCamera, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of("bright.simp drew nothing: every one of its 2 primitives lies wholly outside the view"
                + box + nearSide), warnings);
        warnings.clear();
        String volume = " wholly outside the view (the camera's view volume: in front of the camera, between its near"
                + " and far planes), ";
        Path lit = write("lit.simp", "camera -1 -1 1 1 -1 -100", "ambient 1 1 1", "polygon (0 0 5) (1 0 5) (0 1 5)");
        draw(lit, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of("lit.simp drew nothing: its one primitive lies" + volume + "so it was culled: it lies"
                + " nearer than the near plane z = -1 (hither): behind the camera, or too near its eye; the camera"
                + " looks down its own -z axis"), warnings);
        warnings.clear();
        Path far = write("far.simp", "camera -1 -1 1 1 -0.1 -100", "ambient 1 1 1",
                "polygon (0 0 -200) (1 0 -200) (0 1 -200)", "line (0 0 -300) (1 1 -300)");
        draw(far, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of("far.simp drew nothing: every one of its 2 primitives lies" + volume + "so it was culled:"
                + " every one lies beyond the far plane z = -100 (yon): bring them nearer, or give yon a number"
                + " further below 0"), warnings);
        warnings.clear();
        // one beyond the far plane, one behind the eye: no one plane to name
        Path both = write("both.simp", "camera -1 -1 1 1 -0.1 -100", "ambient 1 1 1",
                "polygon (0 0 -200) (1 0 -200) (0 1 -200)", "polygon (0 0 5) (1 0 5) (0 1 5)");
        draw(both, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of("both.simp drew nothing: every one of its 2 primitives lies" + volume + "so it was"
                + " culled"), warnings);
        warnings.clear();
        // around a corner of the view: outside it, but not wholly outside one plane; the clipper leaves nothing
        Path corner = write("corner.simp", "camera -1 -1 1 1 -1 -100", "ambient 1 1 1",
                "polygon (-40 5 -10) (-5 40 -10) (-40 40 -10)");
        draw(corner, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of("corner.simp drew nothing: its one primitive lies" + volume + "so the clipper cut it away"
                + " whole: it lies round a corner of the view, partly left of the camera's window, and partly above the"
                + " camera's window, wholly beyond none (which is all culling looks for)"), warnings);
        warnings.clear();
        // one culled of two: no warning
        Path half = write("half.simp", "polygon (0 0 10) (50 0 10) (0 50 10)", "polygon (0 0 -10) (50 0 -10) (0 50 -10)");
        draw(half, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of(), warnings);
    }

    /**
     * A scene whose parts lie in folders of their own, two of them a part.simp, names each file in its warnings
     * by its path from the scene's folder, as the scene's file commands name them: never by the name alone,
     * which both part.simp files share. The scene's own file, in that folder, is named alone.
     */
    @Test
    void warningsNameFilesFromTheScenesFolder() throws Exception {
        Files.createDirectories(dir.resolve("a"));
        Files.createDirectories(dir.resolve("b"));
        write("a/part.simp", "polygon (0, 0, -10, 2, 0, 0) (10, 0, -10, 0, 0, 0) (0, 10, -10, 0, 0, 0)");
        write("b/part.simp", "obj \"part\"", "{");
        write("b/part.obj", "v 0 0 -10", "v 1 1 -10", "v 2 2 -10", "f 1 2 3");
        Path scene = write("scene.simp", "ambient 1 1 1", "file \"a/part\"", "file \"b/part\"", "{",
                "polygon (0, 0, -300) (1, 0, -300) (0, 1, -300)", "}");
        draw(scene, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS);
        List<String> places = new ArrayList<>();
        for (String w : warnings) {
            places.add(w.substring(0, w.indexOf(": ")));
        }
        assertEquals(List.of("b/part.obj:4", "a/part.simp:1", "b/part.simp:2"), places, String.join("\n", warnings));
    }

    /**
     * A depth-cued polygon whose vertices all lie outside the view, but none wholly beyond one side, is not culled:
     * drawn, the scissor dropping each pixel. When it misses the view round a corner, nothing of it shows, and a
     * scene of nothing else says so, and where it lies, as a culled one's does; one that covers part of the view
     * draws there, and a line that passes less than a pixel from the corner is not counted (its rounded pixels may
     * reach the panel).
     */
    @Test
    void aDepthCuedSceneRoundACornerOfTheViewSaysItDrewNothingAndWhere() throws Exception {
        String box = " wholly outside the view (x and y from -100 to 100, z from 0 near to -200 far), so";
        Path corner = write("corner.simp", "polygon (-150 90 -50) (-90 150 -50) (-160 160 -50)");
        PageCanvas canvas = new PageCanvas();
        draw(corner, canvas, ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of("corner.simp drew nothing: its one primitive lies" + box + " none of it reaches the panel:"
                + " it lies round a corner of the view, partly at x below -100, left of the panel, and partly at y above"
                + " 100, above the panel, wholly beyond none (which is all culling looks for)"), warnings);
        warnings.clear();
        Path two = write("two.simp", "polygon (-150 90 -50) (-90 150 -50) (-160 160 -50)",
                "line (0 300 -50) (10 101 -50)", "polygon (150 90 -50) (90 150 -50) (160 160 -50)");
        draw(two, canvas, ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of("two.simp drew nothing: every one of its 3 primitives lies" + box + " it was culled, or"
                + " none of it reaches the panel: 1 culled, lying at y above 100, above the panel, and 2 round corners of"
                + " the view, partly at y above 100, above the panel and partly beyond another side, wholly beyond none"
                + " (which is all culling looks for)"), warnings);
        warnings.clear();
        // its box over the corner and its edge across it: drawn, no warning
        Path across = write("across.simp", "polygon (-150 40 -50) (-40 150 -50) (-160 160 -50)");
        draw(across, canvas, ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of(), warnings);
        assertTrue((canvas.panel().getPixel(0, PageCanvas.PANEL - 1) & 0xFFFFFF) != 0, "the corner pixel is drawn");
        // a line round the corner less than a pixel from it, whose rounded ends are the corner pixel: not counted
        Path near = write("near.simp", "line (-100.1 -100 -50) (-100 -100.1 -50)");
        draw(near, canvas, ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of(), warnings);
        assertTrue((canvas.panel().getPixel(0, 0) & 0xFFFFFF) != 0, "the line's one pixel is drawn");
    }

    /**
     * A lit scene with no light and no ambient draws its polygons black, as SPEC says; the scene says why.
     * Only then: not when something lights them, nor when they are black for another reason (a black
     * surface), nor when a fog tints them, nor for lines (not lit: drawn in kd).
     */
    @Test
    void aLitSceneWithNothingLightingItSaysWhyItIsBlack() throws Exception {
        Files.writeString(dir.resolve("model.obj"), "v -50 -50 -100\nv 50 -50 -100\nv 0 50 -100\nf 1 2 3\n");
        String warning = "dark.simp: every lit polygon came out black: the scene has no light and no ambient"
                + " (ambient 0 0 0) where they are drawn; add 'ambient 0.2 0.2 0.2' or a 'light' before them";
        draw(write("dark.simp", "obj model"), new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of(warning), warnings);
        warnings.clear();
        // a light of no intensity lights nothing; a light after the polygon does not light it
        draw(write("dark.simp", "camera -1 -1 1 1 -1 -200", "light 0 0 0 1 0", "gouraud",
                "polygon (-1 -1 -5) (1 -1 -5) (0 1 -5)", "light 1 1 1 1 0"), new PageCanvas(),
                ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of(warning), warnings);
        warnings.clear();
        String[][] notForThis = {
            {"ambient 0.1 0 0", "obj model"},
            {"light 1 1 1 1 0", "obj model"},
            {"obj model", "ambient 1 1 1", "obj model"},
            {"surface 0 0 0", "ambient 1 1 1", "obj model"},
            {"depth -10 -150 0 0 1", "obj model"},
            {"camera -1 -1 1 1 -1 -200", "line (0 0 -5) (1 1 -5)"},
            {"camera -1 -1 1 1 -1 -200", "wire", "polygon (-1 -1 -5) (1 -1 -5) (0 1 -5)"},
        };
        for (String[] scene : notForThis) {
            draw(write("lit.simp", scene), new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS);
            assertEquals(List.of(), warnings, String.join(" / ", scene));
        }
    }

    /**
     * A light behind every polygon (the commonest cause: vertices listed clockwise as the camera sees them) adds
     * nothing, by SPEC's formula (N . L at most 0): the polygons show the ambient light alone, black without it.
     * The scene says so, and only then: not when a light stands in front of one polygon, nor for an obj face whose
     * own normals decide instead, nor for a light of no intensity in front (which lights nothing).
     */
    @Test
    void aSceneWhoseLightsAreAllBehindItsPolygonsSaysSo() throws Exception {
        String camera = "camera -1 -1 1 1 -1 -200";
        String light = "light 1 1 1 1 0"; // at the eye
        String clockwise = "polygon (-1 -1 -5) (0 1 -5) (1 -1 -5)"; // (p2 - p1) x (p3 - p1) = (0, 0, -4): away
        String counterClockwise = "polygon (-1 -1 -6) (1 -1 -6) (0 1 -6)";
        PageCanvas canvas = new PageCanvas();
        draw(write("back.simp", camera, light, clockwise), canvas, ScenePipeline.Rules.BY_COMMANDS);
        String behind = ": every light stands behind every polygon, on the side its face normal (p2 - p1) x (p3 - p1)"
                + " points away from; a polygon's front is the side from which its vertices run counter-clockwise,"
                + " so list them the other way round, or move the lights in front";
        assertEquals(List.of("back.simp: no light reached the front of any lit polygon, so every one came out black"
                + " (there is no ambient light where they are drawn)" + behind), warnings);
        int centre = canvas.image().getRGB(50 + 325, 749 - 50 - 325) & 0xFFFFFF;
        assertEquals(0, centre, "no ambient, and the light behind adds nothing");
        warnings.clear();
        draw(write("dim.simp", camera, "ambient 0.2 0.2 0.2", light, "light 1 1 1 1 0", clockwise), canvas,
                ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of("dim.simp: no light reached the front of any lit polygon, so each shows the ambient light"
                + " alone" + behind), warnings);
        long level = Math.round(1 * 0.2 * 255); // kd * Ia, clamped, times 255
        centre = canvas.image().getRGB(50 + 325, 749 - 50 - 325) & 0xFFFFFF;
        assertEquals(level << 16 | level << 8 | level, centre);
        warnings.clear();
        // a light of no intensity in front of the polygon lights nothing either
        draw(write("zero.simp", camera, "light 0 0 0 1 0", "{", "translate 0 0 -10", light, "}", counterClockwise),
                canvas, ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(1, warnings.size(), "the only light of some intensity stands behind it");
        warnings.clear();
        Files.writeString(dir.resolve("inward.obj"), "v -1 -1 -5\nv 1 -1 -5\nv 0 1 -5\nvn 0 0 -1\nf 1//1 2//1 3//1\n");
        String[][] notForThis = {
            {camera, light, counterClockwise},
            {camera, light, clockwise, counterClockwise},
            {camera, light, "flat", clockwise, counterClockwise},
            {camera, "{", "translate 0 0 -10", light, "}", clockwise},
            {camera, light, "obj inward"},
            {camera, clockwise, light},
        };
        for (String[] scene : notForThis) {
            draw(write("lit.simp", scene), canvas, ScenePipeline.Rules.BY_COMMANDS);
            assertEquals(List.of(), warnings.stream().filter(w -> w.contains("no light reached")).toList(),
                    String.join(" / ", scene));
            warnings.clear();
        }
    }

    /**
     * A surface or fog colour runs from 0 to 1; one written 0 to 255 draws white or nearly, and is drawn as
     * written (SPEC clamps the lit colour, not kd), with a warning naming the first such command. Light
     * intensities, the ambient light and ks are not colours, and may be above 1 (the course's own scenes have
     * light 8, 8, 12).
     */
    @Test
    void aSurfaceOrFogColourAboveOneIsNamed() throws Exception {
        String camera = "camera -1 -1 1 1 -1 -200";
        String triangle = "polygon (-1 -1 -5) (1 -1 -5) (0 1 -5)";
        PageCanvas canvas = new PageCanvas();
        draw(write("rgb.simp", camera, "ambient 0.2 0.2 0.2", "surface 255 128 0", triangle, "surface 300 0 0"),
                canvas, ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of("rgb.simp:3: surface colour 255 is above 1: a colour runs from 0 to 1, not 0 to 255"
                + " (255 of 255 is 1); a surface above 1 gives back more light than falls on it, and comes out brighter"
                + " than white would (this is the first such command)"), warnings);
        // kd * Ia per channel, clamped to [0, 1], then times 255
        long r = Math.round(Math.min(1, 255 * 0.2) * 255);
        long g = Math.round(Math.min(1, 128 * 0.2) * 255);
        long b = Math.round(Math.min(1, 0 * 0.2) * 255);
        assertEquals(r << 16 | g << 8 | b, canvas.image().getRGB(50 + 325, 749 - 50 - 325) & 0xFFFFFF);
        warnings.clear();
        draw(write("fog.simp", camera, "ambient 1 1 1", "depth -1 -10 0 1.5 0", triangle), canvas,
                ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of("fog.simp:3: fog colour 1.5 is above 1: a colour runs from 0 to 1; the fog is clamped to"
                + " full in that channel where it is thick (this is the first such command)"), warnings);
        warnings.clear();
        draw(write("fine.simp", camera, "ambient 1 1 1", "light 8, 8, 12, 1, .2", "surface 1 1 1 2 8",
                "depth -1 -10 1 1 1", triangle), canvas, ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of(), warnings);
    }

    /**
     * A fog whose far plane is nearer than everything drawn gives every pixel the fog's colour alone (SPEC: z at
     * or below far is the fog's colour): a picture of one colour, black most often, and the scene says why. Not
     * when one primitive has a vertex nearer than far, nor without fog.
     */
    @Test
    void aSceneWhollyBeyondItsFogSaysSo() throws Exception {
        String camera = "camera -1 -1 1 1 -0.1 -200";
        String light = "light 1 1 1 1 0";
        String fog = "depth -10 -50 0 0 0.2";
        String far = "polygon (-5 -5 -80) (5 -5 -80) (0 5 -80)";
        PageCanvas canvas = new PageCanvas();
        draw(write("fogged.simp", camera, light, fog, far, "line (0 0 -60) (1 1 -70)"), canvas,
                ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of("fogged.simp: every primitive lies at or beyond the far plane of its fog, z = -50 (depth"
                + " -10 -50 0 0 0.2), so each is drawn in the fog's colour alone: near and far are z values in the"
                + " camera's coordinates, below 0 in front of it; give far a number further below 0"), warnings);
        long blue = Math.round(0.2 * 255); // the fog's colour, z = -80 being at or below far
        assertEquals(blue, canvas.image().getRGB(50 + 325, 749 - 50 - 325) & 0xFFFFFF);
        warnings.clear();
        String[][] notForThis = {
            {camera, light, far},
            {camera, light, fog, far, "line (0 0 -60) (1 1 -40)"},
            {camera, light, fog, "polygon (-5 -5 -80) (5 -5 -80) (0 5 -49)"},
            {camera, light, far, fog},
        };
        for (String[] scene : notForThis) {
            draw(write("clear.simp", scene), canvas, ScenePipeline.Rules.BY_COMMANDS);
            assertEquals(List.of(), warnings, String.join(" / ", scene));
        }
    }

    /**
     * A light inside a closed model stands behind every face of it, as a light behind clockwise polygons does,
     * but turning the faces round is not the mend: the faces behind which it stands face opposite ways, so it
     * stands between them, and the warning says to move it out. Two polygons that face one way keep the advice
     * to list their vertices the other way round.
     */
    @Test
    void aLightInsideAClosedModelIsToldToMoveOut() throws Exception {
        // a tetrahedron round (0, 0, -5), its faces counter-clockwise seen from outside
        Files.writeString(dir.resolve("tet.obj"), "v 0 0 -4\nv 1 -1 -6\nv -1 -1 -6\nv 0 1 -6\n"
                + "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
        PageCanvas canvas = new PageCanvas();
        draw(write("inside.simp", "camera -1 -1 1 1 -1 -200", "ambient 0.1 0.1 0.1", "{", "translate 0 0 -5.2",
                "light 1 1 1 1 0", "}", "obj tet"), canvas, ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of("inside.simp: no light reached the front of any lit polygon, so each shows the ambient"
                + " light alone: every light stands behind every polygon, on the side its face normal (p2 - p1) x"
                + " (p3 - p1) points away from; polygons that face opposite ways all have the lights behind them, so"
                + " the lights stand between them, inside what they enclose (a light inside a closed model lights"
                + " only its inside): move the lights out, in front of the polygons the camera sees (or, where"
                + " polygons are meant to face in, list their vertices the other way round)"), warnings);
        warnings.clear();
        draw(write("oneway.simp", "camera -1 -1 1 1 -1 -200", "light 1 1 1 1 0",
                "polygon (-1 -1 -5) (0 1 -5) (1 -1 -5)", "polygon (-1 -1 -7) (0 1 -7) (1 -1 -7)"), canvas,
                ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(1, warnings.size(), "both clockwise, facing one way");
        assertTrue(warnings.get(0).endsWith("so list them the other way round, or move the lights in front"),
                warnings.get(0));
    }

    /**
     * A fog whose near plane lies at or beyond the view's far plane fogs nothing that is drawn (SPEC: z at or
     * above near keeps its colour; nothing beyond yon is drawn), so the picture shows no fog; the scene says so,
     * at the depth command, with the planes to choose between. Not for a fog that reaches into the view, nor
     * for one replaced before any primitive.
     */
    @Test
    void aFogBeyondTheFarPlaneIsNamed() throws Exception {
        String triangle = "polygon (-5 -5 -20) (5 -5 -20) (0 5 -20)";
        PageCanvas canvas = new PageCanvas();
        draw(write("unseen.simp", "camera -1 -1 1 1 -0.1 -50", "ambient 1 1 1", "depth -60 -100 1 0 0", triangle),
                canvas, ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of("unseen.simp:3: this fog shows nowhere: its near plane z = -60 lies at or beyond the"
                + " camera's far plane z = -50 (yon), and only what lies beyond near is fogged, while nothing beyond"
                + " the far plane is drawn; give near a z between hither -0.1 and yon -50 (depth -60 -100 1 0 0, the"
                + " first such fog)"), warnings);
        assertEquals(0xFFFFFF, canvas.image().getRGB(50 + 325, 749 - 50 - 325) & 0xFFFFFF, "no fog, as SPEC says");
        warnings.clear();
        draw(write("parallel.simp", "ambient 1 1 1", "depth -200 -300 1 0 0", triangle), canvas,
                ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of("parallel.simp:2: this fog shows nowhere: its near plane z = -200 lies at or beyond the"
                + " far plane z = -200 (the parallel view of a scene without a camera), and only what lies beyond near"
                + " is fogged, while nothing beyond the far plane is drawn; give near a z between 0 and -200 (depth"
                + " -200 -300 1 0 0, the first such fog)"), warnings);
        warnings.clear();
        String[][] notForThis = {
            {"camera -1 -1 1 1 -0.1 -50", "ambient 1 1 1", "depth -49 -100 1 0 0", triangle},
            {"camera -1 -1 1 1 -0.1 -50", "ambient 1 1 1", "depth -60 -100 1 0 0", "depth -10 -40 1 0 0", triangle},
            {"ambient 1 1 1", "depth 0 -200 0 0 0", triangle},
        };
        for (String[] scene : notForThis) {
            draw(write("seen.simp", scene), canvas, ScenePipeline.Rules.BY_COMMANDS);
            assertEquals(List.of(), warnings, String.join(" / ", scene));
        }
    }

    @Test
    void ownColoursADepthCuedSceneDoesNotDrawAreNamed() throws Exception {
        Path scene = write("colours.simp", "line (0 0 -5) (10 10 -5)",
                "polygon (-60 -50 -50 1 0 0) (60 -50 -50 0 1 0) (0 60 -50 0 0 1)");
        draw(scene, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of("colours.simp:2: the vertices' own colours are not drawn: a depth-cued scene takes its"
                + " colours from the depth cue (SPEC Part 1); ScenePipeline.Options.withOwnColours(true)"
                + " (PageContext.withOwnColours(true) for a page), draws them (this is the first line with colours)"),
                warnings, "a Java caller's monitor is told the library's method, not the command line's option");
        warnings.clear();
        PageCanvas canvas = new PageCanvas();
        canvas.clear();
        ScenePipeline.draw(scene, canvas, ScenePipeline.Options.byCommands(new SceneLibrary()).withOwnColours(true),
                monitor);
        assertEquals(List.of(), warnings, "drawn in their own colours");
        draw(scene, new PageCanvas(), ScenePipeline.Rules.DEPTH_CUED);
        assertEquals(List.of(), warnings, "the course's pages are depth-cued by the course's rule: no word of it");
    }

    /**
     * Colours written as bytes (255 0 0 for red), the common slip of a student who knows colours from paint
     * programs: the clamp's warning says a colour runs from 0 to 1 and what the largest channel of that line
     * would be; a channel a little above 1, or below 0, is told of the clamp alone.
     */
    @Test
    void coloursOfZeroTo255AreToldTheyRunFromZeroToOne() throws Exception {
        PageCanvas canvas = new PageCanvas();
        draw(write("bytes.simp", "polygon (-60 -50 -50 1 0 0) (60 -50 -50 0 1 0) (0 60 -50 0 0 1)",
                "polygon (-60 -50 -60 255 0 0) (60 -50 -60 0 128 0) (0 60 -60 0 0 255)",
                "polygon (-60 -50 -70 300 0 0) (60 -50 -70 0 1 0) (0 60 -70 0 0 1)"), canvas,
                ScenePipeline.Rules.BY_COMMANDS);
        assertEquals("bytes.simp:2: colour channels outside 0 to 1 were clamped (this is the first such line): a colour"
                + " runs from 0 to 1, not 0 to 255 (255 of 255 is 1)", warnings.get(0));
        for (String[] line : new String[][] {{"(-60 -50 -50 1.5 0 0)", ""}, {"(-60 -50 -50 -3 0 0)", ""},
                {"(-60 -50 -50 0 2 0)", ": a colour runs from 0 to 1, not 0 to 255 (2 of 255 is 0.008)"}}) {
            warnings.clear();
            draw(write("near.simp", "polygon " + line[0] + " (60 -50 -50 0 1 0) (0 60 -50 0 0 1)"), canvas,
                    ScenePipeline.Rules.BY_COMMANDS);
            assertEquals("near.simp:1: colour channels outside 0 to 1 were clamped (this is the first such line)"
                    + line[1], warnings.get(0), line[0]);
        }
    }

    @Test
    void aMissingSceneNamedWithoutItsExtensionSaysBothWereLookedFor() {
        SceneException e = assertThrows(SceneException.class,
                () -> draw(dir.resolve("nothere"), new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS));
        assertEquals("file not found: " + dir.resolve("nothere").toAbsolutePath().normalize() + " (nor nothere.simp)",
                e.problem());
    }

    @Test
    void aSceneMayBeNamedWithoutItsExtension() throws Exception {
        Path scene = write("house.simp", "polygon (-50 -50 -50) (50 -50 -50) (0 50 -50)");
        ScenePipeline.Drawn drawn = draw(dir.resolve("house"), new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS);
        assertEquals(List.of(scene), drawn.files());
        assertEquals(List.of(), warnings);
    }

    @Test
    void aProgramRenamedSimpIsNotATextFileAndNoneOfItsBytesAreShown() throws Exception {
        byte[] bytes = new byte[4096];
        new Random(19).nextBytes(bytes);
        bytes[0] = 0x7F;
        bytes[1] = 'E';
        bytes[2] = 'L';
        bytes[3] = 'F';
        Path scene = Files.write(dir.resolve("a.out.simp"), bytes);
        SceneException e = assertThrows(SceneException.class,
                () -> draw(scene, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS));
        assertTrue(e.problem().startsWith("not a text file: byte 0x7F at offset 0 (line 1); it looks like a program"
                + " (ELF)"), e.problem());
        assertTrue(e.getMessage().length() < 300, e.getMessage());
    }

    /** A scene saved as Notepad's "Unicode" is named UTF-16, with what to do, as an .obj model is. */
    @Test
    void aSceneSavedAsUtf16SaysSo() throws Exception {
        Path scene = Files.write(dir.resolve("notepad.simp"),
                "\uFEFFpolygon (0 0 0) (1 0 0) (0 1 0)\r\n".getBytes(StandardCharsets.UTF_16LE));
        SceneException e = assertThrows(SceneException.class,
                () -> draw(scene, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS));
        assertEquals("UTF-16 text, not UTF-8: it starts with the bytes FF FE, as Windows Notepad saves \"Unicode\"; a"
                + " SIMP file is read as UTF-8: save it as UTF-8 (in Notepad: Save As, Encoding UTF-8)", e.problem());
        assertEquals("", e.lineText());
    }

    /** A trace that runs out of memory at the first primitive it is told of: Java's memory running out there. */
    private static SceneMonitor runsOutAtTheFirstPrimitive() {
        return new SceneMonitor() {
            @Override
            public PrimitiveTrace trace() {
                return new PrimitiveTrace() {
                    @Override
                    public void read(int index, Path file, int line, int kind, double[] p, int at, int stride,
                            int vertices) {
                        throw new OutOfMemoryError("Java heap space");
                    }

                    @Override
                    public boolean drawing(int index) {
                        return true;
                    }
                };
            }
        };
    }

    /**
     * Java's memory running out while a line is read and drawn: an error at
     * that line, in the file that holds it, with the lines that included it
     * and how to give Java more.
     */
    @Test
    void memoryRunningOutIsAnErrorAtTheLine() throws Exception {
        write("part.simp", "# a part", "polygon (0 0 -1) (50 0 -1) (0 50 -1)");
        Path scene = write("whole.simp", "wire", "file \"part\"");
        SceneException e = assertThrows(SceneException.class,
                () -> ScenePipeline.drawDepthCued(scene, SceneFixture.NOWHERE, runsOutAtTheFirstPrimitive()));
        assertEquals(dir.resolve("part.simp"), e.file());
        assertEquals(2, e.line());
        assertEquals("whole.simp:2", e.includedFrom());
        assertTrue(e.problem().startsWith("out of memory reading and drawing the scene at this line (Java may use at"
                + " most "), e.problem());
    }

    /** Out of memory on the drawing threads, once the scene is read: an error naming the scene. */
    @Test
    void memoryRunningOutOnTheDrawingThreadsNamesTheScene() throws Exception {
        Path scene = write("drawn.simp", "polygon (0 0 -1) (50 0 -1) (0 50 -1)");
        Drawable full = SceneFixture.throwingAtEveryWrite(() -> new OutOfMemoryError("Java heap space"));
        SceneException e = assertThrows(SceneException.class, () -> ScenePipeline.drawDepthCued(scene, full,
                SceneMonitor.NONE, DrawingThreads.of(2), null));
        assertEquals(scene, e.file());
        assertTrue(e.problem().startsWith("out of memory drawing this scene (Java may use at most "), e.problem());
    }

    @Test
    void aNonTextByteFurtherOnIsPlacedByItsOffset() throws Exception {
        Path scene = Files.writeString(dir.resolve("late.simp"), "wire\npolygon (0 0 0) (1 0 0) (0 1 0)\nsca\u0001le 1 1 1\n");
        SceneException e = assertThrows(SceneException.class,
                () -> draw(scene, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS));
        assertEquals("not a text file: byte 0x01 at offset 40 (line 3); a SIMP file is lines of text", e.problem());
        assertEquals(3, e.line());
        assertEquals(4, e.column());
        assertTrue(e.getMessage().startsWith(scene + ":3:4: "), e.getMessage());
    }

    /**
     * A Latin-1 letter after UTF-8 ones, included: placed at its column,
     * the characters before it counted as characters, not bytes, and a byte
     * order mark not counted at all.
     */
    @Test
    void aNonUtf8ByteIsPlacedAtItsColumnInCharacters() throws Exception {
        Files.write(dir.resolve("part.simp"), new byte[] {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF, '#', ' ', (byte) 0xC3,
            (byte) 0xA9, (byte) 0xE2, (byte) 0x82, (byte) 0xAC, (byte) 0xE9, '\n'});
        Path scene = write("whole.simp", "wire", "file \"part\"");
        SceneException e = assertThrows(SceneException.class,
                () -> draw(scene, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS));
        assertEquals(dir.resolve("part.simp"), e.file());
        assertEquals(1, e.line());
        assertEquals(5, e.column(), "after '# \u00e9\u20ac'");
        assertTrue(e.getMessage().startsWith(dir.resolve("part.simp") + ":1:5, included from whole.simp:2: not UTF-8"),
                e.getMessage());
    }

    /** A line over the reader's limit is an error at the column where it passes the limit, saying what to do. */
    @Test
    void aLineTooLongIsPlacedWhereItPassesTheLimit() throws Exception {
        Path scene = write("long.simp", "wire", "#" + "x".repeat(LineSource.MAX_LINE + 10));
        SceneException e = assertThrows(SceneException.class,
                () -> draw(scene, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS));
        assertEquals(2, e.line());
        assertEquals(LineSource.MAX_LINE + 1, e.column());
        // the .obj reader says it in the same form (ObjErrorsTest): the limit, and what to do
        assertEquals("line is too long: over 1048576 bytes (1 MiB), the most a line may hold. Put one command on "
                + "each line of a SIMP file; a file saved without its line ends is one long line: save it again "
                + "with them", e.problem());
        assertTrue(e.getMessage().startsWith(scene + ":2:" + (LineSource.MAX_LINE + 1) + ": "), e.getMessage());
    }

    /**
     * A picture renamed .simp starts with a byte that is no UTF-8 (0x89): it
     * is named with what the file looks like, as an .obj model's is, at the
     * top of a scene and included alike, and none of its bytes is shown.
     */
    @Test
    void aPictureRenamedSimpIsNamedAtTheTopAndIncluded() throws Exception {
        byte[] png = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R'};
        Path picture = Files.write(dir.resolve("picture.simp"), png);
        String problem = "not a text file: byte 0x89 at offset 0 (line 1); it looks like a PNG picture; a SIMP file is"
                + " lines of text";
        SceneException top = assertThrows(SceneException.class,
                () -> draw(picture, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS));
        assertEquals(problem, top.problem());
        assertEquals("", top.lineText());
        SceneException included = assertThrows(SceneException.class,
                () -> draw(write("page.simp", "wire", "file picture"), new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS));
        assertEquals(problem, included.problem());
        assertEquals("page.simp:2", included.includedFrom());
    }

    /**
     * A scene saved as Latin-1 is not UTF-8 text, wherever its first such
     * byte stands: in a comment too (docs/simp.md), named with what it
     * would be in Latin-1, and no byte of the line shown.
     */
    @Test
    void latin1TextIsNotUtf8EvenInAComment() throws Exception {
        String saveAs = "; a SIMP file is read as UTF-8: save it as UTF-8 (in Notepad: Save As, Encoding UTF-8)";
        Path comment = Files.write(dir.resolve("comment.simp"), "wire\n# caf\u00e9\nline (0 0 0) (1 1 1)\n"
                .getBytes(StandardCharsets.ISO_8859_1));
        SceneException e = assertThrows(SceneException.class,
                () -> draw(comment, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS));
        assertEquals("not UTF-8 text: byte 0xE9 at offset 10 (line 2) starts or continues no UTF-8 character; it looks"
                + " like text saved as Latin-1 or Windows-1252, where that byte is '\u00e9'" + saveAs, e.problem());
        assertEquals(2, e.line());
        assertEquals("", e.lineText());
        Path command = Files.write(dir.resolve("command.simp"), new byte[] {(byte) 0xE9, ' ', '1', '\n'});
        assertEquals("not UTF-8 text: byte 0xE9 at offset 0 (line 1) starts or continues no UTF-8 character; it looks"
                + " like text saved as Latin-1 or Windows-1252, where that byte is '\u00e9'" + saveAs,
                assertThrows(SceneException.class,
                        () -> draw(command, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS)).problem());
        // UTF-8's own letters, and a mark cut by nothing but the end of a 64 KB read, are text
        StringBuilder text = new StringBuilder("# caf\u00e9 \u2014 \uD83D\uDE00\n");
        while (text.length() < 3 * LineSource.CHUNK) {
            text.append("# \u00e9\u00e9\u00e9 \u2212\u2212 \uD83D\uDE00\n");
        }
        text.append("line (0 0 -1) (1 1 -1)\n");
        Path good = Files.writeString(dir.resolve("good.simp"), text);
        draw(good, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS);
    }

    /**
     * The A3 handout prints obj “filename”: a name copied with its curly
     * quotes names nothing, and is told so as other characters copied from
     * a PDF are, with the line to write instead.
     */
    @Test
    void curlyQuotesCopiedFromAPdfAreNamed() throws Exception {
        write("tri.simp", "polygon (0 0 -1) (50 0 -1) (0 50 -1)");
        SceneException e = assertThrows(SceneException.class, () -> draw(write("page.simp", "file \u201Ctri\u201D"),
                new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS));
        assertTrue(e.problem().startsWith("file not found: \u201Ctri\u201D.simp (the name, whose '\u201C' is U+201C LEFT"
                + " DOUBLE QUOTATION MARK, not ASCII: a name is quoted with the ASCII '\"' (text copied from a PDF or a"
                + " word processor often looks right and is not): write file \"tri\"); looked for "), e.problem());
        Files.writeString(dir.resolve("tri.obj"), "v 0 0 -5\nv 1 0 -5\nv 0 1 -5\nf 1 2 3\n");
        SceneException model = assertThrows(SceneException.class, () -> draw(write("lit.simp", "ambient 1 1 1",
                "obj \u2018tri\u2019"), new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS));
        assertTrue(model.problem().contains("whose '\u2018' is U+2018 LEFT SINGLE QUOTATION MARK, not ASCII: a name is"
                + " quoted with the ASCII '\"'"), model.problem());
        assertTrue(model.problem().contains(": write obj \"tri\")"), model.problem());
        // a curly quote opening and a straight one closing: the straight one is no part of the name to write
        SceneException mixed = assertThrows(SceneException.class, () -> draw(write("mixed.simp", "file \u201Ctri\""),
                new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS));
        assertTrue(mixed.problem().contains(": write file \"tri\"); looked for "), mixed.problem());
        SceneException guillemets = assertThrows(SceneException.class, () -> draw(write("fr.simp",
                "file \u00ABtri\u00BB"), new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS));
        assertTrue(guillemets.problem().contains("whose '\u00AB' is U+00AB LEFT-POINTING DOUBLE ANGLE QUOTATION MARK,"
                + " not ASCII: a name is quoted with the ASCII '\"'"), guillemets.problem());
        assertTrue(guillemets.problem().contains(": write file \"tri\"); looked for "), guillemets.problem());
    }

    @Test
    void anObjNamingAFolderSaysSoInWords() throws Exception {
        Files.createDirectory(dir.resolve("models.obj"));
        Path scene = write("lit.simp", "ambient 1 1 1", "obj \"models\"");
        SceneException e = assertThrows(SceneException.class,
                () -> draw(scene, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS));
        assertTrue(e.problem().contains("not a file but a folder"), e.problem());
        assertFalse(e.getMessage().contains("Exception"), e.getMessage());
    }

    /**
     * A model that cannot be read as a whole (here a folder) is an error at
     * the name in its obj command, line and column, as a file command's
     * is, in an included file too; before, it named the model and the
     * including line but no column.
     */
    @Test
    void anObjThatCannotBeReadIsAnErrorAtItsName() throws Exception {
        Files.createDirectory(dir.resolve("models.obj"));
        Path part = write("part.simp", "# the model", "  obj \"models\"");
        Path scene = write("whole.simp", "ambient 1 1 1", "{", "file \"part\"", "}");
        SceneException e = assertThrows(SceneException.class,
                () -> draw(scene, new PageCanvas(), ScenePipeline.Rules.BY_COMMANDS));
        assertEquals(part, e.file());
        assertEquals(2, e.line());
        assertEquals(7, e.column());
        assertEquals("whole.simp:3", e.includedFrom());
        assertTrue(e.getMessage().startsWith(part + ":2:7, included from whole.simp:3: cannot read the obj file "
                + dir.resolve("models.obj") + ": not a file but a folder"), e.getMessage());
    }

    @Test
    void theShareOfTheTopFileReadGrowsToOne() throws Exception {
        StringBuilder text = new StringBuilder();
        for (int k = 0; k < 5000; k++) {
            text.append("line (-50, -50, -10) (50, 50, -10)\n");
            if (k == 2500) {
                text.append("file \"part\"\n");
            }
        }
        write("part.simp", "line (0, 0, -5) (10, 10, -5)");
        Path scene = Files.writeString(dir.resolve("long.simp"), text);
        List<Double> shares = new ArrayList<>();
        SceneMonitor told = new SceneMonitor() {
            @Override
            public void topFileRead(double share) {
                shares.add(share);
            }
        };
        PageCanvas canvas = new PageCanvas();
        canvas.clear();
        ScenePipeline.draw(scene, canvas, ScenePipeline.Options.byCommands(new SceneLibrary()), told);
        assertTrue(shares.size() >= 4, shares.toString());
        for (int i = 1; i < shares.size(); i++) {
            assertTrue(shares.get(i) >= shares.get(i - 1), shares.toString());
        }
        assertTrue(shares.get(0) > 0.15 && shares.get(0) < 0.25, "1024 of 5001 lines: " + shares);
        assertEquals(1.0, shares.get(shares.size() - 1), "all of it at the end");
    }

    /**
     * The monitor is told a scene is lit as it turns lit, before it is drawn whole (what a window that draws it
     * asks, to leave own colours out of a scene they do not change); a depth-cued scene never tells it.
     */
    @Test
    void aLitSceneTellsItsMonitorItIsLitAndADepthCuedOneDoesNot() throws Exception {
        Path lit = write("lit.simp", "camera -1 -1 1 1 -1 -100\nambient 1 1 1\n"
                + "polygon (-5, -5, -10, 0, 1, 0) (5, -5, -10, 0, 1, 0) (0, 5, -10, 0, 1, 0)\n");
        Path cued = write("cued.simp", "polygon (-50, -50, -50) (50, -50, -50) (0, 50, -50)\n");
        List<String> told = new ArrayList<>();
        for (Path scene : List.of(lit, cued)) {
            SceneMonitor monitor = new SceneMonitor() {
                @Override
                public void turnedLit() {
                    told.add(scene.getFileName().toString());
                }
            };
            PageCanvas canvas = new PageCanvas();
            canvas.clear();
            ScenePipeline.draw(scene, canvas, ScenePipeline.Options.byCommands(new SceneLibrary()), monitor);
        }
        assertFalse(told.isEmpty(), "the lit scene told nothing");
        assertTrue(told.stream().allMatch("lit.simp"::equals), "told: " + told);
    }

    @Test
    void theCueColoursArePassedOn() throws Exception {
        Path scene = write("near.simp", "polygon (-50 -50 0) (50 -50 0) (0 50 0)");
        PageCanvas canvas = new PageCanvas();
        canvas.clear();
        ScenePipeline.draw(scene, canvas, ScenePipeline.Options.byCommands(new SceneLibrary())
                .withCue(new Rgb(0, 1, 0), Rgb.BLACK), monitor);
        assertEquals(0x00FF00, canvas.image().getRGB(375, 400) & 0xFFFFFF, "green at z = 0");
    }
}

package simpview.scene.simp;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import simpview.geometry.Camera;
import simpview.scene.MemoryAdvice;
import simpview.scene.SceneException;
import simpview.shading.Fog;
import simpview.shading.FragmentStage;
import simpview.shading.FragmentStages;
import simpview.stage.PrimitiveTrace;
import simpview.surface.Drawable;
import simpview.surface.DrawingThreads;
import simpview.surface.OwedRows;
import simpview.surface.PageCanvas;
import simpview.surface.Provenance;
import simpview.surface.Rgb;

/**
 * The one way from a SIMP scene file to its pixels: the window, the pages,
 * {@code render}, {@code compare} and the benchmarks all draw a scene here.
 * Read top to bottom, one scene is:
 *
 * <ol>
 * <li>a canvas its caller has just cleared ({@link PageCanvas#clear}): white
 *     margins, black panel, the z-buffer at the far plane;
 * <li>the files read once each, command by command ({@link SimpInterpreter},
 *     {@link FileStack}), or replayed from the options' {@link SceneLibrary}
 *     while unchanged, every command carried out by {@link SimpClient}:
 *     the CTM and the stacks, then each primitive by the scene's rules;
 * <li>depth-cued rules (SPEC Part 1, {@link DepthCuedRules}): world space,
 *     culling, panel space, DDA lines and top-left-rule triangles, through
 *     the scissor, the z-buffer and the depth cue onto the panel;
 * <li>or, from the first command of the lit rules on (SPEC Part 2,
 *     {@link LitRules}): camera space, culling and the clipper, perspective,
 *     the rasterizers' fragments, then per pixel the depth test, the lighting,
 *     the fog and the bytes ({@link FragmentStage}), on a z-buffer that
 *     starts at -infinity;
 * <li>what was drawn: which rules, why, and every file read or looked for.
 * </ol>
 *
 * Which rules is decided while reading, by the first lit command met, so no
 * file is opened twice to decide it; only a scene whose first lit command
 * comes after a primitive (rare: a camera must come first) is drawn a second
 * time, lit, from the start.
 */
public final class ScenePipeline {

    /** Which rules a scene may be drawn by. */
    public enum Rules {
        /** SPEC Part 2: lit when any file it reads holds a lit command, else depth-cued. */
        BY_COMMANDS,
        /** Always depth-cued (the eight pages): lit commands are ignored, with a warning. */
        DEPTH_CUED,
        /**
         * Depth-cued, and not drawn at all when it turns out lit (depth-cue
         * colours were asked for, which a lit scene cannot take: the caller
         * says so, naming {@link Drawn#litBecause}).
         */
        DEPTH_CUED_OR_NOTHING,
        /** Lit from the first command, whatever the files hold (tests and benchmarks of the lit rules). */
        LIT
    }

    /**
     * How a scene is drawn.
     *
     * @param near the depth cue's colour at z = 0
     * @param far its colour at z = -200
     * @param ownColours depth-cued scenes in their vertices' own colours (white where none), without the cue
     * @param rules which rules the scene may be drawn by
     * @param library where the scene's small .simp files and its obj models come from, and are kept:
     *     by whoever draws, across pictures
     * @param workingDir where {@code file} and {@code obj} names are looked for after the including
     *     file's folder (the course's programs looked in the working directory), absolute. SPEC's second
     *     place, so the process's working directory by default for every caller: a name is always looked
     *     for first beside the file that names it, and a Java caller whose scenes rely on a name found
     *     only where the course's program ran names that folder with {@link #withWorkingDir}
     */
    public record Options(Rgb near, Rgb far, boolean ownColours, Rules rules, SceneLibrary library,
            Path workingDir) {

        /** A scene as its commands say, depth-cued from white to black when it is not lit. */
        public static Options byCommands(SceneLibrary library) {
            return new Options(Rgb.WHITE, Rgb.BLACK, false, Rules.BY_COMMANDS, library, processWorkingDir());
        }

        /** By the lit rules from the first command on. */
        public static Options lit(SceneLibrary library) {
            return byCommands(library).withRules(Rules.LIT);
        }

        /** A page's scene: always depth-cued from {@code near} to black. */
        public static Options depthCued(Rgb near, SceneLibrary library) {
            return byCommands(library).withRules(Rules.DEPTH_CUED).withCue(near, Rgb.BLACK);
        }

        private static Path processWorkingDir() {
            return Path.of("").toAbsolutePath();
        }

        public Options withCue(Rgb newNear, Rgb newFar) {
            return new Options(newNear, newFar, ownColours, rules, library, workingDir);
        }

        public Options withOwnColours(boolean own) {
            return new Options(near, far, own, rules, library, workingDir);
        }

        public Options withRules(Rules newRules) {
            return new Options(near, far, ownColours, newRules, library, workingDir);
        }

        public Options withWorkingDir(Path dir) {
            return new Options(near, far, ownColours, rules, library, dir.toAbsolutePath());
        }
    }

    /**
     * What a scene drew.
     *
     * @param lit true when it was drawn (or, not drawn, would have been) by the lit rules
     * @param litBecause where its first lit command stands, "pageA.simp:3 camera"; null when depth-cued
     * @param drawn false only for {@link Rules#DEPTH_CUED_OR_NOTHING} and a lit scene: nothing was drawn
     * @param files every file it read or looked for, in the order met (see {@link SceneMonitor#reached})
     */
    public record Drawn(boolean lit, String litBecause, boolean drawn, List<Path> files) {
    }

    private ScenePipeline() {
    }

    /**
     * Draws the scene in {@code file} on {@code canvas}, which has just been
     * cleared, from a fresh state (identity CTM, empty stacks, style filled).
     * On an error what was drawn before it stays and the error is thrown on;
     * the monitor is told the files reached (and how it read them) either way.
     */
    public static Drawn draw(Path file, PageCanvas canvas, Options options, SceneMonitor monitor)
            throws SceneException {
        FileStack files = files(options);
        String litAfterDrawing = null;
        try {
            SimpClient client = options.rules() == Rules.LIT ? litFromTheStart(canvas, options, files, monitor)
                    : depthCuedFirst(canvas, options, files, monitor);
            run(client, monitor, file);
            return drawn(client, client.litBecause(), files, monitor, options);
        } catch (SceneTurnsLit turn) {
            if (options.rules() == Rules.DEPTH_CUED_OR_NOTHING) {
                canvas.clear();
                return new Drawn(true, turn.because, false, files.reached());
            }
            litAfterDrawing = turn.because;
        } finally {
            if (litAfterDrawing == null) {
                monitor.versionsAsRead(files.versionsAsRead());
                monitor.reached(files.reached());
            }
        }
        return drawnAgainLit(file, canvas, options, monitor, litAfterDrawing);
    }

    /** The scene's files, read from the options' library and kept in it. */
    private static FileStack files(Options options) {
        return new FileStack(FileStack.SMALL_FILE, options.workingDir(), options.library().scenes());
    }

    /** A scene that turned lit after it had drawn depth-cued: the whole of it again, lit from its first command. */
    private static Drawn drawnAgainLit(Path file, PageCanvas canvas, Options options, SceneMonitor monitor,
            String litBecause) throws SceneException {
        canvas.clear();
        PrimitiveTrace trace = monitor.trace();
        if (trace != null) {
            trace.restart();
        }
        FileStack files = files(options);
        try {
            SimpClient client = litFromTheStart(canvas, options, files, monitor);
            run(client, monitor, file);
            return drawn(client, litBecause, files, monitor, options);
        } finally {
            monitor.versionsAsRead(files.versionsAsRead());
            monitor.reached(files.reached());
        }
    }

    /**
     * Reads and draws the scene. With several drawing threads the primitives
     * are recorded as they are read, and what is still recorded is drawn at
     * the end, also after an error (what was read before it stays drawn).
     */
    private static void run(SimpClient client, SceneMonitor monitor, Path file) throws SceneException {
        try {
            try {
                interpreter(client, monitor).run(file);
            } finally {
                client.flush();
            }
        } catch (OutOfMemoryError e) {
            // out of memory drawing what was read, on the drawing threads: the line read last is gone
            throw new SceneException(file, 0, 0, "", MemoryAdvice.outOfMemory("drawing this scene"));
        }
    }

    /** A client that draws depth-cued until the scene's first lit command (what then depends on the options). */
    private static SimpClient depthCuedFirst(PageCanvas canvas, Options options, FileStack files, SceneMonitor monitor) {
        DrawingWatch watch = monitor.watch();
        Drawable panel = watch != null ? watch.depthCued(canvas, options.near(), options.far(), options.ownColours())
                : options.ownColours() ? canvas.depthTested() : canvas.depthCued(options.near(), options.far());
        DepthCuedRules cued = new DepthCuedRules(panel, files, monitor.trace(), monitor.viewTurn());
        if (watch != null) {
            watch.began(files::chain, null); // and drawn on this thread alone: the watch sees each write as it is made
        } else {
            cued.drawWith(canvas.drawingThreads(), canvas.zbuffer(), canvas::owedPanelRows, panel, canvas.provenance());
        }
        SimpClient.OnLit onLit = switch (options.rules()) {
            case BY_COMMANDS, LIT -> SimpClient.OnLit.TURN_LIT;
            case DEPTH_CUED -> SimpClient.OnLit.IGNORE;
            case DEPTH_CUED_OR_NOTHING -> SimpClient.OnLit.STOP;
        };
        return new SimpClient(files, cued, onLit, () -> lit(canvas, options, files, monitor));
    }

    /** A client by the lit rules from its first command. */
    private static SimpClient litFromTheStart(PageCanvas canvas, Options options, FileStack files,
            SceneMonitor monitor) {
        return new SimpClient(files, lit(canvas, options, files, monitor), SimpClient.OnLit.TURN_LIT,
                () -> lit(canvas, options, files, monitor));
    }

    /** The lit rules on the canvas: its z-buffer from -infinity, fragments onto its panel. */
    private static LitRules lit(PageCanvas canvas, Options options, FileStack files, SceneMonitor monitor) {
        monitor.turnedLit();
        Drawable panel = canvas.litPanel();
        FragmentStages stages = FragmentStages.keptBy(canvas.drawingThreads(), canvas.zbuffer());
        FragmentStage fragments = stages.next(panel);
        LitRules lit = new LitRules(fragments, options.library().models(), files, monitor, monitor.trace(),
                monitor.viewTurn());
        DrawingWatch watch = monitor.watch();
        if (watch != null) {
            // Drawn on this thread alone: the watch sees each fragment as the rasterizers make it.
            canvas.zbuffer().reset(Double.NEGATIVE_INFINITY);
            lit.fragmentsThrough(watch.fragments(fragments), stages);
            watch.began(files::chain, lit.state());
        } else {
            // Resets the z-buffer: at once on one thread, band by band by the bands' drawers with several.
            lit.drawWith(canvas.drawingThreads(), canvas.zbuffer(), canvas.owedPanelRows(), panel, canvas.provenance(),
                    canvas.waitingPixels(), stages);
        }
        return lit;
    }

    /**
     * A depth-cued scene onto any panel drawable that already does what is
     * wanted per pixel (tests and benchmarks give scissors, recorders, chains
     * of their own); lit commands are ignored, with a warning. The steps are
     * those of {@link #draw}'s depth-cued rules.
     */
    public static void drawDepthCued(Path file, Drawable panel, SceneMonitor monitor) throws SceneException {
        drawDepthCued(file, panel, monitor, DrawingThreads.one(), null);
    }

    /**
     * The same, drawn by {@code threads} (the geometry stage once, on this
     * thread, then the panel band by band by all of them), owners into
     * {@code provenance} when the panel records them (else null).
     */
    public static void drawDepthCued(Path file, Drawable panel, SceneMonitor monitor, DrawingThreads threads,
            Provenance provenance) throws SceneException {
        FileStack files = new FileStack();
        try {
            DepthCuedRules cued = new DepthCuedRules(panel, files, monitor.trace(), monitor.viewTurn());
            cued.drawWith(threads, null, () -> OwedRows.NONE, panel, provenance);
            run(new SimpClient(files, cued, SimpClient.OnLit.IGNORE, SimpClient::neverLit), monitor, file);
        } finally {
            monitor.versionsAsRead(files.versionsAsRead());
            monitor.reached(files.reached());
        }
    }

    /**
     * The reading loop; a watched scene (the inspector's replay) reads and
     * draws on this thread alone, so each primitive is drawn while its command
     * is being carried out, where the file stack can say where it stands.
     */
    private static SimpInterpreter interpreter(SimpClient client, SceneMonitor monitor) {
        return monitor.watch() != null ? SimpInterpreter.onOneThread(client, monitor)
                : new SimpInterpreter(client, monitor);
    }

    /**
     * Why a scene whose every primitive was culled or clipped away drew
     * nothing: the view, and where they lie: the plane of it that has every
     * culled primitive outside it (a scene at z = +10 looked at down -z), and
     * the corner of it that those not culled lie round (a triangle beyond the
     * panel's top-left corner whose box overlaps the panel). Part 1 clips
     * nothing: its scissor drops every pixel of those.
     */
    private static String outsideTheView(SimpClient client) {
        long n = client.primitiveCount();
        long clipped = client.clippedAwayCount();
        Camera view = client.view();
        String them = n == 1 ? "it" : "them";
        String how = clipped == 0 ? "it was culled"
                : !client.isLit() ? (clipped == n ? "" : "it was culled, or ") + "none of it reaches the panel"
                : clipped == n ? "the clipper cut it away whole" : "it was culled or cut away whole by the clipper";
        String words = (n == 1 ? "its one primitive lies" : "every one of its " + n + " primitives lies")
                + " wholly outside the view (" + (view.isPerspective()
                        ? "the camera's view volume: in front of the camera, between its near and far planes"
                        : "x and y from -100 to 100, z from 0 near to -200 far")
                + "), so " + how;
        int outside = client.culledOutside();
        if (view.isPerspective() && (outside & 1 << Camera.HITHER) != 0) {
            // behind the eye every side plane's outside half-space holds the point too: nothing to say of them
            outside = 1 << Camera.HITHER;
        }
        if (clipped == 0) {
            return outside == 0 ? words : words + ": " + (n == 1 ? "it lies " : "every one lies ")
                    + where(view, outside, them, ", and ");
        }
        String corner = roundACorner(view, client.clippedAwayOutside(), clipped == 1 ? "it" : "them");
        if (clipped == n) {
            return words + ": " + (n == 1 ? "it lies " : "every one lies ") + corner;
        }
        long culled = n - clipped;
        String culledWhere = outside == 0 ? "" : ", " + (culled == 1 ? "lying " : "every one lying ")
                + where(view, outside, culled == 1 ? "it" : "them", ", and ");
        return words + ": " + culled + " culled" + culledWhere + ", and " + clipped + " " + corner;
    }

    /**
     * Where primitives not culled but wholly outside the view lie: round a corner of it, partly beyond two sides
     * (or more), {@code sides} those every one of them reaches beyond.
     */
    private static String roundACorner(Camera view, int sides, String them) {
        String culling = ", wholly beyond none (which is all culling looks for)";
        return switch (Integer.bitCount(sides)) {
            case 0 -> "round corners of the view, each partly beyond two of its sides" + culling;
            case 1 -> "round corners of the view, partly " + where(view, sides, them, "") + " and partly beyond another"
                    + " side" + culling;
            default -> "round a corner of the view, partly " + where(view, sides, them, ", and partly ") + culling;
        };
    }

    /** The sides of the view in {@code planes} (bits 1 &lt;&lt; Camera.HITHER ...), each as {@link #beyond} says it. */
    private static String where(Camera view, int planes, String them, String joiner) {
        List<String> where = new ArrayList<>();
        for (int plane = 0; plane < Camera.PLANES; plane++) {
            if ((planes & 1 << plane) != 0) {
                where.add(beyond(view, plane, them));
            }
        }
        return String.join(joiner, where);
    }

    /** Where a point outside one plane of the view lies, in words a student placing a scene reads. */
    private static String beyond(Camera view, int plane, String them) {
        if (view.isPerspective()) {
            return switch (plane) {
                case Camera.HITHER -> "nearer than the near plane z = " + Camera.written(view.hither())
                        + " (hither): behind the camera, or too near its eye; the camera looks down its own -z axis";
                case Camera.YON -> "beyond the far plane z = " + Camera.written(view.yon()) + " (yon): bring " + them
                        + " nearer, or give yon a number further below 0";
                case Camera.LEFT -> "left of the camera's window";
                case Camera.RIGHT -> "right of the camera's window";
                case Camera.BOTTOM -> "below the camera's window";
                default -> "above the camera's window";
            };
        }
        return switch (plane) {
            case Camera.HITHER -> "at z above 0, in front of the near plane z = 0: you look down the -z axis, so what"
                    + " is seen has z from 0 to -200";
            case Camera.YON -> "at z below -200, beyond the far plane";
            case Camera.LEFT -> "at x below -100, left of the panel";
            case Camera.RIGHT -> "at x above 100, right of the panel";
            case Camera.BOTTOM -> "at y below -100, below the panel";
            default -> "at y above 100, above the panel";
        };
    }


    private static Drawn drawn(SimpClient client, String litBecause, FileStack files, SceneMonitor monitor,
            Options options) {
        if (!client.drew()) {
            monitor.warning(files.reached().get(0).getFileName()
                    + " drew nothing: no line, polygon or obj in it or in the files it includes");
        } else if (client.primitiveCount() > 0
                && client.culledCount() + client.clippedAwayCount() == client.primitiveCount()) {
            monitor.warning(files.reached().get(0).getFileName() + " drew nothing: " + outsideTheView(client));
        } else if (client.everyPrimitiveFoggedWhole() != null) {
            // correct by SPEC, but a picture of the fog's colour alone (black, most often) looks like a bug
            Fog fog = client.everyPrimitiveFoggedWhole();
            monitor.warning(files.reached().get(0).getFileName() + ": every primitive lies at or beyond the far plane"
                    + " of its fog, z = " + Camera.written(fog.far()) + " (depth " + Camera.written(fog.near()) + " "
                    + Camera.written(fog.far()) + " " + Camera.written(fog.r()) + " " + Camera.written(fog.g()) + " "
                    + Camera.written(fog.b()) + "), so each is drawn in the fog's colour alone: near and far are z"
                    + " values in the camera's coordinates, below 0 in front of it; give far a number further below 0");
        }
        boolean lightsBehind = client.noLightReachedAPolygon();
        if (client.everyLitPolygonBlack() && !lightsBehind) {
            // correct by SPEC (ambient starts at 0 0 0), but a black panel with no word looks like a bug
            monitor.warning(files.reached().get(0).getFileName() + ": every lit polygon came out black: the scene"
                    + " has no light and no ambient (ambient 0 0 0) where they are drawn; add 'ambient 0.2 0.2 0.2'"
                    + " or a 'light' before them");
        } else if (lightsBehind) {
            // correct by SPEC too (a light behind a face adds nothing), and the commonest cause is a face's
            // vertices listed clockwise
            monitor.warning(files.reached().get(0).getFileName() + ": no light reached the front of any lit polygon,"
                    + " so " + (client.everyLitPolygonBlack() ? "every one came out black (there is no ambient light"
                            + " where they are drawn)" : "each shows the ambient light alone")
                    + ": every light stands behind every polygon, on the side its face normal (p2 - p1) x (p3 - p1)"
                    + " points away from; " + (client.lightsInsideThePolygons() ? "polygons that face opposite ways"
                            + " all have the lights behind them, so the lights stand between them, inside what they"
                            + " enclose (a light inside a closed model lights only its inside): move the lights out,"
                            + " in front of the polygons the camera sees (or, where polygons are meant to face in,"
                            + " list their vertices the other way round)" : "a polygon's front is the side from which"
                            + " its vertices run counter-clockwise, so list them the other way round, or move the"
                            + " lights in front"));
        }
        if (!client.isLit() && !options.ownColours() && options.rules() == Rules.BY_COMMANDS
                && client.firstOwnColours() != null) {
            // the course's rule, but a student who gave colours expects to see them
            monitor.warning(client.firstOwnColours() + ": the vertices' own colours are not drawn: a depth-cued scene"
                    + " takes its colours from the depth cue (SPEC Part 1); " + monitor.nameOf(Setting.OWN_COLOURS)
                    + ", draws them (this is the first line with colours)");
        }
        double[] centre = client.shownCentre();
        if (centre != null) {
            monitor.shownCentre(centre);
        }
        return new Drawn(client.isLit(), litBecause, true, files.reached());
    }
}

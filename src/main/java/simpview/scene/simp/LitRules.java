package simpview.scene.simp;

import java.nio.file.Path;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import simpview.geometry.Camera;
import simpview.geometry.Matrix4;
import simpview.raster.FragmentSink;
import simpview.scene.SceneException;
import simpview.scene.obj.ObjCounts;
import simpview.scene.obj.ObjFilesSeen;
import simpview.scene.obj.ObjLibrary;
import simpview.scene.obj.ObjSink;
import simpview.shading.Fog;
import simpview.shading.FragmentStage;
import simpview.shading.FragmentStages;
import simpview.shading.LitState;
import simpview.stage.LitGeometry;
import simpview.stage.LitPrimitives;
import simpview.stage.ObjFace;
import simpview.stage.PrimitiveTrace;
import simpview.surface.Drawable;
import simpview.surface.DrawingThreads;
import simpview.surface.OwedRows;
import simpview.surface.Provenance;
import simpview.surface.WaitingPixels;
import simpview.surface.ZBuffer;

/**
 * A scene by the lit rules (SPEC Part 2): the lit commands set the camera,
 * the light, the surface, the fog and the shading in its {@link LitState},
 * each checking its numbers first, and every line, polygon and obj face goes
 * through the lit geometry stage to the fragment stage.
 */
final class LitRules implements RuleSet {

    private final LitState state = new LitState();
    private final LitGeometry geometry;
    private final ObjLibrary models;
    /** The obj files this picture has looked at and read: a model drawn again is not looked up or read again. */
    private final ObjFilesSeen modelsSeen = new ObjFilesSeen();
    /** Where the first model colour outside 0 to 1 stands ("dummy.obj:12"), or null. */
    private String firstClampedColour;
    /** The largest channel of that colour, as written, or NaN. */
    private double firstClampedChannel = Double.NaN;
    /** The first surface or fog colour with a channel above 1, as the warning names it, or null. */
    private String firstColourAboveOne;
    /** Where the last depth command stands (null before one: no fog yet), and the last fog checked (state.fog()). */
    private String fogSetAt;
    private Fog fogChecked;
    /** The first fog in force at a primitive whose near plane lies at or beyond the view's far plane, or null. */
    private String firstFogUnseen;
    /** What the models read so far warned of, each warning once however often its model is drawn. */
    private final Set<String> modelWarnings = new LinkedHashSet<>();
    private final FileStack files;
    /** Who is told of a model's lines as they are read, and may stop the scene in the middle of one. */
    private final SceneMonitor monitor;
    private final boolean traced;
    private final PrimitiveTrace trace;
    /** Where the camera command stands, and where the first primitive did ("file:line"), or null. */
    private String cameraAt;
    private String firstPrimitiveAt;
    /** Where the first primitive with a vertex that is not finite stands ("ovf.obj:3 face ..."). */
    private final FirstNonFinite firstNonFinite;
    /** The record several threads draw from, or null: drawn at once, on this thread. */
    private LitPrimitives record;
    /** Where the fragments go when drawn at once. */
    private final FragmentStage fragments;
    /** The picture's fragment stages, given back to its threads at its end; null when they are not kept. */
    private FragmentStages stages;

    /**
     * @param fragments where the fragments go: the canvas's z-buffer (reset to -infinity) and panel
     * @param models where obj models come from (kept by whoever draws, across pictures)
     * @param monitor who is told of a model's lines as they are read, and may cancel in the middle of one
     * @param trace who follows the primitives, or null
     * @param turn the window's turn of the view, after W (the camera moves about the world), or null
     */
    LitRules(FragmentStage fragments, ObjLibrary models, FileStack files, SceneMonitor monitor, PrimitiveTrace trace,
            Matrix4 turn) {
        this.geometry = new LitGeometry(state, fragments);
        this.firstNonFinite = new FirstNonFinite(geometry);
        this.fragments = fragments;
        this.models = models;
        this.files = files;
        this.monitor = monitor;
        this.traced = trace != null;
        this.trace = trace;
        geometry.follow(trace);
        state.turnView(turn);
    }

    @Override
    public void line(Matrix4 ctm, double[] xyz, double[] rgb) {
        primitive();
        source(ctm, xyz, 2);
        geometry.line(ctm, xyz, rgb);
        firstNonFinite.note(files, "line");
    }

    @Override
    public void polygon(Matrix4 ctm, double[] xyz, double[] rgb, boolean wire) {
        primitive();
        source(ctm, xyz, 3);
        geometry.polygon(ctm, xyz, rgb, wire);
        firstNonFinite.note(files, "polygon");
    }

    @Override
    public LitGeometry geometry() {
        return geometry;
    }

    @Override
    public String firstNonFinite() {
        return firstNonFinite.place();
    }

    @Override
    public String nonFiniteWhy() {
        return "a vertex comes out infinite or NaN in camera space (its numbers are finite, but the CTM takes them"
                + " beyond about 1.8e308)";
    }

    /** Tells a trace that wants them the primitive's vertices as written and the CTM. */
    private void source(Matrix4 ctm, double[] xyz, int vertices) {
        if (trace != null && trace.wantsSource()) {
            trace.source(ctm, xyz, vertices);
        }
    }

    /**
     * The rasterizers' fragments go through {@code sink} on their way to the
     * fragment stage (the inspector's probe), drawn on this thread; the
     * fragment stages come from {@code stages} (this one's among them), given
     * back at the scene's end, as {@link #drawWith} gives them back.
     */
    void fragmentsThrough(FragmentSink sink, FragmentStages stages) {
        this.stages = stages;
        geometry.fragmentsThrough(sink);
    }

    /*
     * The commands of the lit rules, each called by SimpClient.execute once
     * the scene is lit; each returns true when it drew (only an obj does).
     */

    boolean ambient(Command c) throws SceneException {
        notNegative(c, 0, 3, "ambient light");
        state.setAmbient(c.numbers[0], c.numbers[1], c.numbers[2]);
        return false;
    }

    boolean camera(Command c, Matrix4 ctm) throws SceneException {
        if (cameraAt != null) {
            throw error(c, c.commandIndex, "a second camera: a scene has one, and the first is at " + cameraAt);
        }
        if (firstPrimitiveAt != null) {
            throw error(c, c.commandIndex, "the camera must come before every line, polygon and obj; "
                    + firstPrimitiveAt + " drew one before it");
        }
        double[] n = c.numbers;
        Camera.Problem problem = Camera.problem(n[0], n[1], n[2], n[3], n[4], n[5]);
        if (problem != null) {
            throw errorAtNumber(c, problem.number(), problem.words());
        }
        Matrix4 w = ctm.inverse();
        if (w == null && ctm.inverseOverflows()) {
            // the CTM itself is finite (SimpClient checks each transform), its inverse is not
            throw error(c, c.commandIndex, "the CTM at the camera cannot be inverted: its inverse overflows (holds "
                    + "numbers beyond about 1.8e308, a scale too near 0?), so there is no way from the world to the"
                    + " camera");
        }
        if (w == null) {
            throw error(c, c.commandIndex, "the CTM at the camera cannot be inverted (a scale of 0?): "
                    + "there is no way from the world to the camera");
        }
        cameraAt = files.place();
        state.setCamera(Camera.perspective(n[0], n[1], n[2], n[3], n[4], n[5]), w);
        return false;
    }

    /**
     * Where a model's faces go: the geometry stage. Every so many of its lines the monitor is told the lines read
     * so far, the model's among them (the scene's count goes on from there once the model is drawn), and asked
     * whether to stop: a model of millions of faces is cancelled as it is read, not once it is drawn whole.
     */
    private ObjSink modelFaces() {
        return new ObjSink() {
            @Override
            public void face(ObjFace face) throws SceneException {
                geometry.face(face);
            }

            @Override
            public boolean readsEdges() {
                return geometry.readsEdges();
            }

            @Override
            public void progress(int line) {
                monitor.linesRead(files.linesRead() + line);
                if (monitor.cancelled()) {
                    throw new SceneCancelledException();
                }
            }
        };
    }

    boolean obj(Command c, Matrix4 ctm, SimpClient.Style style) throws SceneException {
        primitive();
        Path file = files.locateModel(c);
        geometry.beginObj(ctm, style == SimpClient.Style.WIRE, file);
        ObjCounts counts;
        try {
            counts = models.draw(file, modelFaces(), modelsSeen);
        } catch (SceneException e) {
            throw wholeModel(c, file, e);
        }
        files.modelDrawn(file, modelsSeen.asRead(file));
        if (firstClampedColour == null && counts.firstClampedColour() > 0) {
            firstClampedColour = files.shown(file) + ":" + counts.firstClampedColour();
            firstClampedChannel = counts.firstClampedChannel();
        }
        // the reader names the model by its file name alone (it knows no scene): the scene names it as its files
        String bare = String.valueOf(file.getFileName());
        for (String w : counts.warnings()) {
            modelWarnings.add(w.startsWith(bare + ":") ? files.shown(file) + w.substring(bare.length()) : w);
        }
        if (firstNonFinite.justCounted()) {
            firstNonFinite.noteAs(files.shown(file) + ":" + geometry.firstNonFiniteLine()
                    + " face (of the model drawn by " + files.place() + " obj)");
        }
        return true;
    }

    /**
     * An error about the model {@code file} as a whole (line 0: a folder, a
     * pipe, a file that cannot be opened or read), placed as the same
     * problem with a {@code file} command is: at the name in the obj
     * command, whose column an editor can go to. An error at a line of the
     * model is that line's, and stays so.
     */
    private SceneException wholeModel(Command c, Path file, SceneException e) {
        if (e.line() > 0 || !file.equals(e.file())) {
            return e;
        }
        return error(c, c.argumentIndex, e.problem());
    }

    @Override
    public List<String> modelWarnings() {
        return List.copyOf(modelWarnings);
    }

    @Override
    public String firstClampedColour() {
        return firstClampedColour;
    }

    @Override
    public double firstClampedChannel() {
        return firstClampedChannel;
    }

    boolean surface(Command c) throws SceneException {
        notNegative(c, 0, c.count, c.count == 3 ? "surface colour" : "surface colour, ks and p");
        aboveOne(c, 0, "surface colour", "a surface above 1 gives back more light than falls on it, and comes out"
                + " brighter than white would");
        double[] n = c.numbers;
        if (c.count == 3) {
            state.setSurface(n[0], n[1], n[2]);
        } else {
            state.setSurface(n[0], n[1], n[2], n[3], n[4]);
        }
        return false;
    }

    boolean depth(Command c) throws SceneException {
        double[] n = c.numbers;
        if (!(n[0] > n[1])) {
            String meant = n[0] >= 0 && n[1] > n[0] && n[1] > 0
                    ? ": they are z values, below 0 in front of the camera; as distances in front of it they are"
                    + " depth " + Camera.written(-n[0]) + " " + Camera.written(-n[1])
                    : n[1] > n[0] ? ": near is the nearer z and far the one further below 0: swap them" : "";
            throw error(c, c.argumentIndex, "fog needs near > far (camera-space z, far more negative), found near "
                    + n[0] + " and far " + n[1] + meant);
        }
        notNegative(c, 2, 5, "fog colour");
        aboveOne(c, 2, "fog colour", "the fog is clamped to full in that channel where it is thick");
        fogSetAt = files.place();
        state.setFog(new Fog(n[0], n[1], n[2], n[3], n[4]));
        return false;
    }

    boolean light(Command c, Matrix4 ctm) throws SceneException {
        notNegative(c, 0, 5, "light intensity and attenuation");
        double[] n = c.numbers;
        if (n[3] == 0 && n[4] == 0) {
            throw errorAtNumber(c, 3, "attenuation A and B are both 0: the light would be infinitely bright");
        }
        state.addLight(ctm.get(0, 3), ctm.get(1, 3), ctm.get(2, 3), n[0], n[1], n[2], n[3], n[4]);
        return false;
    }

    boolean shading(LitState.ShadingMode shading) {
        state.setShading(shading);
        return false;
    }

    private void notNegative(Command c, int from, int to, String what) throws SceneException {
        for (int i = from; i < to; i++) {
            if (c.numbers[i] < 0) {
                throw errorAtNumber(c, i, what + " may not be negative, found " + c.numbers[i]);
            }
        }
    }

    /**
     * Notes the first colour, the three numbers of {@code c} from
     * {@code from} on, with a channel above 1: a colour runs from 0 to 1
     * (reference/assignment3.txt: "All colors are in [0, 1]"), and one of 0
     * to 255 (255 0 0 for red) draws as white or nearly, with no word of why.
     * It is drawn as written: SPEC clamps the lit colour, not kd. The
     * warning names {@code what} it is and its {@code effect}.
     */
    private void aboveOne(Command c, int from, String what, String effect) {
        if (firstColourAboveOne != null) {
            return;
        }
        for (int i = from; i < from + 3; i++) {
            double v = c.numbers[i];
            if (v > 1) {
                firstColourAboveOne = files.place() + ": " + what + " " + Camera.written(v) + " is above 1: a colour"
                        + " runs from 0 to 1" + notOf255(v) + "; " + effect + " (this is the first such command)";
                return;
            }
        }
    }

    /**
     * For a colour channel {@code v} above 1: from 2 on, that a colour is not of 0 to 255 and what v of 255
     * would be (", not 0 to 255 (255 of 255 is 1)"), as a student who wrote bytes needs to hear; else "".
     */
    static String notOf255(double v) {
        return v >= 2 ? ", not 0 to 255 (" + Camera.written(v) + " of 255 is "
                + Camera.written(Math.round(v / 255 * 1000) / 1000.0) + ")" : "";
    }

    /**
     * Notes {@code fog}, in force at a primitive, when its near plane lies at or beyond the view's far plane:
     * SPEC fogs only what lies beyond near, and draws nothing beyond yon, so it shows nowhere (a student who
     * wrote it sees no fog and no word of why). The camera is known by now: it comes before every primitive.
     */
    private void noteFogUnseen(Fog fog) {
        Camera view = state.camera();
        if (firstFogUnseen != null || fog.near() > view.yon()) {
            return;
        }
        String far = view.isPerspective() ? "the camera's far plane z = " + Camera.written(view.yon()) + " (yon)"
                : "the far plane z = " + Camera.written(view.yon()) + " (the parallel view of a scene without a"
                + " camera)";
        String between = view.isPerspective() ? "between hither " + Camera.written(view.hither()) + " and yon "
                + Camera.written(view.yon()) : "between 0 and -200";
        firstFogUnseen = fogSetAt + ": this fog shows nowhere: its near plane z = " + Camera.written(fog.near())
                + " lies at or beyond " + far + ", and only what lies beyond near is fogged, while nothing beyond"
                + " the far plane is drawn; give near a z " + between + " (depth " + Camera.written(fog.near()) + " "
                + Camera.written(fog.far()) + " " + Camera.written(fog.r()) + " " + Camera.written(fog.g()) + " "
                + Camera.written(fog.b()) + ", the first such fog)";
    }

    /** Where the first fog that shows nowhere stands and why, as a warning; or null. */
    String fogUnseen() {
        return firstFogUnseen;
    }

    /** Where the first surface or fog colour above 1 stands and what it was, as a warning; or null. */
    String colourAboveOne() {
        return firstColourAboveOne;
    }

    private SceneException error(Command c, int at, String problem) {
        return files.current().error(at, problem);
    }

    /** An error at the command's number n (from 0), the caret under it. */
    private SceneException errorAtNumber(Command c, int n, String problem) {
        return files.current().errorAtNumber(c.argumentIndex, n, problem);
    }

    /** Notes the first primitive, which no camera may follow; tells a followed stage where it stands. */
    private void primitive() {
        if (firstPrimitiveAt == null) {
            firstPrimitiveAt = files.place();
        }
        if (fogSetAt != null && state.fog() != fogChecked) {
            fogChecked = state.fog();
            noteFogUnseen(fogChecked);
        }
        if (traced) {
            geometry.from(files.current().file(), files.current().lineNumber());
        }
    }

    /** The state as the commands so far left it: read, never to be changed. */
    LitState state() {
        return state;
    }

    /**
     * Resets {@code zbuffer} to -infinity and, with more than one of
     * {@code threads}, from now on records the primitives to be drawn band by
     * band, depth-tested against {@code zbuffer} onto {@code panel} (the
     * fragment stage's), owners into {@code provenance} (or null); then each
     * band's drawer resets its own rows of the z-buffer, on its own thread,
     * and makes its rows of {@code panelRows}, those the canvas's clear owes
     * of the panel (nothing on one thread, whose canvas clears at once). Phong pixels wait in {@code waiting} (the panel's, which the drawers
     * clear first) to be shaded once each at the scene's end
     * ({@link FragmentStage#shadeLater}). The fragment stages come from
     * {@code stages} (this one's among them), given back at the scene's end.
     * Call before the scene is read.
     */
    void drawWith(DrawingThreads threads, ZBuffer zbuffer, OwedRows panelRows, Drawable panel,
            Provenance provenance, WaitingPixels waiting, FragmentStages stages) {
        this.stages = stages;
        if (threads.isOne()) {
            zbuffer.reset(Double.NEGATIVE_INFINITY);
            fragments.shadeLater(waiting, provenance);
            fragments.clearWaits();
            return;
        }
        // Resets the z-buffer band by band, and makes the panel's owed rows so.
        record = new LitPrimitives(threads, zbuffer, panelRows, panel, provenance, waiting, stages);
        geometry.recordTo(record);
    }

    @Override
    public void flush() {
        if (record != null) {
            record.flush();
        } else {
            fragments.shadeWaiting();
        }
        if (stages != null) {
            stages.keep(); // drawn: no thread uses them any more
        }
    }

    /** True when polygons were lit and each came out black, as nothing lit it (see {@link LitGeometry#everyLitPolygonBlack}). */
    boolean everyLitPolygonBlack() {
        return geometry.everyLitPolygonBlack();
    }

    /** The fog every primitive drawn lies wholly beyond, or null (see {@link LitGeometry#everyPrimitiveFoggedWhole}). */
    Fog everyPrimitiveFoggedWhole() {
        return geometry.everyPrimitiveFoggedWhole();
    }

    /**
     * True when no light reached a lit polygon's front and those polygons face opposite ways (see
     * {@link LitGeometry#lightsInsideThePolygons}).
     */
    boolean lightsInsideThePolygons() {
        return geometry.lightsInsideThePolygons();
    }

    /** True when lights were on and none reached the front of a lit polygon (see {@link LitGeometry#noLightReachedAPolygon}). */
    boolean noLightReachedAPolygon() {
        return geometry.noLightReachedAPolygon();
    }

    /** For a scene that was followed: the centre of what its view showed, in camera space; else null. */
    double[] shownCentre() {
        return geometry.shownCentre();
    }
}

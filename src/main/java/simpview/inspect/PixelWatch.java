package simpview.inspect;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import simpview.geometry.Camera;
import simpview.geometry.Clipper;
import simpview.geometry.Matrix4;
import simpview.raster.FragmentLayout;
import simpview.shading.LitState;
import simpview.stage.Painter;
import simpview.stage.PrimitiveTrace;
import simpview.scene.simp.SourcePlace;
import simpview.surface.ZBuffer;

/**
 * The one-pixel filter of a replay: follows the scene's primitives as the
 * window's instruments do (a {@link PrimitiveTrace}), and keeps a history
 * entry for every write that the probes see arrive at its pixel, with how far
 * it got. Nothing is kept for any other pixel. One watch per replay.
 */
final class PixelWatch implements PrimitiveTrace {

    private final int x;
    private final int y;
    private final List<HistoryEntry> entries = new ArrayList<>();
    private final ZBuffer zbuffer;
    // Set when the scene's rules begin (again, when it turns lit): where to ask for the include chain,
    // the view, and what explains and colours the writes (the depth cue's or the lighting's).
    private Supplier<List<SourcePlace>> chains = List::of;
    private Supplier<Camera> camera = () -> Camera.PARALLEL;
    private Supplier<Matrix4> worldToCamera = Matrix4::identity;
    private boolean lit;
    private Explainer explainer;

    // The primitive being drawn: its number, command, kind and projected outline.
    private int primitive = HistoryEntry.NO_NUMBER;
    private Path file;
    private int line;
    private int kind;
    private double[] outline = new double[64];
    private int stride;
    private int vertices;
    /**
     * Whether the primitive at hand carries one colour (phong: one kd), as it is in its outline
     * (PrimitiveTrace.oneColour).
     */
    private boolean oneColour;
    /** Told by the trace just before the read it is about. */
    private boolean nextOneColour;
    private List<SourcePlace> chain;
    private int lastWritten = HistoryEntry.NO_NUMBER;
    /** The write on its way down the chain now. */
    private HistoryEntry current;
    private double depthBefore;
    // The lit primitive at hand in camera space before clipping (LitGeometry's vertices: x, y, z, r, g, b, normal),
    // told before it is read; and the entry it gets if its drawn part never reaches the pixel but its uncut one would.
    private double[] unclipped = new double[9 * 8];
    private int unclippedStride;
    private int unclippedCount;
    /** Whether the primitive at hand has its face normal at every vertex, none of its own (PrimitiveTrace.faceNormalOnly). */
    private boolean faceNormalOnly;
    /** What the flat polygon at hand was lit with: centroid, normal, mean kd; null when not flat. */
    private double[] litOnce;
    /** The kd each vertex of the gouraud polygon at hand was lit with, 3 a vertex; null when not gouraud. */
    private double[] litEach;
    private HistoryEntry cutAway;
    /** Clips a primitive again to learn which planes cut it; made for the first one cut. */
    private Clipper clipper;

    /** What a watch asks of the scene's kind of drawing. */
    interface Explainer {
        /**
         * The colour of a write at depth z whose fragment channels (lit) or
         * drawn levels (depth-cued, or null) are given, explained into terms
         * (null: none wanted); 0xAARRGGBB.
         */
        int colour(PixelWatch watch, double z, double[] values, int drawnArgb, boolean drawn, Terms terms);
    }

    // The primitive as written, told before it is drawn; kept for those that reach the pixel and the one asked for.
    private Matrix4 sourceCtm;
    private double[] sourceXyz = new double[3 * 8];
    private int sourceVertices;
    private final Map<Integer, PrimitiveSource> sources = new HashMap<>();
    private int wanted = HistoryEntry.NO_NUMBER;
    private boolean explaining = true;

    PixelWatch(int x, int y, ZBuffer zbuffer) {
        this.x = x;
        this.y = y;
        this.zbuffer = zbuffer;
    }

    /** The scene's rules begin: depth-cued ones (lit null) explained by {@code cue}, or lit ones by their state. */
    void begin(Supplier<List<SourcePlace>> chain, LitState state, Explainer cue) {
        chains = chain;
        lit = state != null;
        camera = lit ? state::camera : () -> Camera.PARALLEL;
        worldToCamera = lit ? state::worldToCamera : Matrix4::identity;
        explainer = lit ? new LitExplainer(state) : cue;
    }

    boolean lit() {
        return lit;
    }

    /** The scene is drawn again from the start (it turned lit): what was seen so far is forgotten. */
    @Override
    public void restart() {
        entries.clear();
        sources.clear();
        lastWritten = HistoryEntry.NO_NUMBER;
        primitive = HistoryEntry.NO_NUMBER;
        current = null;
        sourceCtm = null;
        unclippedCount = 0;
        cutAway = null;
    }

    int x() {
        return x;
    }

    int y() {
        return y;
    }

    List<HistoryEntry> entries() {
        settleCutAway();
        return entries;
    }

    /** The primitive cut by the clipper is done without a fragment at the pixel: its entry stands. */
    private void settleCutAway() {
        if (cutAway != null) {
            entries.add(cutAway);
            cutAway = null;
        }
    }

    @Override
    public void oneColour() {
        nextOneColour = true;
    }

    @Override
    public void litOnce(double[] once) {
        litOnce = once.clone();
    }

    /** What the flat polygon at hand was lit with (PrimitiveTrace.litOnce), or null when it is not flat. */
    double[] litOnce() {
        return litOnce;
    }

    @Override
    public void litEach(double[] kd, int count) {
        litEach = Arrays.copyOf(kd, 3 * count);
    }

    /** The kd each vertex of the gouraud polygon at hand was lit with (PrimitiveTrace.litEach), or null. */
    double[] litEach() {
        return litEach;
    }

    @Override
    public void unclipped(double[] p, int at, int numbers, int count) {
        litOnce = null;
        litEach = null;
        faceNormalOnly = false;
        if (unclipped.length < numbers * count) {
            unclipped = new double[2 * numbers * count];
        }
        System.arraycopy(p, at, unclipped, 0, numbers * count);
        unclippedStride = numbers;
        unclippedCount = count;
    }

    // ---- the trace

    @Override
    public void read(int index, Path commandFile, int commandLine, int primitiveKind, double[] p, int at,
            int numbers, int count) {
        settleCutAway();
        primitive = index;
        file = commandFile;
        line = commandLine;
        kind = primitiveKind;
        stride = numbers;
        vertices = count;
        oneColour = nextOneColour;
        nextOneColour = false;
        if (outline.length < numbers * count) {
            outline = new double[2 * numbers * count];
        }
        System.arraycopy(p, at, outline, 0, numbers * count);
        chain = null;
        if (index == wanted) {
            keepSource();
        }
        int cut = cutBy();
        if (cut != 0 && Coverage.covers(camera.get(), kind, unclipped, 0, unclippedStride, unclippedCount, x, y)) {
            // Kept until a fragment of it reaches the pixel (then it covered the pixel after all) or the next primitive.
            cutAway = new HistoryEntry(index, chain(), kind, Outcome.CLIPPED);
            cutAway.planes = cut;
            placeHere(cutAway, unclipped, 0, unclippedStride, unclippedCount);
        }
    }

    /** The planes the clipper cut the lit primitive at hand by (0: uncut, or not lit). */
    private int cutBy() {
        return lit && unclippedCount > 0 ? cutPlanes(camera.get(), kind, unclipped, 0, unclippedStride, unclippedCount) : 0;
    }

    /**
     * The planes that cut the primitive of {@code count} camera-space vertices
     * in p (from {@code at}, {@code numbers} each), as the clipper cuts it: a
     * plane some vertex is outside of is not one of them when an earlier
     * plane's pass took that vertex away, and one that only a vertex made
     * by an earlier pass is outside of is.
     */
    private int cutPlanes(Camera view, int primitiveKind, double[] p, int at, int numbers, int count) {
        if (clipper == null || clipper.stride() != numbers) {
            clipper = new Clipper(numbers);
        }
        if (primitiveKind == Painter.LINE) {
            clipper.clipLine(view, p, at, at + numbers);
        } else {
            clipper.clipPolygon(view, p, at, count);
        }
        return clipper.cutPlanes();
    }

    /**
     * For a filled polygon cut away at the pixel: where the ray through the
     * pixel's centre meets the polygon's plane, and the planes that point is
     * outside of, which are what cut the polygon away here. The polygon is
     * {@code count} vertices of p (from {@code at}, {@code numbers} each,
     * camera space); its plane's normal is summed over all its edges
     * (Newell's), so a face whose first three vertices lie on one line (an
     * obj quad with a vertex in the middle of an edge) still has its plane.
     * Nothing when the point is inside every plane (the centre exactly on an
     * edge of the clipped outline), the polygon has no area, or the ray runs
     * along its plane.
     */
    private void placeHere(HistoryEntry e, double[] p, int at, int numbers, int count) {
        if (e.kind != Painter.FILLED) {
            return;
        }
        Camera view = camera.get();
        double wx = view.windowX(x + 0.5);
        double wy = view.windowY(y + 0.5);
        double nx = 0, ny = 0, nz = 0;
        for (int k = 0; k < count; k++) {
            int i = at + k * numbers;
            int j = at + (k + 1) % count * numbers;
            nx += (p[i + 1] - p[j + 1]) * (p[i + 2] + p[j + 2]);
            ny += (p[i + 2] - p[j + 2]) * (p[i] + p[j]);
            nz += (p[i] - p[j]) * (p[i + 1] + p[j + 1]);
        }
        double[] point;
        if (view.isPerspective()) {
            // the ray t (wx, wy, -1), t > 0, meets n . (P - p0) = 0
            double t = (nx * p[at] + ny * p[at + 1] + nz * p[at + 2]) / (nx * wx + ny * wy - nz);
            point = new double[] {t * wx, t * wy, -t};
            if (!(t > 0)) {
                return;
            }
        } else {
            // the line (wx, wy, z) straight down z
            point = new double[] {wx, wy, p[at + 2] - (nx * (wx - p[at]) + ny * (wy - p[at + 1])) / nz};
        }
        int outside = view.outcode(point[0], point[1], point[2]);
        if (outside != 0 && Double.isFinite(point[0]) && Double.isFinite(point[1]) && Double.isFinite(point[2])) {
            e.here = point;
            e.herePlanes = outside;
        }
    }

    @Override
    public void faceNormalOnly() {
        faceNormalOnly = true;
    }

    /** True when no vertex of the lit polygon at hand has a normal of its own: each carries its face normal. */
    boolean hasFaceNormalOnly() {
        return faceNormalOnly;
    }

    /** The lit primitive at hand in camera space before clipping: vertices() of unclippedStride() numbers; read only. */
    double[] unclippedVertices() {
        return unclipped;
    }

    int unclippedStride() {
        return unclippedStride;
    }

    /** How many vertices the lit primitive at hand had before clipping; 0 when not told (depth-cued). */
    int unclippedCount() {
        return lit ? unclippedCount : 0;
    }

    @Override
    public boolean wantsSource() {
        return true;
    }

    @Override
    public void source(Matrix4 ctm, double[] xyz, int count) {
        sourceCtm = ctm;
        if (sourceXyz.length < 3 * count) {
            sourceXyz = new double[6 * count];
        }
        System.arraycopy(xyz, 0, sourceXyz, 0, 3 * count);
        sourceVertices = count;
    }

    /** The primitive at hand as written, kept (once) under its number. */
    private void keepSource() {
        if (sourceCtm != null && !sources.containsKey(primitive)) {
            double[] drawn = new double[2 * vertices];
            for (int k = 0; k < vertices; k++) {
                drawn[2 * k] = outline[k * stride];
                drawn[2 * k + 1] = outline[k * stride + 1];
            }
            sources.put(primitive, new PrimitiveSource(primitive, chain(), kind, sourceCtm, worldToCamera.get(),
                    camera.get(), lit, Arrays.copyOf(sourceXyz, 3 * sourceVertices), sourceVertices, drawn));
        }
    }

    /** With false, each write gets its colour but no explanation (what an explanation costs is the difference). */
    void explaining(boolean explain) {
        explaining = explain;
    }

    /** Also keep primitive n as written, whether or not it reaches the pixel. */
    void want(int n) {
        wanted = n;
    }

    /** Primitive n as written, if it reached the pixel or was wanted; else null. */
    PrimitiveSource source(int n) {
        return sources.get(n);
    }

    @Override
    public boolean drawing(int index) {
        primitive = index;
        return true;
    }

    @Override
    public void skipped(Path commandFile, int commandLine, int primitiveKind, boolean culled, double[] p, int at,
            int numbers, int count) {
        settleCutAway();
        unclippedCount = 0;
        Camera view = camera.get();
        if (Coverage.covers(view, primitiveKind, p, at, numbers, count, x, y)) {
            HistoryEntry e = new HistoryEntry(HistoryEntry.NO_NUMBER, chainOf(commandFile, commandLine),
                    primitiveKind, culled ? Outcome.CULLED : Outcome.CLIPPED);
            if (culled) {
                int common = ~0;
                for (int k = 0; k < count; k++) {
                    int o = at + k * numbers;
                    common &= view.outcode(p[o], p[o + 1], p[o + 2]);
                }
                e.planes = common;
            } else {
                e.planes = cutPlanes(view, primitiveKind, p, at, numbers, count);
                placeHere(e, p, at, numbers, count);
            }
            entries.add(e);
        }
    }

    /** The include chain of the command at hand, ending at (file, line) when that is not the innermost simp line. */
    private List<SourcePlace> chainOf(Path commandFile, int commandLine) {
        List<SourcePlace> c = new ArrayList<>(chains.get());
        if (commandFile != null && (c.isEmpty() || !c.get(c.size() - 1).file().equals(commandFile))) {
            c.add(new SourcePlace(commandFile, commandLine));
        }
        return List.copyOf(c);
    }

    private List<SourcePlace> chain() {
        if (chain == null) {
            chain = chainOf(file, line);
        }
        return chain;
    }

    // ---- depth-cued writes, from the probes of the drawable chain

    /** A write at the pixel reached a probe: levels are the drawn colour's levels when it came in a span. */
    void reached(WriteProbe.Point point, double z, int argb, double[] levels) {
        switch (point) {
            case ATTEMPTED -> {
                keepSource();
                current = new HistoryEntry(primitive, chain(), kind, Outcome.SCISSORED);
                current.z = z;
                current.argb = explainer.colour(this, z, null, argb, false, null);
                entries.add(current);
            }
            case IN_RANGE -> {
                current.outcome = Outcome.DEPTH_FAILED;
                current.storedDepth = zbuffer.depthAt(x, y);
                current.storedOwner = lastWritten;
            }
            case PASSED_DEPTH -> {
                current.outcome = Outcome.WRITTEN;
                current.storedDepth = Double.NaN;
                current.storedOwner = HistoryEntry.NO_NUMBER;
                lastWritten = primitive;
            }
            case SHOWN -> {
                Terms terms = explaining ? new Terms() : null;
                current.argb = explainer.colour(this, z, levels, argb, true, terms);
                current.explanation = terms;
            }
            default -> throw new IllegalStateException(String.valueOf(point));
        }
    }

    // ---- lit fragments, from the fragment probe

    /** Channels the fragments of the primitive at hand carry. */
    int channels() {
        return stride - 3;
    }

    /** A fragment at the pixel, resolved, before the fragment stage tests it. */
    void fragment(double[] channels) {
        if (cutAway != null && cutAway.primitive == primitive) {
            cutAway = null; // its drawn part covers the pixel
        }
        double z = channels[0];
        keepSource();
        current = new HistoryEntry(primitive, chain(), kind, Outcome.DEPTH_FAILED);
        current.z = z;
        depthBefore = zbuffer.depthAt(x, y);
        current.storedDepth = depthBefore;
        current.storedOwner = lastWritten;
        Terms terms = explaining ? new Terms() : null;
        current.argb = explainer.colour(this, z, Arrays.copyOf(channels, channels()), 0, false, terms);
        current.explanation = terms;
        entries.add(current);
    }

    /** The fragment stage is done with the fragment: it won when the stored depth changed. */
    void fragmentDone() {
        if (Double.compare(zbuffer.depthAt(x, y), depthBefore) != 0) {
            current.outcome = Outcome.WRITTEN;
            current.storedDepth = Double.NaN;
            current.storedOwner = HistoryEntry.NO_NUMBER;
            lastWritten = primitive;
        }
    }

    // ---- what the explainers read of the primitive at hand

    int kind() {
        return kind;
    }

    /** The scene's camera now. */
    Camera camera() {
        return camera.get();
    }

    /**
     * The projected outline of the primitive at hand: vertices() of stride()
     * numbers (panel x, y, q, then channels times q, but the colour of a
     * primitive of one colour as it is: {@link #colourAt}).
     */
    double[] outline() {
        return outline;
    }

    /**
     * The colour (r, g, b) outline vertex k carries (a phong polygon's: its kd): its colour channels over its q,
     * or as they are for one colour.
     */
    double[] colourAt(int k) {
        int at = k * stride;
        double q = oneColour ? 1 : outline[at + FragmentLayout.Q];
        int c = at + FragmentLayout.CHANNEL;
        return new double[] {outline[c + FragmentLayout.R] / q, outline[c + FragmentLayout.G] / q,
            outline[c + FragmentLayout.B] / q};
    }

    /** Whether the primitive at hand carries one colour (phong: one kd), the same at every vertex, to the bit. */
    boolean carriesOneColour() {
        return oneColour;
    }

    int stride() {
        return stride;
    }

    int vertices() {
        return vertices;
    }
}

package simpview.stage;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.function.Supplier;
import simpview.geometry.Camera;
import simpview.geometry.Clipper;
import simpview.geometry.Matrix4;
import simpview.raster.FragmentLayout;
import simpview.raster.FragmentSink;
import simpview.raster.LitLineRasterizer;
import simpview.raster.LitPolygonRasterizer;
import simpview.shading.Fog;
import simpview.shading.FragmentStage;
import simpview.shading.LitState;
import simpview.shading.PointShader;

/**
 * The geometry stage of a lit scene (SPEC Part 2), top to bottom for every
 * line, polygon and .obj face:
 * <ol>
 * <li>object -> camera space by W * CTM (W the inverse of the CTM at the
 *     {@code camera} command; the identity without one), own normals by its
 *     normal transform, made unit length;</li>
 * <li>culled when every vertex is outside one plane of the view;</li>
 * <li>the face normal for vertices without their own;</li>
 * <li>lit, for filled polygons: once at the centroid (flat), at each vertex
 *     (gouraud), or not yet (phong: the fragment stage lights every pixel);
 *     lines and wire polygons are not lit, they carry kd;</li>
 * <li>clipped against the six planes (Sutherland-Hodgman, attributes lerped
 *     in camera space); whether the clipped vertices share one colour (phong:
 *     one kd) is told to the fragment stage;</li>
 * <li>projected onto the panel, each attribute multiplied by q = 1/w (but
 *     a colour or kd that every vertex shares, as it is);</li>
 * <li>rasterized: a fan for filled polygons, the clipped outline for wire
 *     ones, a DDA line for lines; the fragments go to the
 *     {@link FragmentStage}.</li>
 * </ol>
 * One instance draws one scene; it reuses its scratch arrays, and allocates
 * nothing per primitive beyond growing them for the largest face yet.
 *
 * <p>Followed by a {@link PrimitiveTrace} (the window's instruments), each
 * primitive is told to it between steps 6 and 7, with its file and line and
 * its clipped, projected outline, and may be left out (stepping); the
 * camera-space box of what was rasterized is kept, for the window's orbit.
 * Not followed (null, the default), this costs one test per primitive.
 */
public final class LitGeometry implements GeometryStage {

    // A camera-space vertex, as the clipper takes it.
    static final int CX = 0;
    static final int CY = 1;
    static final int CZ = 2;
    static final int CR = 3;
    static final int CG = 4;
    static final int CB = 5;
    static final int CNX = 6;
    static final int CNY = 7;
    static final int CNZ = 8;
    static final int CAMERA_STRIDE = 9;

    private final LitState state;
    private final FragmentStage fragments;
    /** The lighting frozen for phong pixels shaded later, and what it was made from. */
    private PointShader frozen;
    private Supplier<PointShader> frozenFrom;
    /** Where the rasterizers hand their fragments: the fragment stage, or a watcher that passes them on to it. */
    private FragmentSink raster;
    /**
     * Whether the primitive at hand carries one colour: a line, wire outline or flat or gouraud polygon whose
     * clipped vertices all have the same colour, or a phong polygon whose clipped vertices all have the same kd.
     * Its colour channels are then projected as they are, not times q ({@link FragmentStage#oneColour},
     * {@link FragmentStage#phong(PointShader, Fog, boolean)}), so that every pixel of it is that colour (that kd,
     * lit there) to the bit.
     */
    private boolean oneColour;
    private final LitRasterizers rasterizers = LitRasterizers.make();
    private final LitPolygonRasterizer fill = rasterizers.fill();
    private final LitLineRasterizer lines = rasterizers.lines();
    private final Clipper clipper = new Clipper(CAMERA_STRIDE);
    private double[] cam = new double[CAMERA_STRIDE * 8];
    private boolean[] ownNormal = new boolean[8];
    private double[] screen = new double[(FragmentLayout.stride(FragmentLayout.PHONG_CHANNELS)) * 16];
    private final double[] lit = new double[3];
    /** What the last flat polygon was lit with: centroid, normal, mean kd (for a trace: PrimitiveTrace.litOnce). */
    private final double[] litOnce = new double[9];
    /** The kd each vertex of the last gouraud polygon was lit with, 3 a vertex (for a trace: PrimitiveTrace.litEach). */
    private double[] litEach = new double[3 * 8];
    /** An obj face's vertices as written, for a trace that wants them. */
    private double[] written = new double[3 * 8];
    /** The unit face normal of the polygon at hand (zero when it has none), from step 3. */
    private double faceNx;
    private double faceNy;
    private double faceNz;
    // W * CTM and its normal transform, for the CTM they were made from.
    private Matrix4 madeFrom;
    private Matrix4 madeWith;
    private Matrix4 toCamera;
    private Matrix4 normals;
    /** The CTM and style of the obj command whose faces are being drawn. */
    private Matrix4 objCtm;
    private boolean objWire;
    private Path objFile;
    /**
     * A wire model's edges drawn twice: a face's edge that an earlier face of
     * the same obj command drew already, both faces whole in view (no vertex
     * outside a plane), is not drawn again, as it would change nothing. Its
     * ends are the same vertices, projected by the same expressions to the
     * same bits. The DDA walks an edge the same way whichever end it is given
     * first (DdaWalk.start orders them), but for an edge whose ends fall on
     * one pixel, which takes its values from the end given first: so each
     * pixel of the edge has the z the first drawing gave it, or, on one
     * pixel, the z of one of its ends, which that pixel had already (a face
     * drawn whole gives each vertex's pixel the vertex's own values, by the
     * edge that leaves it, or an earlier face did by that edge). The depth
     * there is that z or nearer since, and a pixel passes only where its z is
     * above the depth: none passes. Only while nothing follows the fragments
     * (no trace, no watch), which would see the second drawing. edgeFaces
     * holds, for the face at hand's corners, the earlier face with each
     * corner's edge (ObjFace.edgeFirstFace), and edgesKnown whether it is
     * known; drawnWhole the faces of this command drawn whole, one bit each
     * (faces below drawnWholeWords * 64).
     */
    private boolean edgesKnown;
    private long edgesLeftOut;
    private int faceIndex;
    private int[] edgeFaces = new int[8];
    private long[] drawnWhole = new long[0];
    private int drawnWholeWords;
    private long culled;
    /** The planes every culled primitive lies wholly outside of (see {@link #culledOutside}). */
    private int culledOutside;
    /** Primitives not culled that the clipper cut away whole. */
    private long clippedAway;
    /** The sides of the view every one of those reaches beyond (see {@link #clippedAwayOutside}). */
    private int clippedAwayOutside;
    /**
     * Whether a primitive not culled had a vertex nearer than the far plane
     * of its fog (or no fog); while not, the fog of the first one, which
     * every one so far lies wholly beyond: drawn in the fog's colour alone.
     */
    private boolean anyNearerThanFog;
    private Fog firstFoggedWhole;
    private long primitives;
    /**
     * Filled polygons lit so far (after culling), and whether one of them was
     * lit by anything or fogged in a colour: while not, every one came out
     * black. Once one was, nothing more is asked per primitive.
     */
    private long shaded;
    private boolean anyNotBlack;
    /**
     * Filled polygons lit while a light of some intensity was on, and whether
     * such a light stood in front of one of them (or one had normals of its
     * own, which no test here judges): while not, no light reached the front
     * of any, and each showed the ambient light alone.
     */
    private long shadedUnderLights;
    private boolean anyLightReached;
    /** Polygons whose normals were made ({@link #facesWithNormals}). */
    private long facesWithNormals;
    /**
     * The unit face normal of the first polygon judged with every light behind it, and whether another such
     * polygon faced against it (normals at more than 90 degrees): lights behind faces that face opposite ways
     * stand between them, inside what they enclose, which no turning of the faces mends.
     */
    private double[] firstBehind;
    private boolean behindFacingOppositeWays;
    /** Primitives not drawn because a vertex is not finite in camera space; the first one's line, for an obj face. */
    private long nonFinite;
    private int firstNonFiniteLine;
    /** Who follows the primitives, or null; where the primitive at hand comes from; how many were told. */
    private PrimitiveTrace trace;
    private Path sourceFile;
    private int sourceLine;
    private int traced;
    /** The camera-space box of the clipped vertices of every primitive told to the trace: min x, y, z, max x, y, z. */
    private final double[] shown = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
        Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};

    /** Where the primitives are recorded to be drawn by several threads; null: drawn here, at once. */
    private LitPrimitives record;

    public LitGeometry(LitState state, FragmentStage fragments) {
        this.state = state;
        this.fragments = fragments;
        this.raster = fragments;
    }

    /**
     * From now on the rasterizers hand their fragments to {@code sink}, which
     * passes each on to this stage's fragment stage (the inspector's one-pixel
     * watch); null: straight to the fragment stage again, the default.
     */
    public void fragmentsThrough(FragmentSink sink) {
        raster = sink == null ? fragments : sink;
    }

    /**
     * From now on the primitives are recorded in {@code to}, to be drawn by
     * its threads, instead of drawn at once (null: at once again). Call
     * before the scene is read.
     */
    public void recordTo(LitPrimitives to) {
        record = to;
    }

    @Override
    public void line(Matrix4 ctm, double[] xyz, double[] rgb) {
        primitives++;
        transform(ctm);
        for (int k = 0; k < 2; k++) {
            vertex(k, xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]);
            colour(k, rgb, 3 * k);
            ownNormal[k] = false;
        }
        if (!finite(2)) {
            return;
        }
        if (culled(state.camera(), 2)) {
            skipped(Painter.LINE, true, 2);
            return;
        }
        if (!anyNearerThanFog) {
            lookAtFog(2);
        }
        if (trace != null && trace.wantsSource()) {
            trace.unclipped(cam, 0, CAMERA_STRIDE, 2);
        }
        if (!clipper.clipLine(state.camera(), cam, 0, CAMERA_STRIDE)) {
            clippedAway(state.camera(), 2);
            skipped(Painter.LINE, false, 2);
        } else {
            carriedColours(2, false);
            int n = project(clipper.vertices(), 2, FragmentLayout.COLOUR_CHANNELS);
            if (n == 2 && (trace == null || traced(Painter.LINE, FragmentLayout.COLOUR_CHANNELS, 2))) {
                if (record != null) {
                    record.add(LitPrimitives.Kind.LINE, screen, 2, FragmentLayout.COLOUR_CHANNELS,
                            record.look(state.fog(), null, oneColour));
                    return;
                }
                lines.draw(screen, 0, FragmentLayout.stride(FragmentLayout.COLOUR_CHANNELS), FragmentLayout.COLOUR_CHANNELS,
                        fragments.width(), fragments.height(), raster);
            }
        }
    }

    @Override
    public void polygon(Matrix4 ctm, double[] xyz, double[] rgb, boolean wire) {
        edgesKnown = false;
        transform(ctm);
        for (int k = 0; k < 3; k++) {
            vertex(k, xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]);
            colour(k, rgb, 3 * k);
            ownNormal[k] = false;
        }
        face(3, wire);
    }

    /** Starts the faces of an {@code obj} command: the model in {@code file}, drawn with this CTM and style. */
    public void beginObj(Matrix4 ctm, boolean wire, Path file) {
        objCtm = ctm;
        objWire = wire;
        objFile = file;
        Arrays.fill(drawnWhole, 0, drawnWholeWords, 0);
        drawnWholeWords = 0;
    }

    /** How many polygons so far had their normals made: those a light or the trace reads ({@link #normalsRead}). */
    public long facesWithNormals() {
        return facesWithNormals;
    }

    /** How many edges of wire models were not drawn again so far ({@link #edgesKnown}). */
    public long edgesLeftOut() {
        return edgesLeftOut;
    }

    /** Whether the faces of the obj command at hand are to tell which earlier face shares each edge. */
    public boolean readsEdges() {
        return objWire && trace == null && raster == fragments;
    }

    /** One face of the model begun by {@link #beginObj}: the obj reader's faces come here, in file order. */
    public void face(ObjFace f) {
        sourceFile = objFile;
        sourceLine = f.line();
        int n = f.size();
        room(n);
        faceIndex = f.index();
        edgesKnown = faceIndex >= 0 && readsEdges();
        if (edgesKnown) {
            if (edgeFaces.length < n) {
                edgeFaces = new int[2 * n];
            }
            for (int k = 0; k < n; k++) {
                edgeFaces[k] = f.edgeFirstFace(k);
            }
        }
        transform(objCtm);
        boolean normalsRead = normalsRead(objWire);
        for (int k = 0; k < n; k++) {
            vertex(k, f.x(k), f.y(k), f.z(k));
            int o = k * CAMERA_STRIDE;
            if (f.hasColor(k)) {
                cam[o + CR] = clamp(f.r(k));
                cam[o + CG] = clamp(f.g(k));
                cam[o + CB] = clamp(f.b(k));
            } else {
                colour(k, null, 0);
            }
            ownNormal[k] = f.hasNormal(k);
            if (ownNormal[k] && normalsRead) {
                normal(k, f.nx(k), f.ny(k), f.nz(k));
            }
        }
        if (trace != null && trace.wantsSource()) {
            if (written.length < 3 * n) {
                written = new double[6 * n];
            }
            for (int k = 0; k < n; k++) {
                written[3 * k] = f.x(k);
                written[3 * k + 1] = f.y(k);
                written[3 * k + 2] = f.z(k);
            }
            trace.source(objCtm, written, n);
        }
        face(n, objWire);
    }

    /** Steps 2 to 7 for a polygon whose n camera-space vertices are in place. */
    private void face(int n, boolean wire) {
        primitives++;
        if (!finite(n)) {
            return;
        }
        Camera camera = state.camera();
        if (culled(camera, n)) {
            skipped(wire ? Painter.WIRE : Painter.FILLED, true, n);
            return;
        }
        if (!anyNearerThanFog) {
            lookAtFog(n);
        }
        boolean normalsRead = normalsRead(wire);
        if (normalsRead) {
            facesWithNormals++;
            faceNormals(n);
        }
        int channels = wire ? FragmentLayout.COLOUR_CHANNELS : shade(n);
        boolean phong = channels == FragmentLayout.PHONG_CHANNELS;
        if (phong && !normalsRead) {
            channels = FragmentLayout.COLOUR_CHANNELS; // lit by the ambient term alone: its pixels read z and kd only
        }
        if (trace != null && trace.wantsSource()) {
            trace.unclipped(cam, 0, CAMERA_STRIDE, n);
            if (!anyOwnNormal(n)) {
                trace.faceNormalOnly();
            }
            if (!wire && state.shading() == LitState.ShadingMode.FLAT) {
                trace.litOnce(litOnce);
            } else if (!wire && state.shading() == LitState.ShadingMode.GOURAUD) {
                trace.litEach(litEach, n);
            }
        }
        int kept = clipper.clipPolygon(camera, cam, 0, n);
        if (kept < 3) {
            clippedAway(camera, n);
            skipped(wire ? Painter.WIRE : Painter.FILLED, false, n);
            return;
        }
        carriedColours(kept, phong);
        boolean whole = edgesKnown && clipper.cutPlanes() == 0 && kept == n;
        if (record != null && trace == null) {
            // Projected straight into the record's batch: no copy of the vertices.
            double[] into = record.room(kept, channels);
            if (project(clipper.vertices(), kept, channels, into, record.roomAt()) == kept) {
                long drawnBefore = whole ? edgesDrawnBefore(kept) : 0;
                record.addInRoom(wire ? LitPrimitives.Kind.OUTLINE : LitPrimitives.Kind.FILL, kept, channels,
                        recordedLook(phong), drawnBefore);
            }
            return;
        }
        int m = project(clipper.vertices(), kept, channels);
        if (m < kept) {
            return; // a vertex that cannot be projected (not finite)
        }
        if (trace != null && !traced(wire ? Painter.WIRE : Painter.FILLED, channels, kept)) {
            return;
        }
        if (record != null) {
            record.add(wire ? LitPrimitives.Kind.OUTLINE : LitPrimitives.Kind.FILL, screen, kept, channels,
                    recordedLook(phong));
            return;
        }
        int width = fragments.width();
        int height = fragments.height();
        if (!wire) {
            fill.fill(screen, kept, channels, width, height, raster);
            return;
        }
        lines.outline(screen, 0, kept, channels, whole ? edgesDrawnBefore(kept) : 0, width, height, raster);
    }

    /**
     * Of the wire face at hand, of n corners and drawn whole in view: the
     * edges an earlier face of this obj command drew whole already, one bit
     * each (edge k from corner k to corner k + 1, the first 64; see
     * {@link #edgesKnown}); and the face noted as drawn whole.
     */
    private long edgesDrawnBefore(int n) {
        long before = 0;
        for (int k = 0; k < n && k < Long.SIZE; k++) {
            int first = edgeFaces[k];
            if (first >= 0 && first >>> 6 < drawnWholeWords && (drawnWhole[first >>> 6] >>> first & 1) != 0) {
                before |= 1L << k;
                edgesLeftOut++;
            }
        }
        int word = faceIndex >>> 6;
        if (word >= drawnWhole.length) {
            drawnWhole = Arrays.copyOf(drawnWhole, Math.max(2 * drawnWhole.length, word + 1));
        }
        drawnWhole[word] |= 1L << faceIndex;
        drawnWholeWords = Math.max(drawnWholeWords, word + 1);
        return before;
    }

    /**
     * Notes whether the primitive at hand, its n camera-space vertices in
     * place and not culled, has a vertex nearer than its fog's far plane.
     * When none has, every point of it (each a mean of its vertices) is at
     * or beyond far, and SPEC's fog gives it the fog's colour alone.
     */
    private void lookAtFog(int n) {
        Fog fog = state.fog();
        for (int k = 0; k < n && !anyNearerThanFog; k++) {
            anyNearerThanFog = fog.isNone() || cam[k * CAMERA_STRIDE + CZ] > fog.far();
        }
        if (!anyNearerThanFog && firstFoggedWhole == null) {
            firstFoggedWhole = fog;
        }
    }

    /**
     * The fog of the first primitive drawn, when every primitive drawn (not
     * culled) lies wholly at or beyond the far plane of its fog, and so is
     * the fog's colour alone; null otherwise.
     */
    public Fog everyPrimitiveFoggedWhole() {
        return anyNearerThanFog ? null : firstFoggedWhole;
    }

    /** Counts a primitive of n camera-space vertices, not culled, that the clipper cut away whole. */
    private void clippedAway(Camera camera, int n) {
        int reaches = camera.outsideAny(cam, CAMERA_STRIDE, n);
        clippedAwayOutside = clippedAway++ == 0 ? reaches : clippedAwayOutside & reaches;
    }

    /** Step 2: whether the n camera-space vertices are all outside one plane of the view; counted so. */
    private boolean culled(Camera camera, int n) {
        int outside = camera.outsideEvery(cam, CAMERA_STRIDE, n);
        if (outside == 0) {
            return false;
        }
        culledOutside = culled++ == 0 ? outside : culledOutside & outside;
        return true;
    }

    /**
     * Whether the n camera-space vertices are finite; else the primitive is
     * counted, its face's line noted for an obj, and not drawn (a NaN vertex
     * would be culled as outside every plane, an infinite one lost in the
     * clipper's lerps: either way silently). One sum per primitive: a sum
     * that is not finite (which large finite numbers can also make) is looked
     * at vertex by vertex.
     */
    private boolean finite(int n) {
        double sum = 0;
        for (int k = 0; k < n; k++) {
            int o = k * CAMERA_STRIDE;
            sum += cam[o + CX] + cam[o + CY] + cam[o + CZ];
        }
        if (Double.isFinite(sum) || GeometryStage.allFinite(cam, CAMERA_STRIDE, n)) {
            return true;
        }
        if (nonFinite++ == 0) {
            firstNonFiniteLine = sourceLine;
        }
        return false;
    }

    /** How a recorded polygon is shaded: lit at every pixel as the state lights now (phong), or its colours fogged. */
    private int recordedLook(boolean phong) {
        return record.look(state.fog(), phong ? state : null, oneColour);
    }

    /**
     * Step 5's end: whether the primitive's n clipped vertices share one
     * colour, or for a {@code phong} polygon one kd ({@link #oneColour}),
     * and the fragment stage told so, with how the primitive is shaded (lit
     * at every pixel, or its colours fogged). A flat polygon always does
     * (each vertex has the lit colour, and the clipper's lerp
     * {@code a + t (b - a)} keeps a value both ends share); a line or
     * outline of the surface colour, a gouraud polygon whose vertices are
     * lit alike, or a phong polygon of the surface colour does too. A colour
     * that is not a number never equals itself, so it is lerped as before.
     */
    private void carriedColours(int n, boolean phong) {
        double[] v = clipper.vertices();
        boolean one = true;
        for (int k = 1; k < n && one; k++) {
            int o = k * CAMERA_STRIDE;
            one = v[o + CR] == v[CR] && v[o + CG] == v[CG] && v[o + CB] == v[CB];
        }
        oneColour = one && v[CR] == v[CR] && v[CG] == v[CG] && v[CB] == v[CB];
        if (phong) {
            fragments.phong(phongShader(), state.fog(), oneColour);
        } else if (oneColour) {
            fragments.oneColour(state.fog());
        } else {
            fragments.colours(state.fog());
        }
    }

    /**
     * Step 4 for a filled polygon: flat and gouraud put the lit colour in
     * place of kd; phong leaves kd and the normals for the fragment stage.
     *
     * @return the channels the fragments will carry
     */
    private int shade(int n) {
        shaded++;
        if (!anyNotBlack || !anyLightReached) {
            lookForLight(n);
        }
        return switch (state.shading()) {
            case FLAT -> {
                flat(n);
                yield FragmentLayout.COLOUR_CHANNELS; // the fragment stage is told once clipped: carriedColours
            }
            case GOURAUD -> {
                if (trace != null && litEach.length < 3 * n) {
                    litEach = new double[6 * n];
                }
                for (int k = 0; k < n; k++) {
                    int o = k * CAMERA_STRIDE;
                    if (trace != null) {
                        litEach[3 * k] = cam[o + CR];
                        litEach[3 * k + 1] = cam[o + CG];
                        litEach[3 * k + 2] = cam[o + CB];
                    }
                    state.shade(cam[o + CX], cam[o + CY], cam[o + CZ], cam[o + CNX], cam[o + CNY], cam[o + CNZ],
                            cam[o + CR], cam[o + CG], cam[o + CB], lit);
                    cam[o + CR] = lit[0];
                    cam[o + CG] = lit[1];
                    cam[o + CB] = lit[2];
                }
                yield FragmentLayout.COLOUR_CHANNELS; // the fragment stage is told once clipped: carriedColours
            }
            case PHONG -> {
                yield FragmentLayout.PHONG_CHANNELS; // the fragment stage is told once clipped: carriedColours
            }
        };
    }

    /**
     * Notes whether a light reaches the filled polygon at hand, whose n
     * camera-space vertices and normals are in place, and whether anything
     * makes it other than black. A light reaches it when it stands in front
     * of its face normal at one of its vertices ({@link LitState#lightInFront});
     * with a normal of its own at some vertex, or no face normal (three
     * vertices on a line), any light of some intensity is taken to reach it,
     * as nothing here tells.
     */
    private void lookForLight(int n) {
        boolean reached = false;
        if (state.anyLightOn()) {
            shadedUnderLights++;
            boolean faceNormalOnly = !anyOwnNormal(n) && (faceNx != 0 || faceNy != 0 || faceNz != 0);
            reached = !faceNormalOnly || state.lightInFront(faceNx, faceNy, faceNz, cam, CAMERA_STRIDE, n);
            if (!reached && !anyLightReached) {
                noteBehind();
            }
        }
        anyLightReached |= reached;
        if (!anyNotBlack) {
            Fog fog = state.fog();
            anyNotBlack = reached || state.ambientR() + state.ambientG() + state.ambientB() > 0
                    || fog.r() + fog.g() + fog.b() > 0;
        }
    }

    /** Notes the face normal of a polygon every light stands behind ({@link #firstBehind}). */
    private void noteBehind() {
        if (firstBehind == null) {
            firstBehind = new double[] {faceNx, faceNy, faceNz};
        } else if (faceNx * firstBehind[0] + faceNy * firstBehind[1] + faceNz * firstBehind[2] < 0) {
            behindFacingOppositeWays = true;
        }
    }

    /** True when one of the n vertices has a normal of its own. */
    private boolean anyOwnNormal(int n) {
        for (int k = 0; k < n; k++) {
            if (ownNormal[k]) {
                return true;
            }
        }
        return false;
    }

    /**
     * What lights phong pixels: the state itself, or, when the fragment
     * stage shades them later ({@link FragmentStage#shadeLater}), the
     * state's lighting as it is now, frozen, made again only once it changed.
     */
    private PointShader phongShader() {
        if (!fragments.shadesLater()) {
            return state;
        }
        Supplier<PointShader> now = state.frozenShader(); // the same while the lighting is unchanged
        if (now != frozenFrom) {
            frozenFrom = now;
            frozen = now.get();
        }
        return frozen;
    }

    /** One colour for the polygon: lit at the centroid, with the mean kd and the mean own normal or the face's. */
    private void flat(int n) {
        double px = 0, py = 0, pz = 0, kr = 0, kg = 0, kb = 0, nx = 0, ny = 0, nz = 0;
        for (int k = 0; k < n; k++) {
            int o = k * CAMERA_STRIDE;
            px += cam[o + CX];
            py += cam[o + CY];
            pz += cam[o + CZ];
            kr += cam[o + CR];
            kg += cam[o + CG];
            kb += cam[o + CB];
            nx += cam[o + CNX];
            ny += cam[o + CNY];
            nz += cam[o + CNZ];
        }
        if (!allOwnNormals(n)) {
            nx = faceNx;
            ny = faceNy;
            nz = faceNz;
        }
        double cx = px / n;
        double cy = py / n;
        double cz = pz / n;
        double meanR = kr / n;
        double meanG = kg / n;
        double meanB = kb / n;
        state.shade(cx, cy, cz, nx, ny, nz, meanR, meanG, meanB, lit);
        if (trace != null) {
            double[] once = litOnce;
            once[0] = cx;
            once[1] = cy;
            once[2] = cz;
            once[3] = nx;
            once[4] = ny;
            once[5] = nz;
            once[6] = meanR;
            once[7] = meanG;
            once[8] = meanB;
        }
        for (int k = 0; k < n; k++) {
            int o = k * CAMERA_STRIDE;
            cam[o + CR] = lit[0];
            cam[o + CG] = lit[1];
            cam[o + CB] = lit[2];
        }
    }

    /**
     * Step 3: the face normal (p2 - p1) x (p3 - p1), unit or zero, given to
     * every vertex without its own; not made when every vertex has its own
     * (flat shading reads it only when one has not).
     */
    private void faceNormals(int n) {
        if (allOwnNormals(n)) {
            return;
        }
        int b = CAMERA_STRIDE;
        int c = 2 * CAMERA_STRIDE;
        double e1x = cam[b + CX] - cam[CX];
        double e1y = cam[b + CY] - cam[CY];
        double e1z = cam[b + CZ] - cam[CZ];
        double e2x = cam[c + CX] - cam[CX];
        double e2y = cam[c + CY] - cam[CY];
        double e2z = cam[c + CZ] - cam[CZ];
        double nx = e1y * e2z - e1z * e2y;
        double ny = e1z * e2x - e1x * e2z;
        double nz = e1x * e2y - e1y * e2x;
        double length = Math.sqrt(nx * nx + ny * ny + nz * nz);
        boolean usable = length > 0 && Double.isFinite(length);
        faceNx = usable ? nx / length : 0;
        faceNy = usable ? ny / length : 0;
        faceNz = usable ? nz / length : 0;
        for (int k = 0; k < n; k++) {
            if (!ownNormal[k]) {
                int o = k * CAMERA_STRIDE;
                cam[o + CNX] = faceNx;
                cam[o + CNY] = faceNy;
                cam[o + CNZ] = faceNz;
            }
        }
    }

    /**
     * Whether a polygon's normals are read: the trace, when one follows, reads them all; a filled polygon is lit
     * with them while there is a light, and under the ambient term alone reads none ({@link LitState#shade},
     * {@link FragmentStage#channelsRead}); an outline ({@code wire}) is drawn in its colours, unlit.
     */
    private boolean normalsRead(boolean wire) {
        return trace != null || !wire && state.lightCount() > 0;
    }

    /** True when each of the n vertices has its own normal: then no face normal is made or read. */
    private boolean allOwnNormals(int n) {
        boolean all = true;
        for (int k = 0; k < n; k++) {
            all &= ownNormal[k];
        }
        return all;
    }

    /**
     * Step 6: the first n clipped vertices to panel space, channels times q (one colour or kd as it is:
     * {@link #oneColour}).
     *
     * @return how many could be projected (all of them unless one is not finite)
     */
    private int project(double[] v, int n, int channels) {
        int stride = FragmentLayout.stride(channels);
        if (screen.length < n * stride) {
            screen = new double[2 * n * stride];
        }
        return project(v, n, channels, screen, 0);
    }

    /** The same into {@code out} from {@code at}, which has room for them. */
    private int project(double[] v, int n, int channels, double[] out, int at) {
        Camera camera = state.camera();
        int stride = FragmentLayout.stride(channels);
        for (int k = 0; k < n; k++) {
            int i = k * CAMERA_STRIDE;
            int o = at + k * stride;
            double x = v[i + CX];
            double y = v[i + CY];
            double z = v[i + CZ];
            double q = camera.q(z);
            double sx = camera.panelX(x, z);
            double sy = camera.panelY(y, z);
            if (!Double.isFinite(sx) || !Double.isFinite(sy) || !Double.isFinite(q)) {
                return k;
            }
            out[o + FragmentLayout.X] = sx;
            out[o + FragmentLayout.Y] = sy;
            out[o + FragmentLayout.Q] = q;
            out[o + FragmentLayout.CHANNEL + FragmentLayout.Z] = z * q;
            double colourTimes = oneColour ? 1 : q;
            out[o + FragmentLayout.CHANNEL + FragmentLayout.R] = v[i + CR] * colourTimes;
            out[o + FragmentLayout.CHANNEL + FragmentLayout.G] = v[i + CG] * colourTimes;
            out[o + FragmentLayout.CHANNEL + FragmentLayout.B] = v[i + CB] * colourTimes;
            if (channels == FragmentLayout.PHONG_CHANNELS) {
                out[o + FragmentLayout.CHANNEL + FragmentLayout.PX] = x * q;
                out[o + FragmentLayout.CHANNEL + FragmentLayout.PY] = y * q;
                out[o + FragmentLayout.CHANNEL + FragmentLayout.NX] = v[i + CNX] * q;
                out[o + FragmentLayout.CHANNEL + FragmentLayout.NY] = v[i + CNY] * q;
                out[o + FragmentLayout.CHANNEL + FragmentLayout.NZ] = v[i + CNZ] * q;
            }
        }
        return n;
    }

    /** W * CTM and its normal transform, made again only when the CTM or the camera changed. */
    private void transform(Matrix4 ctm) {
        Matrix4 w = state.worldToCamera();
        if (ctm != madeFrom || w != madeWith) {
            madeFrom = ctm;
            madeWith = w;
            toCamera = w.times(ctm);
            normals = toCamera.normalTransform();
        }
    }

    /** Step 1 for vertex k's position. */
    private void vertex(int k, double x, double y, double z) {
        int o = k * CAMERA_STRIDE;
        Matrix4 m = toCamera;
        cam[o + CX] = m.applyX(x, y, z);
        cam[o + CY] = m.applyY(x, y, z);
        cam[o + CZ] = m.applyZ(x, y, z);
    }

    /** Vertex k's kd: its own colour from rgb[at], else the surface colour. */
    private void colour(int k, double[] rgb, int at) {
        int o = k * CAMERA_STRIDE;
        cam[o + CR] = rgb == null ? state.kdR() : rgb[at];
        cam[o + CG] = rgb == null ? state.kdG() : rgb[at + 1];
        cam[o + CB] = rgb == null ? state.kdB() : rgb[at + 2];
    }

    /** Step 1 for vertex k's own normal: by the normal transform, made unit length (zero stays zero). */
    private void normal(int k, double x, double y, double z) {
        Matrix4 m = normals;
        double nx = m.applyX(x, y, z);
        double ny = m.applyY(x, y, z);
        double nz = m.applyZ(x, y, z);
        double length = Math.sqrt(nx * nx + ny * ny + nz * nz);
        boolean usable = length > 0 && Double.isFinite(length);
        int o = k * CAMERA_STRIDE;
        cam[o + CNX] = usable ? nx / length : 0;
        cam[o + CNY] = usable ? ny / length : 0;
        cam[o + CNZ] = usable ? nz / length : 0;
    }

    private static double clamp(double c) {
        return c < 0 ? 0 : c > 1 ? 1 : c;
    }

    /** Room for a face of n vertices. */
    private void room(int n) {
        if (ownNormal.length < n) {
            ownNormal = new boolean[2 * n];
            cam = new double[2 * n * CAMERA_STRIDE];
        }
    }

    /**
     * From now on tells {@code follower} of every primitive about to be
     * rasterized (null: nobody). Lines and polygons of the SIMP file say
     * where they stand with {@link #from}; .obj faces name their model's
     * file and line themselves.
     */
    public void follow(PrimitiveTrace follower) {
        trace = follower;
    }

    /** The next line or polygon is the command at {@code line} of {@code file}. */
    public void from(Path file, int line) {
        sourceFile = file;
        sourceLine = line;
    }

    /**
     * The centre of the camera-space box around every primitive told to the
     * trace, as clipped (what the view showed), or null when none was.
     */
    public double[] shownCentre() {
        if (!(shown[0] <= shown[3])) {
            return null;
        }
        return new double[] {(shown[0] + shown[3]) / 2, (shown[1] + shown[4]) / 2, (shown[2] + shown[5]) / 2};
    }

    /**
     * Tells the trace of the primitive whose n projected vertices are in
     * {@code screen} and whose clipped camera-space ones are the clipper's;
     * false when it is to be left out.
     */
    private boolean traced(int kind, int channels, int n) {
        double[] v = clipper.vertices();
        for (int k = 0; k < n; k++) {
            for (int axis = 0; axis < 3; axis++) {
                double c = v[k * CAMERA_STRIDE + axis];
                shown[axis] = Math.min(shown[axis], c);
                shown[3 + axis] = Math.max(shown[3 + axis], c);
            }
        }
        int index = traced++;
        if (oneColour) {
            trace.oneColour(); // for the read just below
        }
        trace.read(index, sourceFile, sourceLine, kind, screen, 0, FragmentLayout.stride(channels), n);
        return trace.drawing(index);
    }

    /** Tells the trace, if any, of a primitive culled or clipped away, with its n camera-space vertices. */
    private void skipped(int kind, boolean wasCulled, int n) {
        if (trace != null) {
            trace.skipped(sourceFile, sourceLine, kind, wasCulled, cam, 0, CAMERA_STRIDE, n);
        }
    }

    @Override
    public long culledCount() {
        return culled;
    }

    @Override
    public int culledOutside() {
        return culledOutside;
    }

    @Override
    public long clippedAwayCount() {
        return clippedAway;
    }

    @Override
    public int clippedAwayOutside() {
        return clippedAwayOutside;
    }

    @Override
    public long primitiveCount() {
        return primitives;
    }

    @Override
    public long nonFiniteCount() {
        return nonFinite;
    }

    /**
     * True when polygons were lit (filled, not culled) and every one of them
     * came out black because nothing lit it: no ambient light, no fog of a
     * colour, at its command, and no light of some intensity in front of it
     * (SPEC's formula then gives 0 whatever the surface). Lines and wire
     * polygons are not lit.
     */
    public boolean everyLitPolygonBlack() {
        return shaded > 0 && !anyNotBlack;
    }

    /**
     * True when filled polygons were lit while a light of some intensity was
     * on, and that light, and every other, stood behind each of them (their
     * face normals turned away from it): no light reached the front of any,
     * so each shows the ambient light alone (black without one).
     */
    public boolean noLightReachedAPolygon() {
        return shadedUnderLights > 0 && !anyLightReached;
    }

    /**
     * True when {@link #noLightReachedAPolygon} and two of those polygons face opposite ways (their face normals
     * at more than 90 degrees): the lights stand behind both, between them, most often inside a closed model,
     * where turning the faces round would not light what the camera sees.
     */
    public boolean lightsInsideThePolygons() {
        return noLightReachedAPolygon() && behindFacingOppositeWays;
    }

    /** The line in its model of the first primitive {@link #nonFiniteCount} counted, when that was an obj face. */
    public int firstNonFiniteLine() {
        return firstNonFiniteLine;
    }
}

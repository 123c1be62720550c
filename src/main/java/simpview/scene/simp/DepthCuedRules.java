package simpview.scene.simp;

import java.util.function.Supplier;
import simpview.geometry.Matrix4;
import simpview.geometry.Vertex;
import simpview.stage.CuedPrimitives;
import simpview.stage.CuedRenderers;
import simpview.stage.DepthCuedGeometry;
import simpview.stage.Painter;
import simpview.stage.PrimitiveSink;
import simpview.stage.PrimitiveTrace;
import simpview.surface.Drawable;
import simpview.surface.DrawingThreads;
import simpview.surface.OwedRows;
import simpview.surface.Provenance;
import simpview.surface.ZBuffer;

/**
 * A scene by the depth-cued rules (SPEC Part 1): each line and polygon goes
 * through the depth-cued geometry stage to the painter, which draws it on a
 * panel drawable that already does what the page wants done per pixel
 * (scissor, z-buffer, depth cue). A big scene's reader may send the
 * transformed primitives to batches instead ({@link #sendTo}), for the
 * painter to draw on another thread.
 */
final class DepthCuedRules implements RuleSet {

    private final Painter painter;
    private final DepthCuedGeometry geometry;
    private final FileStack files;
    /** Who follows the primitives (the window's instruments), or null: nobody, at no cost. */
    private final PrimitiveTrace trace;
    /** The window's turn of the view, applied before the CTM (the world turns before the depth cue), or null. */
    private final Matrix4 turn;
    private final FirstNonFinite firstNonFinite;
    private Matrix4 lastCtm;
    private Matrix4 turnedCtm;
    private int traced;
    /** The record several threads draw from, or null: drawn at once, on this thread. */
    private CuedPrimitives record;

    /** The project's renderers on {@code panel}: DDA lines, top-left-rule fills, wireframes of DDA lines. */
    DepthCuedRules(Drawable panel, FileStack files, PrimitiveTrace trace, Matrix4 turn) {
        this(CuedRenderers.make().painter(panel), files, trace, turn);
    }

    /** Drawing with {@code painter} (tests give it renderers that record). */
    DepthCuedRules(Painter painter, FileStack files, PrimitiveTrace trace, Matrix4 turn) {
        this.painter = painter;
        this.geometry = new DepthCuedGeometry(painter);
        this.firstNonFinite = new FirstNonFinite(geometry);
        this.files = files;
        this.trace = trace;
        this.turn = turn;
        painter.follow(trace);
        geometry.follow(trace);
        sendTo(painter);
    }

    @Override
    public void line(Matrix4 ctm, double[] xyz, double[] rgb) {
        source(ctm, xyz, 2);
        geometry.line(viewed(ctm), xyz, rgb);
        firstNonFinite.note(files, "line");
    }

    @Override
    public void polygon(Matrix4 ctm, double[] xyz, double[] rgb, boolean wire) {
        source(ctm, xyz, 3);
        geometry.polygon(viewed(ctm), xyz, rgb, wire);
        firstNonFinite.note(files, "polygon");
    }

    @Override
    public DepthCuedGeometry geometry() {
        return geometry;
    }

    @Override
    public String firstNonFinite() {
        return firstNonFinite.place();
    }

    /** After the transforms (a depth-cued scene has no camera: the CTM goes straight to the panel), or on the panel. */
    @Override
    public String nonFiniteWhy() {
        return geometry.firstBeyondPanel()
                ? "a vertex lies too far out to draw: its numbers and the CTM's are finite, but its panel"
                        + " coordinates (650 pixels to 200 units), or the filled triangle's area there, go beyond"
                        + " about 1.8e308"
                : "a vertex comes out infinite or NaN after the transforms (its numbers are finite, but the CTM"
                        + " takes them beyond about 1.8e308)";
    }

    /** Tells a trace that wants them the primitive's vertices as written and the CTM (as turned for the view). */
    private void source(Matrix4 ctm, double[] xyz, int vertices) {
        if (trace != null && trace.wantsSource()) {
            trace.source(viewed(ctm), xyz, vertices);
        }
    }

    /** turn * ctm, worked out again only when the CTM changed (it is a new object each time it does). */
    private Matrix4 viewed(Matrix4 ctm) {
        if (turn == null) {
            return ctm;
        }
        if (ctm != lastCtm) {
            lastCtm = ctm;
            turnedCtm = turn.times(ctm);
        }
        return turnedCtm;
    }

    Painter painter() {
        return painter;
    }

    /**
     * With more than one of {@code threads}: from now on the primitives are
     * recorded and drawn band by band onto {@code panel} (the painter's),
     * owners into {@code provenance} (or null). {@code zbuffer} is the one
     * the panel tests against, whose reset owed by the canvas's clear the
     * bands' drawers then make row by row, or null (the panel's own, made by
     * its first test); the panel's rows the canvas's clear owes, asked of
     * {@code panelRows} at the first primitive drawn in bands, are made the
     * same way.
     * Call before the scene is read.
     */
    void drawWith(DrawingThreads threads, ZBuffer zbuffer, Supplier<OwedRows> panelRows, Drawable panel,
            Provenance provenance) {
        if (!threads.isOne()) {
            record = new CuedPrimitives(threads, zbuffer, panelRows, panel, provenance);
            painter.recordTo(record);
        }
    }

    @Override
    public void flush() {
        if (record != null) {
            record.flush();
        }
    }

    /** From now on the transformed primitives go to {@code to} (the painter, or a reader's batches). */
    void sendTo(PrimitiveSink to) {
        geometry.sendTo(trace == null ? to : new Traced(to));
    }

    /** A sink that tells the trace where each primitive came from, then hands it on. */
    private final class Traced implements PrimitiveSink {
        private final PrimitiveSink next;

        Traced(PrimitiveSink next) {
            this.next = next;
        }

        @Override
        public void add(int kind, double[] p) {
            trace.read(traced++, files.current().file(), files.current().lineNumber(), kind, p, 0, Vertex.NUMBERS,
                    kind == Painter.LINE ? 2 : 3);
            next.add(kind, p);
        }
    }
}

package simpview.stage;

import simpview.geometry.Vertex;
import simpview.raster.LineRenderer;
import simpview.raster.PolygonRenderer;
import simpview.surface.Drawable;

/**
 * Draws primitives given as plain numbers in panel space with the scene's
 * renderers. Everything it touches (renderers, panel) belongs to the thread
 * that draws, so it is the only part of a scene that runs there. With
 * several drawing threads it records the primitives instead
 * ({@link CuedPrimitives}), and each band's own painter draws them.
 */
public final class Painter implements PrimitiveSink {

    /*
     * The kinds of primitive, kept as ints because they travel in the
     * recorded batches' number arrays and to the trace; draw below names each
     * and throws for any other, and PainterTest draws every one.
     */
    public static final int LINE = 0;
    public static final int FILLED = 1;
    public static final int WIRE = 2;
    /** Numbers per primitive: room for a polygon's three vertices (panel x, panel y, world z, r, g, b each). */
    public static final int STRIDE = 3 * Vertex.NUMBERS;

    private final Drawable panel;
    private final LineRenderer lines;
    private final PolygonRenderer filled;
    private final PolygonRenderer wire;
    /** Who follows the primitives drawn (the window's instruments), or null. */
    private PrimitiveTrace trace;
    private int drawn;
    /** Where the primitives are recorded to be drawn by several threads, or null: drawn at once. */
    private CuedPrimitives record;

    public Painter(Drawable panel, LineRenderer lines, PolygonRenderer filled, PolygonRenderer wire) {
        this.panel = panel;
        this.lines = lines;
        this.filled = filled;
        this.wire = wire;
    }

    @Override
    public void add(int kind, double[] p) {
        draw(kind, p, 0);
    }

    /** From now on tells {@code follower} of every primitive before drawing it (null: nobody). */
    public void follow(PrimitiveTrace follower) {
        trace = follower;
    }

    /**
     * From now on records the primitives in {@code to}, to be drawn by its
     * threads (null: draws them at once).
     */
    public void recordTo(CuedPrimitives to) {
        record = to;
    }

    /** Draws the primitive whose numbers start at p[at], as numbers: no object per primitive. */
    public void draw(int kind, double[] p, int at) {
        if (trace != null && !trace.drawing(drawn++)) {
            return;
        }
        if (record != null) {
            record.add(kind, p, at);
            return;
        }
        switch (kind) {
            case LINE -> lines.drawLine(p, at, at + Vertex.NUMBERS, panel);
            case FILLED -> filled.drawPolygon(p, at, panel);
            case WIRE -> wire.drawPolygon(p, at, panel);
            default -> throw new AssertionError("primitive kind " + kind + ": a kind added without its case here");
        }
    }
}

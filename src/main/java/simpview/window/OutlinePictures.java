package simpview.window;

import java.awt.AlphaComposite;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.Rectangle;
import java.awt.RenderingHints;
import java.awt.geom.AffineTransform;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import javax.swing.JComponent;
import javax.swing.SwingUtilities;
import simpview.surface.PageCanvas;
import simpview.window.instruments.Outlines;

/**
 * The outlines over the page (W: wire over fill; U: the culled and clipped-away primitives), drawn in opaque
 * colours into pictures of the view's size that the view copies to the screen, the wire's at its share over the
 * page. A picture is drawn again only when the outlines, the zoom, the pan or the view's size changed, and then on
 * the EDT a slice at a time: each slice draws outlines for at most {@link #SLICE_NANOS} and hands the rest to the
 * next, posted behind whatever else waits, so that zooming and panning answer whatever the number of outlines.
 * Only the outlines whose box meets the part of the panel in view are drawn: at a zoom most of them are out of it.
 * Until the new pictures are done the view shows the last ones moved and scaled to where the zoom and pan put them
 * now; a change before they are done drops them and starts again.
 *
 * <p>Drawn whole on each change, 40,000 outlines took 11-13 ms a zoom step on an idle host, and with two busy
 * loops beside it WireOverFillWindowTest's zoom steps froze the window 180-294 ms; in slices, 32-48 ms. Each
 * picture is copied to the screen only over the part its outlines reach: the copy at the wire's share took 2-5 ms
 * of the view alone, up to 35 ms with the busy loops.
 */
final class OutlinePictures {

    /** How long a slice draws before it hands the rest on: well under the 100 ms a stall may take. */
    static final long SLICE_NANOS = 8_000_000;
    /** Outlines drawn together as one path between looks at the clock. */
    private static final int GROUP = 64;

    /** What the pictures are drawn of, and at which zoom, pan and size: equal, they are drawn again the same. */
    record Drawn(List<double[]> wire, List<double[]> culled, List<double[]> clipped, double zoom, double x, double y,
            int unit, int width, int height) {

        double screenX(double imageX) {
            return x + imageX * zoom;
        }

        double screenY(double imageY) {
            return y + imageY * zoom;
        }
    }

    /**
     * The wire's picture and the culled and clipped-away outlines' (null for none), what they are of, and the part of
     * each that the outlines reach (transparent around it: only that part is copied to the screen).
     */
    private record Pictures(Drawn drawn, BufferedImage wire, BufferedImage skipped, int outlines, Rectangle wireReach,
            Rectangle skippedReach) {
    }

    private final JComponent view;
    private final long sliceNanos;
    private final Color wireColour;
    private final Color culledColour;
    private final Color clippedColour;
    /** The pictures last finished, shown until newer ones are; null for none. */
    private Pictures shown;
    /** The pictures being drawn, or null. */
    private Slices drawing;
    /** Pictures no longer shown, drawn into again when of the view's size. */
    private BufferedImage spareWire;
    private BufferedImage spareSkipped;
    /** Slices run to finish the pictures last finished: for the tests. */
    private int slicesTaken;

    /**
     * The outlines over {@code view}, which is repainted once new pictures are done, in these colours, drawn again
     * {@code sliceNanos} a slice.
     */
    OutlinePictures(JComponent view, Color wire, Color culled, Color clipped, long sliceNanos) {
        this.view = view;
        this.wireColour = wire;
        this.culledColour = culled;
        this.clippedColour = clipped;
        this.sliceNanos = sliceNanos;
    }

    /** Forgets the pictures: no outlines are shown. */
    void clear() {
        shown = null;
        drawing = null;
        spareWire = null;
        spareSkipped = null;
    }

    /**
     * Copies the pictures of {@code now} to {@code graphics}, the wire at {@code wireShare} over what is there;
     * until they are drawn, the last ones moved to where {@code now} puts them, and the first slice of the new
     * ones drawn now (all of them when there are few).
     */
    void paint(Graphics2D graphics, Drawn now, AlphaComposite wireShare) {
        if (shown == null || !shown.drawn().equals(now)) {
            if (drawing == null || !drawing.drawn.equals(now)) {
                if (drawing != null) {
                    spareWire = drawing.wire;
                    spareSkipped = drawing.skipped;
                }
                drawing = new Slices(now);
                drawing.slice();
                if (!drawing.done()) {
                    Slices started = drawing;
                    SwingUtilities.invokeLater(() -> nextSlice(started));
                }
            }
            if (drawing.done()) {
                finish();
            }
        }
        if (shown == null) {
            return;
        }
        Graphics2D g = (Graphics2D) graphics.create();
        try {
            Drawn then = shown.drawn();
            if (!then.equals(now)) {
                // the last pictures where the new zoom and pan put what they show, until the new ones are done
                double by = now.zoom() / then.zoom();
                g.transform(new AffineTransform(by, 0, 0, by, now.x() - then.x() * by, now.y() - then.y() * by));
                g.setRenderingHint(RenderingHints.KEY_INTERPOLATION,
                        RenderingHints.VALUE_INTERPOLATION_NEAREST_NEIGHBOR);
            }
            // (not the outlines of another picture, or those turned off)
            if (now.wire() != null && now.wire() == then.wire()) {
                g.setComposite(wireShare);
                copy(g, shown.wire(), shown.wireReach());
                g.setComposite(AlphaComposite.SrcOver);
            }
            if (now.culled() != null && now.culled() == then.culled() && now.clipped() == then.clipped()) {
                copy(g, shown.skipped(), shown.skippedReach());
            }
        } finally {
            g.dispose();
        }
    }

    private static void copy(Graphics2D g, BufferedImage picture, Rectangle part) {
        if (!part.isEmpty()) {
            g.drawImage(picture, part.x, part.y, part.x + part.width, part.y + part.height, part.x, part.y,
                    part.x + part.width, part.y + part.height, null);
        }
    }

    private void nextSlice(Slices these) {
        if (drawing != these) {
            return; // a change came first: the view's next paint draws them again
        }
        these.slice();
        if (these.done()) {
            finish();
            view.repaint();
        } else {
            SwingUtilities.invokeLater(() -> nextSlice(these));
        }
    }

    /** The pictures drawn take the place of those shown. */
    private void finish() {
        if (shown != null) {
            spareWire = shown.wire();
            spareSkipped = shown.skipped();
        }
        shown = new Pictures(drawing.drawn, drawing.wire, drawing.skipped, drawing.outlines,
                drawing.reach(drawing.wireBox), drawing.reach(drawing.skippedBox));
        slicesTaken = drawing.slices;
        drawing = null;
    }

    // For tests: what is shown.

    /** Whether the pictures shown are of {@code now}, none still being drawn. */
    boolean finished(Drawn now) {
        return drawing == null && shown != null && shown.drawn().equals(now);
    }

    /** The wire's picture shown, or null. */
    BufferedImage wirePicture() {
        return shown == null ? null : shown.wire();
    }

    /** How many outlines the pictures shown have drawn: those that meet the panel's part in view. */
    int outlinesDrawn() {
        return shown == null ? 0 : shown.outlines();
    }

    /** How many slices the pictures shown took. */
    int slicesTaken() {
        return slicesTaken;
    }

    /**
     * Whether an outline's box, grown by {@code margin}, meets the rectangle from (left, top) to (right, bottom), in
     * the screen coordinates of {@code drawn}; an outline whose coordinates are not numbers is drawn, as Java2D
     * will have it.
     */
    private static boolean meets(double[] points, Drawn drawn, double left, double top, double right, double bottom,
            double margin) {
        double minX = Double.POSITIVE_INFINITY;
        double minY = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY;
        double maxY = Double.NEGATIVE_INFINITY;
        for (int k = 0; k + 1 < points.length; k += 2) {
            double x = drawn.screenX(points[k]);
            double y = drawn.screenY(points[k + 1]);
            if (Double.isNaN(x) || Double.isNaN(y)) {
                return true;
            }
            minX = Math.min(minX, x);
            maxX = Math.max(maxX, x);
            minY = Math.min(minY, y);
            maxY = Math.max(maxY, y);
        }
        return maxX + margin >= left && minX - margin <= right && maxY + margin >= top && minY - margin <= bottom;
    }

    /** New pictures of {@link #drawn}, a slice at a time: the wire's outlines, then the culled, then the clipped. */
    private final class Slices {

        final Drawn drawn;
        final BufferedImage wire;
        final BufferedImage skipped;
        /** The lists still to draw, each with its picture and colour; the first partly drawn up to {@link #next}. */
        private final List<Layer> layers = new ArrayList<>();
        private int next;
        int outlines;
        int slices;
        /** What the paths drawn into each picture cover, in its coordinates; null for nothing drawn. */
        Rectangle2D wireBox;
        Rectangle2D skippedBox;
        /** The part of the panel in view, in screen coordinates, and how far a line's pixels may lie from it. */
        private final double left;
        private final double top;
        private final double right;
        private final double bottom;
        private final double margin;

        private record Layer(List<double[]> shapes, BufferedImage picture, Color colour) {
        }

        Slices(Drawn drawn) {
            this.drawn = drawn;
            wire = drawn.wire() == null ? null : cleared(spareWire, drawn);
            skipped = drawn.culled() == null && drawn.clipped() == null ? null : cleared(spareSkipped, drawn);
            spareWire = null;
            spareSkipped = null;
            layers.add(new Layer(drawn.wire(), wire, wireColour));
            layers.add(new Layer(drawn.culled(), skipped, culledColour));
            layers.add(new Layer(drawn.clipped(), skipped, clippedColour));
            layers.removeIf(layer -> layer.shapes() == null);
            double panelLeft = drawn.screenX(PageCanvas.MARGIN);
            double panelTop = drawn.screenY(PageCanvas.MARGIN);
            double side = PageCanvas.PANEL * drawn.zoom();
            left = Math.max(0, panelLeft);
            top = Math.max(0, panelTop);
            right = Math.min(drawn.width(), panelLeft + side);
            bottom = Math.min(drawn.height(), panelTop + side);
            margin = 2 + drawn.unit();
        }

        boolean done() {
            return layers.isEmpty();
        }

        /** The part of the picture where paths covering {@code box} drew their pixels (all of it for paths not numbers). */
        Rectangle reach(Rectangle2D box) {
            if (box == null) {
                return new Rectangle();
            }
            Rectangle whole = new Rectangle(0, 0, drawn.width(), drawn.height());
            double x0 = box.getMinX() - margin;
            double y0 = box.getMinY() - margin;
            double x1 = box.getMaxX() + margin;
            double y1 = box.getMaxY() + margin;
            if (Double.isNaN(x0 + y0 + x1 + y1)) {
                return whole;
            }
            int left = (int) Math.floor(Math.max(0, x0));
            int top = (int) Math.floor(Math.max(0, y0));
            int right = (int) Math.ceil(Math.min(drawn.width(), x1));
            int bottom = (int) Math.ceil(Math.min(drawn.height(), y1));
            return new Rectangle(left, top, right - left, bottom - top).intersection(whole);
        }

        /**
         * Draws outlines for up to {@link #sliceNanos}, at least one group of them; a list whose last group is
         * drawn is done, however long that took (so a few outlines are drawn whole by the first slice).
         */
        void slice() {
            slices++;
            long until = System.nanoTime() + sliceNanos;
            while (!layers.isEmpty()) {
                Layer layer = layers.get(0);
                Graphics2D g = layer.picture().createGraphics();
                try {
                    g.clip(new Rectangle2D.Double(drawn.screenX(PageCanvas.MARGIN), drawn.screenY(PageCanvas.MARGIN),
                            PageCanvas.PANEL * drawn.zoom(), PageCanvas.PANEL * drawn.zoom()));
                    // Not antialiased: 1-px lines, a dozen times faster to draw than antialiased ones
                    // (Overlays.wireOverFill: page-d's 16,026 outlines 57 ms antialiased, 4.8 ms not, against 9.9 ms
                    // to draw the page).
                    g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_OFF);
                    g.setStroke(new BasicStroke(drawn.unit()));
                    g.setColor(layer.colour());
                    List<double[]> group = new ArrayList<>(GROUP);
                    List<double[]> shapes = layer.shapes();
                    while (next < shapes.size()) {
                        // a group of outlines looked at, those in view drawn, then a look at the clock
                        for (int end = Math.min(shapes.size(), next + GROUP); next < end; next++) {
                            double[] points = shapes.get(next);
                            if (points.length >= 2 && meets(points, drawn, left, top, right, bottom, margin)) {
                                group.add(points);
                            }
                        }
                        if (!group.isEmpty()) {
                            Path2D path = Outlines.path(group, drawn::screenX, drawn::screenY);
                            g.draw(path);
                            outlines += group.size();
                            Rectangle2D box = path.getBounds2D();
                            if (layer.picture() == wire) {
                                wireBox = wireBox == null ? box : wireBox.createUnion(box);
                            } else {
                                skippedBox = skippedBox == null ? box : skippedBox.createUnion(box);
                            }
                            group.clear();
                        }
                        // a list drawn to its end is done whatever the clock says: a slice that returned
                        // before taking it off the layers would leave a few outlines waiting for the next
                        if (next < shapes.size() && System.nanoTime() - until > 0) {
                            return;
                        }
                    }
                } finally {
                    g.dispose();
                }
                layers.remove(0);
                next = 0;
            }
        }
    }

    /** {@code picture}, or a new one when it is not of the view's size, made transparent. */
    private static BufferedImage cleared(BufferedImage picture, Drawn drawn) {
        BufferedImage clear = picture != null && picture.getWidth() == drawn.width()
                && picture.getHeight() == drawn.height() ? picture
                : new BufferedImage(drawn.width(), drawn.height(), BufferedImage.TYPE_INT_ARGB);
        Graphics2D g = clear.createGraphics();
        g.setComposite(AlphaComposite.Clear);
        g.fillRect(0, 0, drawn.width(), drawn.height());
        g.dispose();
        return clear;
    }
}

package simpview.window;

import java.awt.AlphaComposite;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.GraphicsConfiguration;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.RenderingHints;
import java.awt.event.ComponentAdapter;
import java.awt.event.ComponentEvent;
import java.awt.geom.AffineTransform;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.util.List;
import javax.accessibility.AccessibleContext;
import javax.accessibility.AccessibleRole;
import javax.swing.JComponent;
import simpview.pages.A1Marks;
import simpview.surface.PageCanvas;

/**
 * The page on screen: the finished image copied at the zoom and place that
 * {@link ZoomPan} says, nearest-neighbour so every image pixel stays a sharp
 * square (below 1:1, the image {@link LineKeepingDownscale} made smaller,
 * copied 1:1), with overlays drawn over it (pixel grid, the pinned pixel, the
 * outline of a primitive, a scene error). The picture itself is
 * never drawn here.
 *
 * <p>The page and its overlays are painted in the display's own pixels
 * (device pixels), whatever the desktop's scale: {@link ZoomPan} works in
 * them, so that a page pixel is always a whole number of them (at 150 %
 * Java2D's own scaling would draw it 1.5 wide: one column one pixel, the
 * next two). The pointer's place, given in the desktop's points, is turned
 * into device pixels here ({@link #deviceX}); the error box and everything
 * else of the window stay in points, at the desktop's size.
 */
public final class PageView extends JComponent {

    private static final long serialVersionUID = 1L;
    private static final Color AROUND = new Color(96, 96, 96);
    private static final Color MARK = new Color(255, 64, 255);
    /** A first-assignment line between its rounded ends: beside the magenta of the line as given. */
    static final Color ROUNDED = new Color(64, 224, 255);

    private final transient ZoomPan zoomPan = new ZoomPan(PageCanvas.SIZE, PageCanvas.MARGIN);
    private transient BufferedImage image = new PageCanvas().snapshot();
    /** The image below 1:1 as {@link LineKeepingDownscale} made it, for {@link #smallOf} and {@link #smallZoom}. */
    private transient BufferedImage small;
    private transient BufferedImage smallOf;
    private double smallZoom;
    private String error;
    private boolean errorAfterDrawing = true;
    private boolean errorHidden;
    private int pinnedX = -1;
    private int pinnedY = -1;
    /** A primitive's outline in image coordinates (x0, y0, x1, y1, ...), or null. */
    private double[] outline;
    /** A first-assignment page's lines and triangles as given, over its pixels; never null. */
    private transient A1Marks marks = A1Marks.NONE;
    /** Outlines drawn over the whole page (wire over fill), each in image coordinates; null for none. */
    private transient List<double[]> wire;
    /** The wire's colour, and how much of it covers the page under it (200 of 255). */
    private static final Color WIRE = new Color(0, 255, 128);
    private static final AlphaComposite WIRE_OVER_PAGE = AlphaComposite.SrcOver.derive(200 / 255f);
    /** The culled and the clipped-away primitives' outlines (image coordinates), or null for none. */
    private transient List<double[]> culled;
    private transient List<double[]> clipped;
    /** The wire, and the culled and clipped-away outlines, as last drawn over the view. */
    private final transient OutlinePictures outlinePictures;
    static final Color CULLED = new Color(255, 160, 0);
    static final Color CLIPPED = new Color(0, 200, 255);
    /** Device pixels a point of the desktop, as last laid out or painted (1.5 at 150 %). */
    private double scale = 1;
    /** Where this view's (0, 0) lies right of (and below) the device pixel the page is painted from: 0 to 0.5. */
    private double shiftX;
    private double shiftY;
    /** What the view shows, in words: "page 5/8: …", "scene: lit.simp"; what a screen reader names it. */
    private String shows = "nothing drawn yet";

    PageView() {
        this(OutlinePictures.SLICE_NANOS);
    }

    /** A view whose outlines are drawn again {@code sliceNanos} at a time (tests take less, to see the slices). */
    PageView(long sliceNanos) {
        outlinePictures = new OutlinePictures(this, WIRE, CULLED, CLIPPED, sliceNanos);
        setMinimumSize(new Dimension(100, 100));
        setOpaque(true);
        addComponentListener(new ComponentAdapter() {
            @Override
            public void componentResized(ComponentEvent e) {
                layOut(desktopScale());
                repaint();
            }
        });
    }

    ZoomPan zoomPan() {
        return zoomPan;
    }

    /**
     * Room for the whole page at the whole number of device pixels a page
     * pixel nearest the desktop's scale, in points: 750 unscaled and at
     * 200 %, 1000 at 150 % (the page two device pixels a page pixel, where
     * 750 points would show it 1.5), 600 at 125 % (one).
     */
    @Override
    public Dimension getPreferredSize() {
        if (isPreferredSizeSet()) {
            return super.getPreferredSize();
        }
        int side = preferredSide(desktopScale());
        return new Dimension(side, side);
    }

    /** The side of the view's preferred square, in points, on a desktop of {@code deviceScale}. */
    static int preferredSide(double deviceScale) {
        return (int) Math.ceil(PageCanvas.SIZE * Math.max(1, Math.round(deviceScale)) / deviceScale - 1e-9);
    }

    /** The desktop's scale where this view is shown (1.5 at 150 %); off screen, the scale it was last painted at. */
    private double desktopScale() {
        GraphicsConfiguration screen = getGraphicsConfiguration();
        return screen == null ? scale : screen.getDefaultTransform().getScaleX();
    }

    /** Sizes the zoom's viewport in device pixels, at {@code deviceScale} of them a point. */
    private void layOut(double deviceScale) {
        scale = deviceScale;
        zoomPan.resize((int) Math.floor(getWidth() * scale + 1e-9), (int) Math.floor(getHeight() * scale + 1e-9),
                unitOf(scale));
    }

    /** Device pixels a page pixel at the desktop's own size: its scale as a whole number (1 at 125 % and 150 %). */
    static int unitOf(double deviceScale) {
        return Math.max(1, (int) Math.floor(deviceScale + 1e-9));
    }

    /** Device pixels a point, as this view was last laid out or painted. */
    double deviceScale() {
        return scale;
    }

    /** The device x (as {@link ZoomPan} counts) of point x of this view, e.g. the pointer's. */
    double deviceX(double x) {
        return x * scale + shiftX;
    }

    double deviceY(double y) {
        return y * scale + shiftY;
    }

    /** The image column under point x of this view, or -1 off the image. */
    int imageX(int x) {
        return zoomPan.imageX(deviceX(x));
    }

    /** The image row under point y of this view, or -1 off the image. */
    int imageY(int y) {
        return zoomPan.imageY(deviceY(y));
    }

    /** Shows a finished page and, if it failed, its error over it. Call on the EDT. */
    public void show(BufferedImage page, String errorMessage) {
        show(page, errorMessage, true);
    }

    /** The same; {@code drewSomething} false when the error came before anything was drawn. */
    public void show(BufferedImage page, String errorMessage, boolean drewSomething) {
        showing(page);
        error = errorMessage;
        errorAfterDrawing = drewSomething;
        repaint();
    }

    /** Replaces the picture only (e.g. the depth view of the same page); the error stays. */
    void showImage(BufferedImage picture) {
        showing(picture);
        repaint();
    }

    BufferedImage image() {
        return image;
    }

    /**
     * Shows {@code picture} from now on. The picture below 1:1 is forgotten
     * when another image is shown, not only when it is asked for again: the
     * window draws turning frames on images given back, so an image shown
     * before may come back with another picture in it
     * ({@link simpview.window.render.BackgroundRenderer#giveBack}).
     */
    private void showing(BufferedImage picture) {
        if (picture != image) {
            small = null;
            smallOf = null;
        }
        image = picture;
    }

    /** Names what the view shows, in words ("page 5/8: …", "scene: lit.simp"), for a screen reader. */
    void describe(String shows) {
        this.shows = shows;
    }

    /**
     * What a screen reader says of the view: its name is what it shows ("page
     * 5/8: …"), its description the page's and panel's sizes, the zoom, and
     * the error over it, if any.
     */
    @Override
    public AccessibleContext getAccessibleContext() {
        if (accessibleContext == null) {
            accessibleContext = new AccessibleJComponent() {
                private static final long serialVersionUID = 1L;

                @Override
                public String getAccessibleName() {
                    return accessibleName != null ? accessibleName : shows;
                }

                @Override
                public String getAccessibleDescription() {
                    String sizes = PageCanvas.SIZE + " by " + PageCanvas.SIZE + " page, its " + PageCanvas.PANEL
                            + " by " + PageCanvas.PANEL + " panel, at " + zoomPan.describe();
                    return error == null || errorHidden ? sizes : sizes + "; " + errorHeading() + " " + error;
                }

                @Override
                public AccessibleRole getAccessibleRole() {
                    return AccessibleRole.CANVAS;
                }
            };
        }
        return accessibleContext;
    }

    /** The error shown over the page, or null. */
    String error() {
        return error;
    }

    /** The heading of the error box: what the page shows under it. */
    private String errorHeading() {
        return errorAfterDrawing ? ErrorOverlay.HEADING : ErrorOverlay.HEADING_NOTHING_DRAWN;
    }

    /** The lines the error box's heading takes at this view's width, as it paints them. */
    List<String> errorHeadingLines() {
        return ErrorOverlay.headingLines(errorHeading(), getFontMetrics(ErrorOverlay.FONT), getWidth());
    }

    /** Hides or shows the error box; the error itself stays known. */
    boolean toggleErrorHidden() {
        errorHidden = !errorHidden;
        repaint();
        return errorHidden;
    }

    boolean errorHidden() {
        return errorHidden;
    }


    /** Marks image pixel (x, y) with a frame; -1 for none. */
    void pin(int x, int y) {
        pinnedX = x;
        pinnedY = y;
        repaint();
    }

    /** Outlines a primitive, given in image coordinates; null for none. */
    void outline(double[] imagePoints) {
        outline = imagePoints;
        repaint();
    }

    /** Shows lines (as given and between their rounded ends) and triangles over a first-assignment page; null for none. */
    void marks(A1Marks shown) {
        marks = shown == null ? A1Marks.NONE : shown;
        repaint();
    }

    A1Marks marks() {
        return marks;
    }

    /** Draws these outlines (image coordinates) over the page, or none (null). */
    void wire(List<double[]> outlines) {
        wire = outlines;
        repaint();
    }

    boolean wireShown() {
        return wire != null;
    }

    /** Outlines the primitives culled and those clipped away (image coordinates), or none (nulls). */
    void skipped(List<double[]> culledOutlines, List<double[]> clippedOutlines) {
        culled = culledOutlines;
        clipped = clippedOutlines;
        repaint();
    }

    boolean skippedShown() {
        return culled != null;
    }

    /** Where the image's top-left corner is, in this component's device pixels (its points when unscaled). */
    Point imageOrigin() {
        return new Point((int) zoomPan.originX(), (int) zoomPan.originY());
    }

    @Override
    protected void paintComponent(Graphics graphics) {
        Graphics2D g = (Graphics2D) graphics.create();
        try {
            Rectangle clip = g.getClipBounds() != null ? g.getClipBounds() : new Rectangle(getSize());
            g.setColor(AROUND);
            g.fillRect(clip.x, clip.y, clip.width, clip.height);
            paintInDevicePixels(g);
            if (error != null && !errorHidden) {
                ErrorOverlay.paint(g, errorHeading(), error, getWidth(), getHeight());
            }
        } finally {
            g.dispose();
        }
    }

    /**
     * The page and its overlays, drawn with the desktop's scaling taken off:
     * one unit of drawing is one device pixel, from the whole device pixel
     * nearest this view's corner.
     */
    private void paintInDevicePixels(Graphics2D logical) {
        AffineTransform toDevice = logical.getTransform();
        if (toDevice.getScaleX() != scale && toDevice.getScaleX() > 0) {
            layOut(toDevice.getScaleX()); // the first paint, or the window moved to a screen of another scale
        }
        Graphics2D g = (Graphics2D) logical.create();
        try {
            double cornerX = Math.floor(toDevice.getTranslateX() + 0.5);
            double cornerY = Math.floor(toDevice.getTranslateY() + 0.5);
            shiftX = toDevice.getTranslateX() - cornerX;
            shiftY = toDevice.getTranslateY() - cornerY;
            g.setTransform(AffineTransform.getTranslateInstance(cornerX, cornerY));
            Rectangle clip = g.getClipBounds() != null ? g.getClipBounds()
                    : new Rectangle(0, 0, (int) Math.ceil(getWidth() * scale), (int) Math.ceil(getHeight() * scale));
            paintImage(g, clip);
            if (PixelGrid.shows(zoomPan)) {
                PixelGrid.paint(g, zoomPan, image, clip);
            }
            paintWire(g);
            paintMarks(g);
        } finally {
            g.dispose();
        }
    }

    /** Copies the part of the image that shows, each image pixel a square of screen pixels. */
    private void paintImage(Graphics2D g, Rectangle clip) {
        g.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_NEAREST_NEIGHBOR);
        g.setRenderingHint(RenderingHints.KEY_RENDERING, RenderingHints.VALUE_RENDER_SPEED);
        double zoom = zoomPan.zoom();
        int ox = (int) zoomPan.originX();
        int oy = (int) zoomPan.originY();
        if (zoomPan.belowOneDevicePixel()) {
            g.drawImage(shownSmall(), ox, oy, null);
            return;
        }
        if (!zoomPan.isIntegerZoom()) {
            int size = (int) Math.round(zoomPan.shownSize());
            g.drawImage(image, ox, oy, ox + size, oy + size, 0, 0, image.getWidth(), image.getHeight(), null);
            return;
        }
        int z = (int) zoom;
        int sx0 = Math.max(0, Math.floorDiv(clip.x - ox, z));
        int sy0 = Math.max(0, Math.floorDiv(clip.y - oy, z));
        int sx1 = Math.min(image.getWidth(), Math.floorDiv(clip.x + clip.width - ox + z - 1, z));
        int sy1 = Math.min(image.getHeight(), Math.floorDiv(clip.y + clip.height - oy + z - 1, z));
        if (sx0 < sx1 && sy0 < sy1) {
            g.drawImage(image, ox + sx0 * z, oy + sy0 * z, ox + sx1 * z, oy + sy1 * z, sx0, sy0, sx1, sy1, null);
        }
    }

    /** The picture below 1:1, made again only when the picture or the zoom changed. */
    BufferedImage shownSmall() {
        if (small == null || smallOf != image || smallZoom != zoomPan.zoom()) {
            small = LineKeepingDownscale.of(image, zoomPan.zoom());
            smallOf = image;
            smallZoom = zoomPan.zoom();
        }
        return small;
    }

    /**
     * The outlines over the page, cut to the panel: what lies outside it is not on the page. They are drawn, in
     * opaque colours, into pictures of the view's size ({@link OutlinePictures}), and those are copied to the
     * screen, the wire's at its share over the page: drawn straight to the screen in its translucent colour, X11's
     * pipeline took 110-190 ms each repaint for page-d's 16,026 outlines (and Java2D's own loops, into a picture,
     * 100 times as long as in an opaque one).
     */
    private void paintWire(Graphics2D graphics) {
        if (wire == null && culled == null) {
            outlinePictures.clear();
            return;
        }
        OutlinePictures.Drawn now = outlinesNow();
        if (now != null) {
            outlinePictures.paint(graphics, now, WIRE_OVER_PAGE);
        }
    }

    /** What the outlines' pictures are to show now, or null while the view has no size. */
    private OutlinePictures.Drawn outlinesNow() {
        int width = (int) Math.ceil(getWidth() * scale);
        int height = (int) Math.ceil(getHeight() * scale);
        if (width <= 0 || height <= 0) {
            return null;
        }
        return new OutlinePictures.Drawn(wire, culled, clipped, zoomPan.zoom(), zoomPan.originX(), zoomPan.originY(),
                zoomPan.unit(), width, height);
    }

    /** The outlines' pictures: for the tests. */
    OutlinePictures outlinePictures() {
        return outlinePictures;
    }

    /** Whether the outlines' pictures shown are those of the zoom, pan and size now, none still being drawn. */
    boolean outlinesFinished() {
        OutlinePictures.Drawn now = outlinesNow();
        return now != null && outlinePictures.finished(now);
    }

    /**
     * A first-assignment line as given (magenta, solid), between its rounded
     * ends (cyan, dashed), each end a small ring: where the line really runs
     * against the pixels each drawer lit. Triangles as given, outlined.
     */
    private void paintA1Marks(Graphics2D g) {
        if (marks.isEmpty()) {
            return;
        }
        float unit = zoomPan.unit();
        g.setStroke(new BasicStroke(1.25f * unit));
        for (double[] points : marks.outlines()) {
            Path2D.Double path = new Path2D.Double();
            path.moveTo(zoomPan.screenX(points[0]), zoomPan.screenY(points[1]));
            for (int k = 2; k + 1 < points.length; k += 2) {
                path.lineTo(zoomPan.screenX(points[k]), zoomPan.screenY(points[k + 1]));
            }
            path.closePath();
            g.draw(path);
        }
        g.setColor(ROUNDED);
        g.setStroke(new BasicStroke(1.25f * unit, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10,
                new float[] {6 * unit, 4 * unit}, 0));
        segments(g, marks.rounded());
        g.setColor(MARK);
        g.setStroke(new BasicStroke(1.5f * unit));
        segments(g, marks.given());
    }

    private void segments(Graphics2D g, double[] ends) {
        double ring = Math.max(3 * zoomPan.unit(), zoomPan.zoom() / 4);
        for (int k = 0; k + 3 < ends.length; k += 4) {
            double x0 = zoomPan.screenX(ends[k]);
            double y0 = zoomPan.screenY(ends[k + 1]);
            double x1 = zoomPan.screenX(ends[k + 2]);
            double y1 = zoomPan.screenY(ends[k + 3]);
            g.draw(new Line2D.Double(x0, y0, x1, y1));
            g.draw(new Ellipse2D.Double(x0 - ring / 2, y0 - ring / 2, ring, ring));
            g.draw(new Ellipse2D.Double(x1 - ring / 2, y1 - ring / 2, ring, ring));
        }
    }

    private void paintMarks(Graphics2D g) {
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(MARK);
        if (outline != null && outline.length >= 4) {
            Path2D.Double path = new Path2D.Double();
            path.moveTo(zoomPan.screenX(outline[0]), zoomPan.screenY(outline[1]));
            for (int k = 2; k + 1 < outline.length; k += 2) {
                path.lineTo(zoomPan.screenX(outline[k]), zoomPan.screenY(outline[k + 1]));
            }
            path.closePath();
            g.setStroke(new BasicStroke(1.25f * zoomPan.unit()));
            g.draw(path);
        }
        paintA1Marks(g);
        if (pinnedX >= 0) {
            int unit = zoomPan.unit();
            double size = Math.max(zoomPan.zoom(), 3 * unit);
            double left = zoomPan.screenX(pinnedX + 0.5) - size / 2;
            double top = zoomPan.screenY(pinnedY + 0.5) - size / 2;
            g.setStroke(new BasicStroke(2f * unit));
            g.draw(new Rectangle2D.Double(left - 2 * unit, top - 2 * unit, size + 4 * unit, size + 4 * unit));
        }
    }
}

package simpview.surface;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.util.Arrays;
import simpview.geometry.Camera;

/**
 * One page: a 750x750 image with 50-pixel white margins around the 650x650
 * panel, the panel's drawable (y up) and its z-buffer. A canvas is reused from
 * page to page; {@link #clear()} gives each page a fresh start.
 */
public final class PageCanvas {

    /** The white margin around the panel, in pixels. */
    public static final int MARGIN = 50;
    /** The panel's side in pixels, 650. */
    public static final int PANEL = Camera.PANEL_SIZE;
    /** The page's side in pixels, 750: the panel and its margins. */
    public static final int SIZE = PANEL + 2 * MARGIN;
    /**
     * The colour a panel is cleared to, the background of every page and scene (pages 1 to 8, depth-cued and lit
     * scenes, the first assignment's panels): what simpview shows where nothing is drawn.
     */
    public static final int BACKGROUND = Colors.BLACK;

    private final BufferedImage image;
    private final ImageDrawable imageDrawable;
    private final PanelDrawable panel;
    private final ZBuffer zbuffer;
    /** A row of the image through the panel as the clear leaves it: white margins, black panel. */
    private final int[] clearedRow = new int[SIZE];
    /** Who drew each panel pixel, when someone asked to know; null costs nothing. */
    private Provenance provenance;
    /** See {@link #waitingPixels}: made at the first lit picture. */
    private WaitingPixels waiting;
    /** The threads scenes are drawn on this canvas with: the owner's, given to it; one (the caller's) by default. */
    private DrawingThreads threads = DrawingThreads.one();
    /** True from a {@link #handOff} to the next {@link #clear}: the image is then no page. */
    private boolean handedOff;

    /** A cleared page, drawn on the caller's thread alone until {@link #drawWith} says otherwise. */
    public PageCanvas() {
        image = new BufferedImage(SIZE, SIZE, BufferedImage.TYPE_INT_RGB);
        imageDrawable = new ImageDrawable(image);
        panel = new PanelDrawable(imageDrawable, MARGIN, MARGIN, PANEL);
        zbuffer = new ZBuffer(PANEL, PANEL);
        Arrays.fill(clearedRow, Colors.WHITE);
        Arrays.fill(clearedRow, MARGIN, MARGIN + PANEL, BACKGROUND);
        clear();
    }

    /**
     * White margins, black panel, z-buffer at the far plane. A canvas drawn
     * on one thread fills every pixel now. One drawn by several fills the
     * rows above and below the panel now and owes the rows through it
     * ({@link ImageDrawable#oweRows}): a picture's band drawers make them,
     * each its own rows ({@link #owedPanelRows}), or the first read or write
     * of the image, on one thread ({@link Drawable#settle} before several
     * write at once otherwise). The z-buffer is filled when first read or
     * tested ({@link ZBuffer#resetWhenNeeded}), which a lit scene, resetting
     * it to -infinity itself, never does.
     */
    public void clear() {
        imageDrawable.fillRect(0, 0, SIZE, MARGIN, Colors.WHITE);
        imageDrawable.fillRect(0, MARGIN + PANEL, SIZE, SIZE, Colors.WHITE);
        if (threads.isOne()) {
            imageDrawable.fillRect(0, MARGIN, MARGIN, MARGIN + PANEL, Colors.WHITE);
            imageDrawable.fillRect(MARGIN + PANEL, MARGIN, SIZE, MARGIN + PANEL, Colors.WHITE);
            imageDrawable.fillRect(MARGIN, MARGIN, MARGIN + PANEL, MARGIN + PANEL, BACKGROUND);
        } else {
            imageDrawable.oweRows(MARGIN, MARGIN + PANEL, clearedRow);
        }
        zbuffer.resetWhenNeeded(Camera.PARALLEL.yon());
        if (provenance != null) {
            provenance.reset();
        }
        handedOff = false;
    }

    /**
     * From now on the depth-tested chains record who drew each pixel into
     * {@code record} (after the z-buffer, so only winning writes count);
     * null stops it. Cleared with the canvas.
     */
    public void recordProvenance(Provenance record) {
        if (record != null && (record.width() != PANEL || record.height() != PANEL)) {
            throw new IllegalArgumentException("provenance must be " + PANEL + "x" + PANEL);
        }
        provenance = record;
        if (record != null) {
            record.reset();
        }
    }

    /**
     * From now on scenes are drawn on this canvas by {@code drawing}'s
     * threads. The canvas does not own them: whoever gave them closes them.
     */
    public void drawWith(DrawingThreads drawing) {
        threads = drawing;
    }

    /** The threads scenes are drawn on this canvas with. */
    public DrawingThreads drawingThreads() {
        return threads;
    }

    /** The provenance being recorded, or null. */
    public Provenance provenance() {
        return provenance;
    }

    /** What the z-buffer passes its winning writes to: {@code next}, behind the provenance record if there is one. */
    private Drawable afterZBuffer(Drawable next) {
        return provenance == null ? next : new ProvenanceDrawable(provenance, next);
    }

    /** The panel's pixels that wait to be shaded at a lit picture's end: made once, at the first that asks. */
    public WaitingPixels waitingPixels() {
        if (waiting == null) {
            waiting = new WaitingPixels(PANEL, PANEL);
        }
        return waiting;
    }

    /**
     * The page's image itself, 750x750 (what the clear owes of it made first): the next page drawn on this
     * canvas overwrites it; {@link #snapshot} is a copy to keep.
     */
    public BufferedImage image() {
        checkNotHandedOff();
        return imageDrawable.image();
    }

    private void checkNotHandedOff() {
        if (handedOff) {
            throw new IllegalStateException("the page was handed off: clear the canvas before reading it again");
        }
    }

    /**
     * The rows through the panel that the clear still owes, handed to a
     * picture's band drawers ({@link OwedRows}): from now on whoever draws
     * panel rows makes them first, and reading or writing the image no
     * longer does. Called before the picture draws anything.
     */
    public OwedRows owedPanelRows() {
        if (!imageDrawable.fillOwedByRows()) {
            return OwedRows.NONE;
        }
        return (from, to) -> imageDrawable.fillOwedRows(MARGIN + PANEL - to, MARGIN + PANEL - from);
    }

    /** The panel, in panel coordinates: origin bottom-left, y up. */
    public Drawable panel() {
        return panel;
    }

    /** The panel's depths, one a pixel, as the last page or scene left them. */
    public ZBuffer zbuffer() {
        return zbuffer;
    }

    /**
     * The panel as a lit scene's fragment stage writes it: that stage does
     * its own depth test, so this is the panel behind the provenance record,
     * if there is one.
     */
    public Drawable litPanel() {
        return afterZBuffer(panel);
    }

    /** The panel behind the z-buffer and the scissor: what pages 3 and up draw on. */
    public Drawable depthTested() {
        return new ScissorDrawable(Camera.PARALLEL, new ZBufferDrawable(zbuffer, afterZBuffer(panel)));
    }

    /** The panel behind scissor, z-buffer and depth cue: what a SIMP scene draws on. */
    public Drawable depthCued(Rgb near, Rgb far) {
        return new ScissorDrawable(Camera.PARALLEL, new ZBufferDrawable(zbuffer,
                afterZBuffer(new DepthCueDrawable(near, far, Camera.PARALLEL, panel))));
    }

    /** A copy of the page as it is now: the pixels copied as one array. */
    public BufferedImage snapshot() {
        int[] from = ((DataBufferInt) image().getRaster().getDataBuffer()).getData(); // refused when handed off
        BufferedImage copy = new BufferedImage(SIZE, SIZE, BufferedImage.TYPE_INT_RGB);
        int[] to = ((DataBufferInt) copy.getRaster().getDataBuffer()).getData();
        System.arraycopy(from, 0, to, 0, from.length);
        return copy;
    }

    /**
     * The page as it is now, handed off whole instead of copied: from now on
     * the canvas draws on {@code spare}, a page image that no one else holds
     * any longer (one handed off before and let go of), or on a new one when
     * it is null or not a page image (750x750, INT_RGB). Until the next
     * {@link #clear} the canvas holds no page
     * ({@link #image} and {@link #snapshot} refuse), and the clear makes
     * every pixel of it. The window's pictures come this way: a frame of a
     * turning drag is then 2.25 MB neither made nor copied
     * (docs/performance-log.md, session 48).
     */
    public BufferedImage handOff(BufferedImage spare) {
        boolean fits = spare != null && spare.getWidth() == SIZE && spare.getHeight() == SIZE
                && spare.getType() == BufferedImage.TYPE_INT_RGB;
        BufferedImage next = fits ? spare : new BufferedImage(SIZE, SIZE, BufferedImage.TYPE_INT_RGB);
        BufferedImage page = imageDrawable.exchange(next);
        handedOff = true;
        return page;
    }
}

package simpview.window;

import java.awt.Toolkit;
import java.awt.datatransfer.StringSelection;
import javax.swing.JFrame;
import simpview.inspect.HistoryEntry;
import simpview.inspect.InspectedScene;
import simpview.inspect.PixelPair;
import simpview.surface.PageCanvas;
import simpview.window.instruments.ComparisonLayer;
import simpview.window.instruments.Inspector;
import simpview.window.instruments.InspectorPanel;
import simpview.window.render.DrawSettings;
import simpview.window.render.RenderedView;
import simpview.window.render.View;

/**
 * The pixel the inspector looks at: the pinned one (P, Shift+G), else the
 * one under the pointer; and what is said of it on the status line, in the
 * side panel (I) and on the clipboard (Ctrl+C, Ctrl+Shift+C). All methods
 * run on the EDT.
 */
final class InspectedPixel {

    private final JFrame frame;
    private final PageView pageView;
    private final StatusStrip status;
    private final InspectorPanel inspectorPanel;
    private final ComparisonLayer comparison;
    private final Orbit orbit;
    private final OnScreen onScreen;
    /** The pointer's last place over the page view (x = -1: off it): the hovered pixel follows a zoom under it. */
    private int pointerX = -1;
    private int pointerY = -1;
    /** The image pixel under the pointer, and the pinned one (x = -1: none). */
    private int hoverX = -1;
    private int hoverY = -1;
    private int pinnedX = -1;
    private int pinnedY = -1;

    /** The inspected pixel of the view {@code onScreen}, turned by {@code orbit} and compared by {@code comparison}. */
    InspectedPixel(JFrame frame, PageView pageView, StatusStrip status, InspectorPanel inspectorPanel,
            ComparisonLayer comparison, Orbit orbit, OnScreen onScreen) {
        this.frame = frame;
        this.pageView = pageView;
        this.status = status;
        this.inspectorPanel = inspectorPanel;
        this.comparison = comparison;
        this.orbit = orbit;
        this.onScreen = onScreen;
    }

    /** The pointer is at (x, y) over the page view, or off it (-1): the inspector follows it. */
    void pointerAt(int x, int y) {
        pointerX = x;
        pointerY = y;
        inspectUnderPointer();
    }

    /** Whether a pixel is pinned. */
    boolean isPinned() {
        return pinnedX >= 0;
    }

    /** The inspected pixel's column in the image: the pinned one's, else the hovered one's (-1: none). */
    int x() {
        return pinnedX >= 0 ? pinnedX : hoverX;
    }

    /** The inspected pixel's row in the image, as {@link #x}. */
    int y() {
        return pinnedX >= 0 ? pinnedY : hoverY;
    }

    /** Takes the pin away, as a view is left. */
    void unpin() {
        pinnedX = pinnedY = -1;
        pageView.pin(-1, -1);
    }

    /**
     * The pixel under the pointer's last place, found again: the pointer
     * moved, or the zoom, the pan or the view's size changed under it.
     * Returns whether it is another pixel than before.
     */
    boolean followPointer() {
        int wasX = hoverX;
        int wasY = hoverY;
        hoverX = pointerX < 0 ? -1 : pageView.imageX(pointerX);
        hoverY = pointerY < 0 ? -1 : pageView.imageY(pointerY);
        return hoverX != wasX || hoverY != wasY;
    }

    /** The status line's inspector, and the panel while nothing is pinned, on the pixel under the pointer. */
    void inspectUnderPointer() {
        boolean another = followPointer();
        inspect();
        if (pinnedX < 0 && hoverX >= 0 && hoverY >= 0 && another) {
            refreshPanel(); // the panel follows the pointer while nothing is pinned
        }
    }

    /** The status line's inspector: the pinned pixel, else the one under the pointer, and the zoom. */
    void inspect() {
        RenderedView shown = onScreen.picture();
        DrawSettings settings = onScreen.settings();
        int x = x();
        int y = y();
        String pixel = x < 0 || y < 0 ? null : Inspector.describe(shown, x, y);
        String zoom = pageView.zoomPan().describe() + (settings.depthView() ? " · depth view" : "")
                + (onScreen.ownColoursShown() ? " · own colours" : "");
        String theirs = x < 0 || y < 0 ? "" : comparison.theirsAt(x, y)
                .map(rgb -> " · theirs " + Inspector.rgb(rgb)).orElse("");
        String line = (pinnedX >= 0 ? "pinned · " : "") + pixel + theirs;
        // Below 1:1 the zoom comes first: the line may be cut at its end, and that must not be lost.
        status.inspect(pixel == null ? zoom : pageView.zoomPan().belowOneToOne() ? zoom + " · " + line
                : line + " · " + zoom, pixel != null);
        if (settings.stepLimit() < 0) {
            boolean magnified = PixelGrid.shows(pageView.zoomPan());
            pageView.outline(magnified ? Inspector.outlineAt(shown, x, y) : null);
            pageView.marks(magnified ? Inspector.marksAt(shown, x, y) : null);
        }
    }

    void togglePin() {
        if (pinnedX >= 0) {
            pinnedX = pinnedY = -1;
            if (status.messageText().startsWith("Pinned ")) {
                status.say("Unpinned: the inspector follows the pointer again.");
            }
        } else if (hoverX >= 0 && hoverY >= 0) {
            pinnedX = hoverX;
            pinnedY = hoverY;
        } else {
            status.say("Move the pointer over a pixel, then press P to pin it.");
        }
        pageView.pin(pinnedX, pinnedY);
        inspect();
        refreshPanel();
    }

    /** The side panel, when shown: the pinned pixel's history (else the one under the pointer's), replayed. */
    void refreshPanel() {
        RenderedView shown = onScreen.picture();
        DrawSettings settings = onScreen.settings();
        if (!inspectorPanel.isShown()) {
            return;
        }
        int ix = x();
        int iy = y();
        if (ix < 0 || iy < 0 || shown == null) {
            inspectorPanel.say("Point at a pixel, or pin one (P, or Shift+G for its coordinates), to see every write "
                    + "it received, how its colour was made, and its primitive's vertices.");
            return;
        }
        String theirs = comparedAt(ix, iy);
        if (shown.view() instanceof View.OfAssignment1Page a1) {
            // The first assignment's pixels go by page coordinates, y up: every panel is on the page.
            inspectorPanel.inspectFirstAssignment(a1.number(), shown.seed(), shown.a1Rule(), ix, PageCanvas.SIZE - 1 - iy, theirs);
            return;
        }
        int x = ix - PageCanvas.MARGIN;
        int y = PageCanvas.MARGIN + PageCanvas.PANEL - 1 - iy;
        if (x < 0 || y < 0 || x >= PageCanvas.PANEL || y >= PageCanvas.PANEL) {
            inspectorPanel.say((theirs == null ? "" : theirs + "\n\n")
                    + "The pixel is in the margin: nothing is drawn there.");
            return;
        }
        InspectedScene scene = onScreen.inspectedScene(message ->
                inspectorPanel.say((theirs == null ? "" : theirs + "\n\n") + message));
        if (scene == null) {
            return;
        }
        // While stepping (unturned, where the replay numbers the primitives as the steps do), the vertex table is
        // the stepped primitive's: RenderDoc's mesh view of the draw at hand, with whether it covers the pixel.
        int stepped = settings.stepLimit() >= 1 && !orbit.turned() ? settings.stepLimit() - 1 : HistoryEntry.NO_NUMBER;
        String note = orbit.turned() || settings.stepLimit() >= 0
                ? "The history is of the whole drawing in the unturned view (stepping and turning are left out)."
                : null;
        inspectorPanel.inspect(scene, x, y, note, theirs, stepped);
    }

    /** While comparing: both pictures' values at image pixel (ix, iy) and how far apart they are; else null. */
    private String comparedAt(int ix, int iy) {
        RenderedView shown = onScreen.picture();
        return comparison.theirsAt(ix, iy).map(theirs -> {
            int ours = shown.image().getRGB(ix, iy);
            int dr = ((theirs >> 16) & 0xFF) - ((ours >> 16) & 0xFF);
            int dg = ((theirs >> 8) & 0xFF) - ((ours >> 8) & 0xFF);
            int db = (theirs & 0xFF) - (ours & 0xFF);
            return "comparing with " + comparison.theirName() + ":\n  ours   " + Inspector.rgb(ours) + "\n  theirs "
                    + Inspector.rgb(theirs) + "\n  theirs - ours (" + dr + ", " + dg + ", " + db + "), largest "
                    + Math.max(Math.abs(dr), Math.max(Math.abs(dg), Math.abs(db))) + "/255";
        }).orElse(null);
    }

    /** Asks for a pixel by its panel coordinates (x right, y up), pins it and shows it (Shift+G). */
    void askForPixel() {
        RenderedView shown = onScreen.picture();
        if (shown == null) {
            return;
        }
        boolean pageCoordinates = shown.view() instanceof View.OfAssignment1Page;
        int last = pageCoordinates ? PageCanvas.SIZE - 1 : PageCanvas.PANEL - 1;
        String answer = QuestionAfterKey.ask(frame, pageCoordinates
                ? "Go to the page's pixel x, y (x right, y up from the page's bottom-left, 0 to " + last + "):"
                : "Go to the panel's pixel x, y (x right, y up from the panel's bottom-left, 0 to " + last + "):", 'g');
        if (answer != null) {
            goToPixel(answer);
        }
    }

    /**
     * Pins the pixel "x, y" (the panel's coordinates, x right and y up; on
     * the first assignment's pages the page's), read as inspect --at reads
     * it (PixelPair: also "(x, y)" as the inspector writes a pixel, and
     * "x y"), and brings it into view; says why not when the text is not a
     * pixel there.
     */
    void goToPixel(String answer) {
        RenderedView shown = onScreen.picture();
        boolean pageCoordinates = shown != null && shown.view() instanceof View.OfAssignment1Page;
        int last = pageCoordinates ? PageCanvas.SIZE - 1 : PageCanvas.PANEL - 1;
        PixelPair pixel;
        try {
            pixel = PixelPair.read(answer, pageCoordinates ? "page" : "panel", last);
        } catch (PixelPair.NotAPixel e) {
            status.say(e.getMessage() + ".");
            return;
        }
        int x = pixel.x();
        int y = pixel.y();
        int offset = pageCoordinates ? 0 : PageCanvas.MARGIN;
        pinnedX = offset + x;
        pinnedY = offset + last - y;
        pageView.zoomPan().bringIntoView(pinnedX, pinnedY);
        pageView.pin(pinnedX, pinnedY);
        followPointer();
        inspect();
        refreshPanel();
        status.say("Pinned " + (pageCoordinates ? "page" : "panel") + " pixel (" + x + ", " + y + "): the image's column "
                + pinnedX + ", row " + pinnedY + " (rows run down from the top)");
    }

    /** Copies the include chain of the inspected pixel's owner, whole paths (Ctrl+Shift+C). */
    void copyChain() {
        RenderedView shown = onScreen.picture();
        String chain = inspectorPanel.isShown() ? inspectorPanel.ownerChainText() : "";
        String note = "";
        if (chain.isEmpty()) {
            // Without the panel: the owner's own file:line, where a scene gave it; a page's own primitive by its name.
            int x = x();
            int y = y();
            if (x < 0) {
                status.say("No chain to copy: no pixel is inspected. Point at the picture, or pin a pixel (P, or "
                        + "Shift+G for its coordinates), then press "
                        + WindowAction.COPY_CHAIN.keysShown(MenuKey.ofPlatform()) + ".");
                return;
            }
            int owner = Inspector.ownerAt(shown, x, y);
            String place = owner < 0 ? null : shown.facts().primitives().place(owner);
            String line = Inspector.describe(shown, x, y);
            if (place == null && (line == null || !line.contains("drawn by primitive"))) {
                status.say(shown != null && shown.facts().owners() == null
                        ? "This page records no primitive for its pixels: no chain to copy."
                        : "No primitive drew the inspected pixel: no chain to copy (I shows the panel's chains).");
                return;
            }
            chain = place != null ? place : line.substring(line.indexOf("drawn by primitive"));
            note = " (with the panel open, I, the copy is the whole include chain)";
        }
        Toolkit.getDefaultToolkit().getSystemClipboard().setContents(new StringSelection(chain), null);
        status.say("Copied: " + chain + note);
    }

    /** Puts the text selected in the panel, else the inspector's line, on the clipboard; with neither, says so. */
    void copyInspected() {
        String selected = inspectorPanel.isShown() ? inspectorPanel.selectedText() : "";
        if (selected.isEmpty() && x() < 0) {
            // the status line's inspector then holds the zoom alone ("1:1"): no pixel's line to copy
            status.say("Nothing to copy: no pixel is inspected. Point at the picture, or pin a pixel (P, or Shift+G "
                    + "for its coordinates), then press " + WindowAction.COPY.keysShown(MenuKey.ofPlatform())
                    + "; or select text in the inspector panel (I).");
            return;
        }
        String line = selected.isEmpty() ? status.inspectorText() : selected;
        Toolkit.getDefaultToolkit().getSystemClipboard().setContents(new StringSelection(line), null);
        status.say("Copied: " + line);
    }
}

package simpview.window;

import java.awt.Dimension;
import java.awt.GraphicsConfiguration;
import java.awt.Insets;
import java.awt.Rectangle;
import java.awt.Toolkit;
import javax.swing.JFrame;

/**
 * Where a window opens: at the size it wants, cut down to the screen's usable
 * area, centred in it. An instance keeps one window's frame there: it opens
 * it so, and widens it for the inspector panel beside the page and narrows
 * it back. On the EDT.
 */
public final class WindowPlacement {

    private final JFrame frame;
    /** The inspector panel's width: what the frame widens by to show it. */
    private final int panelWidth;
    /** How much wider showing the inspector panel made the frame (0 where the screen or a maximized frame left no room). */
    private int widenedForPanel;
    /** The screen area a test placed the frame in, or null for the real one. */
    private Rectangle placedWithin;

    /** The placement of {@code frame}, whose inspector panel is {@code panelWidth} wide. */
    WindowPlacement(JFrame frame, int panelWidth) {
        this.frame = frame;
        this.panelWidth = panelWidth;
    }

    /** The frame's bounds for a frame that would like to be {@code wanted}, on a screen whose usable area is {@code usable}. */
    public static Rectangle within(Dimension wanted, Rectangle usable) {
        int width = Math.min(wanted.width, usable.width);
        int height = Math.min(wanted.height, usable.height);
        int x = usable.x + (usable.width - width) / 2;
        int y = usable.y + (usable.height - height) / 2;
        return new Rectangle(x, y, width, height);
    }

    /** Places the packed frame as it opens: at its size, within the usable screen. */
    void placeAsOpened() {
        frame.setBounds(within(frame.getSize(), usableScreen()));
    }

    /** The screen's area for windows: without taskbars and docks. */
    private Rectangle usableScreen() {
        return usableArea(frame.getGraphicsConfiguration());
    }

    /** The area for windows of {@code screen}: without its taskbars and docks. */
    static Rectangle usableArea(GraphicsConfiguration screen) {
        Rectangle bounds = screen.getBounds();
        Insets taken = Toolkit.getDefaultToolkit().getScreenInsets(screen);
        return new Rectangle(bounds.x + taken.left, bounds.y + taken.top,
                bounds.width - taken.left - taken.right, bounds.height - taken.top - taken.bottom);
    }

    /**
     * The frame grows by the panel's width when the panel is shown (as far as
     * the screen allows), so that the page keeps its zoom beside it, and
     * hiding it takes away what showing added, from the width the frame has
     * then (a frame the user resized meanwhile keeps the rest of its new
     * width), never below the frame's minimum; a maximized frame keeps its size.
     */
    void makeRoomForThePanel(boolean shownNow) {
        if ((frame.getExtendedState() & JFrame.MAXIMIZED_BOTH) != 0) {
            widenedForPanel = 0;
            return;
        }
        Rectangle bounds = frame.getBounds();
        Rectangle usable = screenForPlacing();
        int width;
        if (shownNow) {
            width = Math.min(usable.width, bounds.width + panelWidth);
            widenedForPanel = Math.max(0, width - bounds.width);
        } else {
            width = Math.max(frame.getMinimumSize().width, bounds.width - widenedForPanel);
            widenedForPanel = 0;
        }
        int x = Math.max(usable.x, Math.min(bounds.x, usable.x + usable.width - width));
        frame.setBounds(x, bounds.y, width, bounds.height);
    }

    /** The screen area the frame is placed in: the usable screen, or what a test said. */
    private Rectangle screenForPlacing() {
        return placedWithin != null ? placedWithin : usableScreen();
    }

    /**
     * Places the frame as it would open on a screen whose usable area is
     * {@code usable} (for tests of a small screen on a larger one).
     */
    void placeWithin(Rectangle usable) {
        placedWithin = usable;
        frame.setBounds(within(frame.getPreferredSize(), usable));
        frame.validate();
    }
}

package simpview.window;

import java.awt.Dimension;
import java.awt.Rectangle;

/** Where a window opens: at the size it wants, cut down to the screen's usable area, centred in it. */
public final class WindowPlacement {

    private WindowPlacement() {
    }

    /** The frame's bounds for a frame that would like to be {@code wanted}, on a screen whose usable area is {@code usable}. */
    public static Rectangle within(Dimension wanted, Rectangle usable) {
        int width = Math.min(wanted.width, usable.width);
        int height = Math.min(wanted.height, usable.height);
        int x = usable.x + (usable.width - width) / 2;
        int y = usable.y + (usable.height - height) / 2;
        return new Rectangle(x, y, width, height);
    }
}

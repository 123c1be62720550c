package simpview.window;

import java.awt.Component;
import java.awt.Cursor;
import java.awt.event.InputEvent;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import javax.swing.SwingUtilities;

/**
 * What the pointer does over the page: a left click (press and release
 * without moving) steps on; a left drag pans; a right drag (or Shift + left
 * drag) turns the view; the wheel zooms about the pointer, and with Ctrl or
 * Alt moves the view nearer or farther; moving reports the point under it.
 * The pointer comes in the desktop's points; the zoom and the pan go by the
 * view's device pixels ({@link PageView#deviceX}).
 */
public final class PointerGestures extends MouseAdapter {

    /** What the gestures ask for. */
    public interface Actions {
        void click();

        /** The view should be redrawn after the zoom or the pan changed. */
        void zoomPanChanged();

        /** A turning drag moved by (dx, dy) screen pixels. */
        void orbit(int dx, int dy);

        /** A turning drag that moved ended: the button was let go. */
        void orbitEnded();

        /** The wheel turned with Ctrl or Alt held: up (negative) nearer, down farther. */
        void nearer(int notches);

        /** The pointer is over screen point (x, y) of the page view, or left it (x = y = -1). */
        void hover(int x, int y);
    }

    /** A press and release closer than this (in screen pixels) is a click, not a drag. */
    static final int CLICK_SLOP = 3;

    private final PageView view;
    private final Actions actions;
    private int pressX;
    private int pressY;
    private int lastX;
    private int lastY;
    private boolean dragging;
    private boolean turning;

    public PointerGestures(PageView view, Actions actions) {
        this.view = view;
        this.actions = actions;
    }

    /** Listens to every pointer event of {@code view}. */
    public void attach(Component view) {
        view.addMouseListener(this);
        view.addMouseMotionListener(this);
        view.addMouseWheelListener(this);
    }

    @Override
    public void mousePressed(MouseEvent e) {
        pressX = lastX = e.getX();
        pressY = lastY = e.getY();
        dragging = false;
        turning = SwingUtilities.isRightMouseButton(e)
                || SwingUtilities.isLeftMouseButton(e) && (e.getModifiersEx() & InputEvent.SHIFT_DOWN_MASK) != 0;
    }

    @Override
    public void mouseDragged(MouseEvent e) {
        if (!dragging && Math.abs(e.getX() - pressX) + Math.abs(e.getY() - pressY) <= CLICK_SLOP) {
            return;
        }
        dragging = true;
        int dx = e.getX() - lastX;
        int dy = e.getY() - lastY;
        lastX = e.getX();
        lastY = e.getY();
        if (turning) {
            actions.orbit(dx, dy);
        } else if (SwingUtilities.isLeftMouseButton(e)) {
            e.getComponent().setCursor(Cursor.getPredefinedCursor(Cursor.MOVE_CURSOR));
            view.zoomPan().pan(dx * view.deviceScale(), dy * view.deviceScale());
            actions.zoomPanChanged();
        }
        actions.hover(e.getX(), e.getY());
    }

    @Override
    public void mouseReleased(MouseEvent e) {
        e.getComponent().setCursor(Cursor.getDefaultCursor());
        if (!dragging && !turning && SwingUtilities.isLeftMouseButton(e)) {
            actions.click();
        }
        if (dragging && turning) {
            actions.orbitEnded();
        }
        dragging = false;
        turning = false;
    }

    @Override
    public void mouseMoved(MouseEvent e) {
        actions.hover(e.getX(), e.getY());
    }

    @Override
    public void mouseExited(MouseEvent e) {
        actions.hover(-1, -1);
    }

    @Override
    public void mouseWheelMoved(MouseWheelEvent e) {
        int notches = e.getWheelRotation();
        if (notches == 0) {
            return;
        }
        if ((e.getModifiersEx() & (InputEvent.CTRL_DOWN_MASK | InputEvent.ALT_DOWN_MASK)) != 0) {
            actions.nearer(notches);
            return;
        }
        view.zoomPan().wheel(view.deviceX(e.getX()), view.deviceY(e.getY()), notches);
        actions.zoomPanChanged();
        actions.hover(e.getX(), e.getY());
    }
}

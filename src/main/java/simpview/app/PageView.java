package simpview.app;

import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import javax.swing.JComponent;
import simpview.surface.PageCanvas;

/**
 * The page at 1:1: the finished image is blitted unscaled, and a scene
 * error, if any, is drawn over it. The picture itself is never drawn here.
 */
final class PageView extends JComponent {

    private static final long serialVersionUID = 1L;
    private static final Dimension SIZE = new Dimension(PageCanvas.SIZE, PageCanvas.SIZE);

    private transient BufferedImage image = new PageCanvas().snapshot();
    private String error;

    PageView() {
        setPreferredSize(SIZE);
        setMinimumSize(SIZE);
        setMaximumSize(SIZE);
        setOpaque(true);
    }

    /** Shows a finished page and, if it failed, its error over it. Call on the EDT. */
    void show(BufferedImage page, String errorMessage) {
        image = page;
        error = errorMessage;
        repaint();
    }

    BufferedImage image() {
        return image;
    }

    /** The error shown over the page, or null. */
    String error() {
        return error;
    }

    @Override
    protected void paintComponent(Graphics g) {
        g.drawImage(image, 0, 0, null);
        if (error != null) {
            ErrorOverlay.paint((Graphics2D) g, error, getWidth());
        }
    }
}

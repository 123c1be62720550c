package simpview.bench;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import simpview.surface.PageCanvas;

/** The Java2D baseline's page: the same image type and size as ours, antialiasing off. */
final class Java2DPage {

    final BufferedImage image = new BufferedImage(PageCanvas.SIZE, PageCanvas.SIZE, BufferedImage.TYPE_INT_RGB);
    final Graphics2D g = image.createGraphics();

    Java2DPage() {
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_OFF);
        g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, PageCanvas.SIZE, PageCanvas.SIZE);
        g.setColor(Color.BLACK);
        g.fillRect(PageCanvas.MARGIN, PageCanvas.MARGIN, PageCanvas.PANEL, PageCanvas.PANEL);
    }

    void dispose() {
        g.dispose();
    }
}

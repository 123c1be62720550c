package simpview.window.instruments;

import java.awt.image.BufferedImage;
import simpview.surface.PageCanvas;
import simpview.window.render.PageFacts;
import simpview.window.render.Primitives;

/**
 * The back-face overlay: the picture with every pixel whose polygon is
 * clockwise on the panel (its projected, clipped outline has a negative
 * signed area, x right and y up) tinted half magenta. SPEC's polygons face
 * the viewer when counter-clockwise, and nothing culls the others: this
 * shows which ones a renderer that culls back faces would leave out.
 */
public final class BackFacePicture {

    private static final int MAGENTA = 0xFF00FF;

    private BackFacePicture() {
    }

    /** The result: the tinted picture and how many polygons of the picture face away. */
    public record Tinted(BufferedImage image, int backFacing, int polygons) {
    }

    /** The picture of {@code facts} with its back-facing pixels tinted; null when who drew each pixel was not recorded. */
    public static Tinted of(BufferedImage page, PageFacts facts) {
        int[] owners = facts.owners();
        if (owners == null) {
            return null;
        }
        Primitives primitives = facts.primitives();
        byte[] facing = new byte[primitives.size()]; // 0 unknown, 1 front, 2 back, 3 not a polygon
        int back = 0;
        int polygons = 0;
        for (int p = 0; p < primitives.size(); p++) {
            double area = signedArea(primitives.outline(p));
            facing[p] = Double.isNaN(area) ? 3 : area < 0 ? (byte) 2 : 1;
            back += facing[p] == 2 ? 1 : 0;
            polygons += facing[p] != 3 ? 1 : 0;
        }
        BufferedImage image = new BufferedImage(page.getWidth(), page.getHeight(), BufferedImage.TYPE_INT_RGB);
        image.getGraphics().drawImage(page, 0, 0, null);
        int panel = PageCanvas.PANEL;
        for (int y = 0; y < panel; y++) {
            for (int x = 0; x < panel; x++) {
                int owner = owners[y * panel + x];
                if (owner >= 0 && owner < facing.length && facing[owner] == 2) {
                    int ix = PageCanvas.MARGIN + x;
                    int iy = PageCanvas.MARGIN + panel - 1 - y;
                    image.setRGB(ix, iy, half(image.getRGB(ix, iy), MAGENTA));
                }
            }
        }
        return new Tinted(image, back, polygons);
    }

    /** Twice the signed area of the outline (x, y pairs); NaN for a line or no outline. */
    static double signedArea(double[] outline) {
        if (outline == null || outline.length < 6) {
            return Double.NaN;
        }
        double sum = 0;
        int n = outline.length / 2;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            sum += outline[2 * i] * outline[2 * j + 1] - outline[2 * j] * outline[2 * i + 1];
        }
        return sum;
    }

    private static int half(int rgb, int tint) {
        int r = ((rgb >> 16 & 0xFF) + (tint >> 16 & 0xFF)) / 2;
        int g = ((rgb >> 8 & 0xFF) + (tint >> 8 & 0xFF)) / 2;
        int b = ((rgb & 0xFF) + (tint & 0xFF)) / 2;
        return r << 16 | g << 8 | b;
    }
}

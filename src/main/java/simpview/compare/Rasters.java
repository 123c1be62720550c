package simpview.compare;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferByte;
import java.awt.image.DataBufferInt;

/**
 * A picture's pixels as one int[] of 0xRRGGBB, row by row from the top. The
 * common layouts (int RGB, 3-byte BGR) are read straight from their buffers;
 * anything else goes through one bulk getRGB.
 */
final class Rasters {

    private Rasters() {
    }

    static int[] rgb(BufferedImage image) {
        int w = image.getWidth();
        int h = image.getHeight();
        int[] out = new int[w * h];
        if (isPlain(image, BufferedImage.TYPE_INT_RGB) || isPlain(image, BufferedImage.TYPE_INT_ARGB)) {
            int[] data = ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
            for (int i = 0; i < out.length; i++) {
                out[i] = data[i] & 0xFFFFFF;
            }
        } else if (isPlain(image, BufferedImage.TYPE_3BYTE_BGR)) {
            byte[] data = ((DataBufferByte) image.getRaster().getDataBuffer()).getData();
            for (int i = 0, b = 0; i < out.length; i++, b += 3) {
                out[i] = (data[b + 2] & 0xFF) << 16 | (data[b + 1] & 0xFF) << 8 | data[b] & 0xFF;
            }
        } else {
            image.getRGB(0, 0, w, h, out, 0, w);
            for (int i = 0; i < out.length; i++) {
                out[i] &= 0xFFFFFF;
            }
        }
        return out;
    }

    /** Of that type, and its buffer holds exactly this picture (not a sub-image of a larger one). */
    private static boolean isPlain(BufferedImage image, int type) {
        if (image.getType() != type || image.getRaster().getParent() != null) {
            return false;
        }
        int elements = type == BufferedImage.TYPE_3BYTE_BGR ? 3 : 1;
        return image.getRaster().getDataBuffer().getSize() == image.getWidth() * image.getHeight() * elements
                && image.getRaster().getDataBuffer().getNumBanks() == 1;
    }

    /** The largest difference of one channel between two 0xRRGGBB colours, 0 to 255. */
    static int distance(int a, int b) {
        int r = Math.abs((a >> 16 & 0xFF) - (b >> 16 & 0xFF));
        int g = Math.abs((a >> 8 & 0xFF) - (b >> 8 & 0xFF));
        int bl = Math.abs((a & 0xFF) - (b & 0xFF));
        return Math.max(r, Math.max(g, bl));
    }
}

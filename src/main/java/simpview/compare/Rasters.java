package simpview.compare;

import java.awt.color.ColorSpace;
import java.awt.color.ICC_ColorSpace;
import java.awt.image.BufferedImage;
import java.awt.image.DataBuffer;
import java.awt.image.DataBufferByte;
import java.awt.image.DataBufferInt;
import java.awt.image.Raster;

/**
 * A picture's pixels as one int[] of 0xRRGGBB, row by row from the top. The
 * common layouts (int RGB, 3-byte BGR) are read straight from their buffers;
 * anything else goes through one bulk getRGB.
 */
final class Rasters {

    private Rasters() {
    }

    /** A colour 0xRRGGBB as the reports write it: "(255,128,0)". */
    static String words(int rgb) {
        return "(" + (rgb >> 16 & 0xFF) + "," + (rgb >> 8 & 0xFF) + "," + (rgb & 0xFF) + ")";
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

    /**
     * The picture's rows as {@link #rgb} reads them, one at a time, for
     * {@link PngCodec#encode(int, int, PngCodec.Rows)}: 0xRRGGBB with any top
     * byte, an int RGB picture's straight from its buffer, any other's by a
     * getRGB of the row.
     */
    static PngCodec.Rows rows(BufferedImage image) {
        int w = image.getWidth();
        if (isPlain(image, BufferedImage.TYPE_INT_RGB) || isPlain(image, BufferedImage.TYPE_INT_ARGB)) {
            int[] data = ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
            return (y, into) -> System.arraycopy(data, y * w, into, 0, w);
        }
        return (y, into) -> image.getRGB(0, y, w, 1, into, 0, w);
    }

    /**
     * A picture file's pixels as a viewer shows them. ImageIO gives a grey picture Java's linear grey
     * colour space, and a CMYK JPEG without a profile a CMYK space of its own, and getRGB would take
     * their levels for light and convert them: here a grey level v is (v, v, v) (16-bit levels scaled
     * to 255, rounded, as getRGB scales 16-bit RGB), and CMYK is mixed as browsers mix it, each of red,
     * green and blue (255 - ink) * (255 - black) / 255, rounded. A CMYK picture with its own profile,
     * and every other one (or one of float or 32-bit levels), is read through getRGB.
     */
    static int[] shown(BufferedImage image) {
        ColorSpace space = image.getColorModel().getColorSpace();
        int type = image.getRaster().getDataBuffer().getDataType();
        if (type != DataBuffer.TYPE_BYTE && type != DataBuffer.TYPE_USHORT) {
            return rgb(image);
        }
        if (space.getType() == ColorSpace.TYPE_GRAY) {
            int[] grey = levels(image, 0);
            for (int i = 0; i < grey.length; i++) {
                grey[i] *= 0x010101;
            }
            return grey;
        }
        if (space.getType() == ColorSpace.TYPE_CMYK && !(space instanceof ICC_ColorSpace)) {
            int[] cyan = levels(image, 0);
            int[] magenta = levels(image, 1);
            int[] yellow = levels(image, 2);
            int[] black = levels(image, 3);
            int[] out = new int[cyan.length];
            for (int i = 0; i < out.length; i++) {
                int white = 255 - black[i];
                out[i] = mix(cyan[i], white) << 16 | mix(magenta[i], white) << 8 | mix(yellow[i], white);
            }
            return out;
        }
        return rgb(image);
    }

    /** One band's samples, row by row from the top, scaled to 0-255 (rounded) from however many bits it has. */
    private static int[] levels(BufferedImage image, int band) {
        Raster raster = image.getRaster();
        int[] samples = raster.getSamples(0, 0, image.getWidth(), image.getHeight(), band, (int[]) null);
        int max = (1 << image.getColorModel().getComponentSize(band)) - 1;
        if (max != 255) {
            for (int i = 0; i < samples.length; i++) {
                samples[i] = (samples[i] * 255 + max / 2) / max;
            }
        }
        return samples;
    }

    /**
     * A picture's alpha, 0-255 row by row from the top (as getRGB gives it, whatever the colour model),
     * or null when the picture has no transparency.
     */
    static byte[] alpha(BufferedImage image) {
        if (!image.getColorModel().hasAlpha()) {
            return null;
        }
        int w = image.getWidth();
        int[] argb = image.getRGB(0, 0, w, image.getHeight(), null, 0, w);
        byte[] alpha = new byte[argb.length];
        for (int i = 0; i < argb.length; i++) {
            alpha[i] = (byte) (argb[i] >>> 24);
        }
        return alpha;
    }

    /** What is left of a channel's light under {@code ink} (0-255), of {@code white} (255 less the black ink). */
    private static int mix(int ink, int white) {
        return ((255 - ink) * white + 127) / 255;
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

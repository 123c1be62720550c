package simpview.compare;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Iterator;
import java.util.Locale;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;
import simpview.scene.FileProblem;

/**
 * A picture to compare: where its panel is, the panel's pixels (650x650
 * 0xRRGGBB, row by row from the top) and the picture's margins. A picture read
 * from a file whose panel is not opaque is refused: a viewer shows what lies
 * behind such pixels, not their colours.
 */
public final class Picture {

    private final String name;
    private final int width;
    private final int height;
    private final PanelPlace place;
    private final int[] panel;
    private final int[] rgb;
    private final byte[] alpha;

    private Picture(String name, int[] rgb, byte[] alpha, int width, int height, PanelPlace place) {
        this.name = name;
        this.rgb = rgb;
        this.alpha = alpha;
        this.width = width;
        this.height = height;
        this.place = place;
        this.panel = new int[PanelPlace.SIZE * PanelPlace.SIZE];
        for (int y = 0; y < PanelPlace.SIZE; y++) {
            System.arraycopy(rgb, (place.top() + y) * width + place.left(), panel, y * PanelPlace.SIZE, PanelPlace.SIZE);
        }
    }

    /** Reads a picture file and finds its panel; every way this can fail is a clear CompareException. */
    public static Picture read(Path file) throws CompareException {
        PngCodec.Pixels pixels = readPixels(file);
        String name = file.toString();
        PanelPlace place = PanelFinder.find(pixels.rgb(), pixels.width(), pixels.height(), name);
        requireOpaque(pixels.alpha(), pixels.width(), place.left(), place.top(), PanelPlace.SIZE, name, "the panel");
        return new Picture(name, pixels.rgb(), pixels.alpha(), pixels.width(), pixels.height(), place);
    }

    /** A picture in memory (a page, a capture), its panel found as in a file. */
    public static Picture of(BufferedImage image, String name) throws CompareException {
        int[] rgb = Rasters.rgb(image);
        PanelPlace place = PanelFinder.find(rgb, image.getWidth(), image.getHeight(), name);
        return new Picture(name, rgb, null, image.getWidth(), image.getHeight(), place);
    }

    /** One of simpview's own 750x750 pages: the panel is where the page puts it, nothing is searched. */
    public static Picture ofPage(BufferedImage page, String name) {
        if (page.getWidth() != PanelFinder.PAGE || page.getHeight() != PanelFinder.PAGE) {
            throw new IllegalArgumentException("a page is 750x750, not " + page.getWidth() + "x" + page.getHeight());
        }
        PanelPlace place = new PanelPlace(PanelFinder.PAGE_MARGIN, PanelFinder.PAGE_MARGIN, "a 750x750 page");
        return new Picture(name, Rasters.rgb(page), null, page.getWidth(), page.getHeight(), place);
    }

    /** A file's pixels: PNG decoded here, other formats (and rarer PNGs) by ImageIO. */
    static PngCodec.Pixels readPixels(Path file) throws CompareException {
        byte[] bytes = readBytes(file);
        if (bytes.length == 0) {
            throw new CompareException(file + " is empty (0 bytes): no picture was saved in it; save or copy the "
                    + "picture again");
        }
        if (PngCodec.isPng(bytes)) {
            try {
                return PngCodec.decode(bytes);
            } catch (PngCodec.TooLarge e) {
                throw new CompareException(file + " " + e.getMessage(), e);
            } catch (CompareException e) {
                throw damaged(file, e.getMessage(), e);
            } catch (PngCodec.Unsupported e) {
                // a kind of PNG ImageIO reads
            }
        }
        long[] size = headerSize(bytes);
        if (size != null && size[0] * size[1] > PngCodec.MAX_PIXELS) {
            // refused before a pixel is decoded: a 30000x30000 GIF would take gigabytes, and end every picture's run
            throw new CompareException(file + " " + new PngCodec.TooLarge(size[0], size[1]).getMessage());
        }
        BufferedImage image;
        try {
            image = ImageIO.read(new ByteArrayInputStream(bytes));
        } catch (IOException | RuntimeException e) {
            // Decoders throw all sorts on damaged data; the cause is for the curious.
            throw damaged(file, e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage(), e);
        }
        if (image == null) {
            throw new CompareException(file + " is not a picture simpview can read (PNG, JPEG, GIF or BMP)");
        }
        return new PngCodec.Pixels(image.getWidth(), image.getHeight(), Rasters.shown(image), Rasters.alpha(image));
    }

    /**
     * The width and height a picture's header says it has, as ImageIO's reader of its format reads them
     * without decoding a pixel; null when no reader knows the format or the header cannot be read (decoding
     * then says what is wrong).
     */
    private static long[] headerSize(byte[] bytes) {
        try (ImageInputStream in = ImageIO.createImageInputStream(new ByteArrayInputStream(bytes))) {
            Iterator<ImageReader> readers = in == null ? null : ImageIO.getImageReaders(in);
            if (readers == null || !readers.hasNext()) {
                return null;
            }
            ImageReader reader = readers.next();
            try {
                reader.setInput(in, true, true);
                return new long[] {reader.getWidth(0), reader.getHeight(0)};
            } finally {
                reader.dispose();
            }
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }

    /**
     * Refuses a square of a picture (its panel, a panel of a page) holding pixels that are not opaque.
     *
     * @param alpha the picture's alpha, rows of {@code width}; null when it has none
     * @param what the square, as the message names it: "the panel", "panel 2"
     */
    static void requireOpaque(byte[] alpha, int width, int left, int top, int size, String name, String what)
            throws CompareException {
        if (alpha == null) {
            return;
        }
        int seeThrough = 0;
        for (int y = top; y < top + size; y++) {
            for (int x = left; x < left + size; x++) {
                if (alpha[y * width + x] != (byte) 255) {
                    seeThrough++;
                }
            }
        }
        if (seeThrough > 0) {
            throw new CompareException(String.format(Locale.ROOT, "%s: %,d of %s's %,d pixels %s not opaque (alpha "
                    + "below 255), and a viewer shows what lies behind them, not their colours: save the picture "
                    + "without transparency", name, seeThrough, what, size * size, seeThrough == 1 ? "is" : "are"));
        }
    }

    private static CompareException damaged(Path file, String why, Exception cause) {
        return new CompareException(file + ": cannot be read as a picture, it is damaged or cut short (" + why + ")", cause);
    }

    private static byte[] readBytes(Path file) throws CompareException {
        if (!Files.exists(file)) {
            throw new CompareException(file + ": no such file");
        }
        if (Files.isDirectory(file)) {
            throw new CompareException(file + " is a folder, not a picture");
        }
        try {
            return Files.readAllBytes(file);
        } catch (AccessDeniedException e) {
            throw new CompareException(file + ": permission denied", e);
        } catch (IOException e) {
            throw new CompareException(file + ": cannot be read: " + FileProblem.of(file, e), e);
        }
    }

    /** The whole picture's pixels, 0xRRGGBB row by row from the top (not a copy: do not change them). */
    int[] rgb() {
        return rgb;
    }

    /** Their alpha, 0-255 the same way, or null when the picture has none (not a copy). */
    byte[] alpha() {
        return alpha;
    }

    public String name() {
        return name;
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    public PanelPlace place() {
        return place;
    }

    /** The panel's pixels, 650x650 0xRRGGBB from the top row down. Shared, not a copy: do not change it. */
    public int[] panel() {
        return panel;
    }

    /** The margins around the panel, judged with a tolerance (in 1/255 steps). */
    public Margins margins(int tolerance) {
        return Margins.of(rgb, width, height, place, tolerance);
    }
}

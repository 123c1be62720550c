package simpview.compare;

import java.awt.image.BufferedImage;
import java.awt.image.ColorModel;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Objects;
import javax.imageio.ImageIO;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;

/** Writes finished pages as PNG files, with messages a user can act on. */
public final class PngFiles {

    /** Why a name not ending in .png is refused for a picture simpview writes ({@link #isPngName}). */
    public static final String PNG_ONLY = "simpview writes PNG files only; name it .png";

    private PngFiles() {
    }

    /**
     * Writes {@code image} to {@code file}, making missing parent folders;
     * the file is replaced only once the whole picture is written, and a FIFO
     * or a device there is written into ({@link OutputFiles}).
     *
     * @throws IllegalArgumentException when the name has another extension
     *     than .png ({@link #isPngName}): PNG bytes under a name such as
     *     x.jpg would be opened as what they are not
     * @throws IOException whose message says which file and why, e.g.
     *     "cannot write out/x.png: permission denied"
     */
    public static void write(BufferedImage image, Path file) throws IOException {
        Objects.requireNonNull(image, "image must not be null");
        Objects.requireNonNull(file, "file must not be null");
        if (!isPngName(file)) {
            throw new IllegalArgumentException(file + ": " + PNG_ONLY);
        }
        // Encoded in memory first: ImageIO's own file streams report a full
        // disk as "I/O error writing PNG file!" and can fail again at exit.
        writeEncoded(encode(image), file);
    }

    /** Writes a PNG already encoded (compare's diff images), with the same messages. */
    public static void writeEncoded(byte[] png, Path file) throws IOException {
        OutputFiles.write(file, out -> out.write(png));
    }

    /** True for a name ending in .png (any case), or with no extension at all. */
    public static boolean isPngName(Path file) {
        String name = file.getFileName() == null ? "" : file.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return dot <= 0 || name.substring(dot + 1).equalsIgnoreCase("png");
    }

    /** The name with ".png" added when it has no extension (a Save dialog's answer "page3"). */
    public static Path withPngExtension(Path file) {
        String name = file.getFileName().toString();
        return name.lastIndexOf('.') > 0 ? file : file.resolveSibling(name + ".png");
    }

    /**
     * An opaque picture in sRGB (every page, sheet and view simpview saves)
     * through {@link PngCodec}, as compare's own pictures: 8-bit RGB, its
     * levels as they are, encoded a row at a time (a sheet of many scenes
     * needs no second copy of itself). ImageIO, for any other picture (with
     * alpha, grey, in another colour space), writes it as its kind: it also
     * costs more, 25-36 ms against 7-11 for a warm page, 74-90 against 35 for
     * the first one a process writes (docs/performance-log.md, "Session 45").
     */
    private static byte[] encode(BufferedImage image) throws IOException {
        ColorModel model = image.getColorModel();
        if (!model.hasAlpha() && model.getColorSpace().isCS_sRGB()) {
            return PngCodec.encode(image.getWidth(), image.getHeight(), Rasters.rows(image));
        }
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ImageOutputStream out = new MemoryCacheImageOutputStream(bytes)) {
            if (!ImageIO.write(image, "png", out)) {
                throw new IOException("this Java has no PNG writer");
            }
        }
        return bytes.toByteArray();
    }
}

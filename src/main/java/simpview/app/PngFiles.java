package simpview.app;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Iterator;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;

/** Writes finished pages as PNG files, with messages a user can act on. */
final class PngFiles {

    private static final float FAST_QUALITY = 0.85f;

    private PngFiles() {
    }

    /**
     * Writes {@code image} to {@code file}, making missing parent folders.
     *
     * @throws IOException whose message says which file and why, e.g.
     *     "cannot write out/x.png: permission denied"
     */
    static void write(BufferedImage image, Path file) throws IOException {
        write(image, file, false);
    }

    /** The same, compressed less to write faster (diff images: written often, looked at once). */
    static void writeFast(BufferedImage image, Path file) throws IOException {
        write(image, file, true);
    }

    private static void write(BufferedImage image, Path file, boolean fast) throws IOException {
        Path target = file.toAbsolutePath();
        try {
            Path parent = target.getParent();
            if (parent != null) {
                Files.createDirectories(parent);
            }
            // Encoded in memory first: ImageIO's own file streams report a full
            // disk as "I/O error writing PNG file!" and can fail again at exit.
            Files.write(target, encode(image, fast));
        } catch (IOException e) {
            throw new IOException("cannot write " + file + ": " + reason(e, target), e);
        }
    }

    private static byte[] encode(BufferedImage image, boolean fast) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ImageOutputStream out = new MemoryCacheImageOutputStream(bytes)) {
            if (fast) {
                encodeFast(image, out);
            } else if (!ImageIO.write(image, "png", out)) {
                throw new IOException("this Java has no PNG writer");
            }
        }
        return bytes.toByteArray();
    }

    /** The JDK's PNG writer maps a compression quality q to deflate level 9 (1 - q): 0.85 gives level 1. */
    private static void encodeFast(BufferedImage image, ImageOutputStream out) throws IOException {
        Iterator<ImageWriter> writers = ImageIO.getImageWritersByFormatName("png");
        if (!writers.hasNext()) {
            throw new IOException("this Java has no PNG writer");
        }
        ImageWriter writer = writers.next();
        try {
            ImageWriteParam param = writer.getDefaultWriteParam();
            param.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
            param.setCompressionQuality(FAST_QUALITY);
            writer.setOutput(out);
            writer.write(null, new IIOImage(image, null, null), param);
        } finally {
            writer.dispose();
        }
    }

    private static String reason(IOException e, Path target) {
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof FileAlreadyExistsException already) {
            return already.getFile() + " is in the way: it is a file, not a folder";
        }
        if (e instanceof FileSystemException fs && fs.getReason() != null) {
            boolean elsewhere = fs.getFile() != null && !Path.of(fs.getFile()).equals(target);
            return fs.getReason() + (elsewhere ? " (" + fs.getFile() + ")" : "");
        }
        if (e instanceof FileSystemException fs) {
            return "no such file or folder: " + fs.getFile();
        }
        return e.getMessage();
    }
}

package simpview.compare;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;

/** Writes finished pages as PNG files, with messages a user can act on. */
public final class PngFiles {

    private PngFiles() {
    }

    /**
     * Writes {@code image} to {@code file}, making missing parent folders.
     *
     * @throws IOException whose message says which file and why, e.g.
     *     "cannot write out/x.png: permission denied"
     */
    public static void write(BufferedImage image, Path file) throws IOException {
        // Encoded in memory first: ImageIO's own file streams report a full
        // disk as "I/O error writing PNG file!" and can fail again at exit.
        writeEncoded(encode(image), file);
    }

    /** Writes a PNG already encoded (compare's diff images), with the same messages. */
    public static void writeEncoded(byte[] png, Path file) throws IOException {
        Path target = file.toAbsolutePath();
        try {
            Path parent = target.getParent();
            if (parent != null) {
                Files.createDirectories(parent);
            }
            Files.write(target, png);
        } catch (IOException e) {
            throw new IOException("cannot write " + file + ": " + reason(e, target), e);
        }
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

    private static byte[] encode(BufferedImage image) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ImageOutputStream out = new MemoryCacheImageOutputStream(bytes)) {
            if (!ImageIO.write(image, "png", out)) {
                throw new IOException("this Java has no PNG writer");
            }
        }
        return bytes.toByteArray();
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

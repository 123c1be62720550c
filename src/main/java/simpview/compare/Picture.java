package simpview.compare;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;
import simpview.scene.FileProblem;
import simpview.scene.PlainPath;

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
    private final PictureFormat format;

    private Picture(String name, int[] rgb, byte[] alpha, int width, int height, PanelPlace place,
            PictureFormat format) {
        this.name = name;
        this.format = format;
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
    public static Picture read(Path named) throws CompareException {
        Objects.requireNonNull(named, "file must not be null");
        // named in every message and report without "." parts: a folder "." checked holds page1.png, not ./page1.png
        Path file = PlainPath.of(named);
        PngCodec.Pixels pixels = readPixels(file);
        String name = file.toString();
        PanelPlace place = PanelFinder.find(pixels.rgb(), pixels.width(), pixels.height(), name);
        requireOpaque(pixels.alpha(), pixels.width(), place.left(), place.top(), PanelPlace.SIZE, name, "the panel");
        return new Picture(name, pixels.rgb(), pixels.alpha(), pixels.width(), pixels.height(), place,
                pixels.format());
    }

    /** A picture in memory (a page, a capture), its panel found as in a file. */
    public static Picture of(BufferedImage image, String name) throws CompareException {
        Objects.requireNonNull(image, "image must not be null");
        Objects.requireNonNull(name, "name must not be null");
        int[] rgb = Rasters.rgb(image);
        PanelPlace place = PanelFinder.find(rgb, image.getWidth(), image.getHeight(), name);
        return new Picture(name, rgb, null, image.getWidth(), image.getHeight(), place, null);
    }

    /** One of simpview's own 750x750 pages: the panel is where the page puts it, nothing is searched. */
    public static Picture ofPage(BufferedImage page, String name) {
        Objects.requireNonNull(page, "page must not be null");
        Objects.requireNonNull(name, "name must not be null");
        if (page.getWidth() != PanelFinder.PAGE || page.getHeight() != PanelFinder.PAGE) {
            throw new IllegalArgumentException("a page is 750x750, not " + page.getWidth() + "x" + page.getHeight());
        }
        PanelPlace place = new PanelPlace(PanelFinder.PAGE_MARGIN, PanelFinder.PAGE_MARGIN, "a 750x750 page");
        return new Picture(name, Rasters.rgb(page), null, page.getWidth(), page.getHeight(), place, null);
    }

    /** A file's pixels: PNG decoded here, other formats (and rarer PNGs) by ImageIO. */
    static PngCodec.Pixels readPixels(Path named) throws CompareException {
        Path file = PlainPath.of(named);
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
        Header header = header(bytes);
        if (header != null && header.width() * header.height() > PngCodec.MAX_PIXELS) {
            // refused before a pixel is decoded: a 30000x30000 GIF would take gigabytes, and end every picture's run
            throw new CompareException(file + " " + new PngCodec.TooLarge(header.width(), header.height()).getMessage());
        }
        BufferedImage image;
        try {
            image = ImageIO.read(new ByteArrayInputStream(bytes));
        } catch (IOException | RuntimeException e) {
            // Decoders throw all sorts on damaged data; the cause is for the curious.
            throw damaged(file, e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage(), e);
        }
        if (image == null) {
            throw new CompareException(file + " is not a picture simpview can read (PNG, JPEG, GIF or BMP)"
                    + holds(bytes));
        }
        // ImageIO.read decodes with the first reader that knows the bytes, the one header() asked: its format
        PictureFormat format = header == null ? PictureFormat.OTHER : header.format();
        return new PngCodec.Pixels(image.getWidth(), image.getHeight(), Rasters.shown(image), Rasters.alpha(image),
                format);
    }

    /** The brands of an AVIF picture, still (avif) or a sequence (avis). */
    private static final List<String> AVIF_BRANDS = List.of("avif", "avis");
    /** The brands of a HEIC picture (HEVC-coded HEIF), still or a sequence, as an iPhone saves them. */
    private static final List<String> HEIC_BRANDS = List.of("heic", "heix", "heim", "heis", "hevc", "hevx", "hevm",
            "hevs");
    /** The brands of HEIF's general structure alone, which both AVIF and HEIC files may give as their major one. */
    private static final List<String> HEIF_BRANDS = List.of("mif1", "msf1", "mif2");

    /**
     * What an ISO file of the HEIF family holds, from its ftyp box: its major brand, then its compatible brands, in
     * order (an AVIF picture often names the general "mif1" as its major brand and "avif" among its compatible
     * ones): "an AVIF picture" for avif or avis, "a HEIC picture ..." for heic, heix, hevc and their kin, "a HEIF
     * picture" for mif1 or msf1 alone; null when the box names none of these.
     */
    static String heifKind(byte[] bytes) {
        if (bytes.length < 16) {
            return null;
        }
        long size = ((bytes[0] & 0xFFL) << 24) | ((bytes[1] & 0xFF) << 16) | ((bytes[2] & 0xFF) << 8) | (bytes[3] & 0xFF);
        int end = (int) Math.min(Math.min(bytes.length, 4096), size < 16 ? 16 : size);
        List<String> brands = new ArrayList<>();
        brands.add(new String(bytes, 8, 4, StandardCharsets.ISO_8859_1)); // the major brand, then the compatible
        for (int at = 16; at + 4 <= end; at += 4) {
            brands.add(new String(bytes, at, 4, StandardCharsets.ISO_8859_1));
        }
        boolean heif = false;
        for (String brand : brands) {
            if (AVIF_BRANDS.contains(brand)) {
                return "an AVIF picture";
            }
            if (HEIC_BRANDS.contains(brand)) {
                return "a HEIC picture (as an iPhone saves them)";
            }
            heif |= HEIF_BRANDS.contains(brand);
        }
        return heif ? "a HEIF picture" : null;
    }

    /**
     * What bytes that are no picture simpview reads hold, when their start tells, for the student to be told what
     * to do: a picture in another format whatever its name says (a screenshot tool's WebP saved as page4.png),
     * a document or an archive, or text, quoted ("my renderer crashed on this one"); "" otherwise.
     */
    static String holds(byte[] bytes) {
        String start = new String(bytes, 0, Math.min(bytes.length, 512), StandardCharsets.ISO_8859_1);
        String other = null;
        if (start.startsWith("RIFF") && start.startsWith("WEBP", 8)) {
            other = "a WebP picture";
        } else if (start.startsWith("II*\0") || start.startsWith("MM\0*")) {
            other = "a TIFF picture";
        } else if (start.startsWith("ftyp", 4) && heifKind(bytes) != null) {
            other = heifKind(bytes);
        } else if (start.startsWith("%PDF")) {
            return ": it holds a PDF document; save the page itself as PNG";
        } else if (start.startsWith("PK\3\4")) {
            return ": it holds a zip archive (or a document made of one); save the page itself as PNG";
        } else if (start.contains("<svg")) {
            other = "an SVG drawing";
        }
        if (other != null) {
            return ": it holds " + other + ", whatever its name says; save it as PNG";
        }
        int end = Math.min(bytes.length, 4096);
        while (end < bytes.length && end > 0 && (bytes[end] & 0xC0) == 0x80) {
            end--; // not inside a character
        }
        String text;
        try {
            text = StandardCharsets.UTF_8.newDecoder()
                    .decode(ByteBuffer.wrap(bytes, 0, end)).toString();
        } catch (CharacterCodingException e) {
            return ""; // not text
        }
        if (text.codePoints().anyMatch(c -> Character.isISOControl(c) && c != '\n' && c != '\r' && c != '\t')) {
            return "";
        }
        String line = text.lines().map(String::strip).filter(l -> !l.isEmpty()).findFirst().orElse("");
        if (line.isEmpty()) {
            return ": it holds only white space";
        }
        return ": it holds text (\"" + (line.length() > 60 ? line.substring(0, 60) + "..." : line) + "\")";
    }

    /**
     * What a picture's header says, as ImageIO's first reader that knows its bytes reads it without decoding a
     * pixel: the format that reader decodes (by the bytes, never the file's name) and the width and height, 0 x 0
     * when they cannot be read.
     */
    private record Header(PictureFormat format, long width, long height) {
    }

    /**
     * The header of a picture ({@link Header}); null when no reader knows the format (decoding then says what is
     * wrong).
     */
    private static Header header(byte[] bytes) {
        try (ImageInputStream in = ImageIO.createImageInputStream(new ByteArrayInputStream(bytes))) {
            Iterator<ImageReader> readers = in == null ? null : ImageIO.getImageReaders(in);
            if (readers == null || !readers.hasNext()) {
                return null;
            }
            ImageReader reader = readers.next();
            PictureFormat format = PictureFormat.ofFormatName(reader.getFormatName());
            try {
                reader.setInput(in, true, true);
                return new Header(format, reader.getWidth(0), reader.getHeight(0));
            } catch (IOException | RuntimeException e) {
                return new Header(format, 0, 0); // its size unread: decoding then says what is wrong
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
            // ls lists it, and a folder's batch takes it: say what it is, a loop of links or a link to nothing
            String link = FileProblem.brokenLink(file);
            if (link != null) {
                throw new CompareException(file + " " + link + ": put the picture itself in its place");
            }
            if (Files.isSymbolicLink(file)) {
                throw new CompareException(file + " is a link to " + linkTarget(file) + ", which does not exist: "
                        + "put the picture itself in its place");
            }
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

    /** Where a link leads, as it is written in it; "somewhere that cannot be read" when it cannot be. */
    private static String linkTarget(Path link) {
        try {
            return Files.readSymbolicLink(link).toString();
        } catch (IOException | UnsupportedOperationException e) {
            return "somewhere that cannot be read";
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

    /** The picture's name in reports: its file's path as given, or the name it was made with. */
    public String name() {
        return name;
    }

    /**
     * The format its file's bytes were decoded as, whatever its name says (a JPEG saved as x.png is a JPEG); null
     * for a picture in memory, read from no file.
     */
    public PictureFormat format() {
        return format;
    }

    /** The whole picture's width in pixels, margins included (750 for a page). */
    public int width() {
        return width;
    }

    /** The whole picture's height in pixels, margins included (750 for a page). */
    public int height() {
        return height;
    }

    /** Where the 650x650 panel was found in the picture, and how. */
    public PanelPlace place() {
        return place;
    }

    /** The panel's pixels, 650x650 0xRRGGBB from the top row down. Shared, not a copy: do not change it. */
    public int[] panel() {
        return panel;
    }

    /**
     * The margins around the panel, judged with a tolerance (in 1/255 steps); a picture decoded as JPEG with at
     * least a JPEG's slack ({@link PanelFinder#JPEG_SLACK}), for its noise leaves white margins only near white.
     */
    public Margins margins(int tolerance) {
        boolean jpeg = format == PictureFormat.JPEG;
        return Margins.of(rgb, width, height, place, jpeg ? Math.max(tolerance, PanelFinder.JPEG_SLACK) : tolerance,
                jpeg);
    }
}

package simpview.compare;

import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Locale;
import java.util.zip.CRC32;
import java.util.zip.DataFormatException;
import java.util.zip.Deflater;
import java.util.zip.Inflater;

/**
 * Reads and writes the PNG files compare meets most, without ImageIO (whose
 * start-up costs more than a whole comparison): 8-bit grey, grey+alpha, RGB,
 * RGBA and palette pictures, not interlaced, straight into 0xRRGGBB pixels
 * and their alpha apart. Anything else (and a grey or RGB picture with one
 * transparent colour) is {@link Unsupported}, and the caller falls back to
 * ImageIO.
 */
final class PngCodec {

    /** A PNG this codec does not read (interlaced, 16-bit, fewer bits per pixel); ImageIO may. */
    static final class Unsupported extends Exception {
        private static final long serialVersionUID = 1L;

        Unsupported(String what) {
            super(what, null, false, false);
        }
    }

    /**
     * A PNG larger than this codec reads ({@link #MAX_PIXELS}): valid, but not a picture of a page (750x750) or
     * a window capture; its message says its size and the limit.
     */
    static final class TooLarge extends Exception {
        private static final long serialVersionUID = 1L;

        TooLarge(long width, long height) {
            super(String.format(Locale.ROOT, "is %dx%d pixels (%,d), more than simpview reads (%,d pixels at "
                    + "most, as 8192x8192): a page is 750x750 and a window capture about 872x782, so save the picture at "
                    + "its own size", width, height, width * height, MAX_PIXELS), null, false, false);
        }
    }

    /**
     * A decoded picture: width x height pixels, row by row from the top, and their alpha (0-255) the
     * same way, or null when the picture has no transparency; {@code format} the format its bytes were decoded
     * as, whatever the file's name says.
     */
    record Pixels(int width, int height, int[] rgb, byte[] alpha, PictureFormat format) {
    }

    private static final byte[] SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', 13, 10, 26, 10};
    static final long MAX_PIXELS = 64L << 20;

    private PngCodec() {
    }

    static boolean isPng(byte[] file) {
        if (file.length < SIGNATURE.length) {
            return false;
        }
        for (int i = 0; i < SIGNATURE.length; i++) {
            if (file[i] != SIGNATURE[i]) {
                return false;
            }
        }
        return true;
    }

    /**
     * Decodes a PNG file's bytes.
     *
     * @throws CompareException with what is wrong, when the file is damaged or cut short
     * @throws Unsupported when it is a kind of PNG this codec leaves to ImageIO
     * @throws TooLarge when it says it has more than {@link #MAX_PIXELS} pixels
     */
    static Pixels decode(byte[] file) throws CompareException, Unsupported, TooLarge {
        ByteBuffer in = ByteBuffer.wrap(file);
        in.position(SIGNATURE.length);
        Header header = null;
        byte[] palette = null;
        byte[] transparency = null;
        ByteArrayOutputStream idat = new ByteArrayOutputStream(file.length);
        while (true) {
            Chunk chunk = Chunk.next(in, file);
            switch (chunk.type()) {
                case "IHDR" -> header = Header.of(file, chunk);
                case "PLTE" -> palette = Arrays.copyOfRange(file, chunk.start(), chunk.start() + chunk.length());
                case "IDAT" -> idat.write(file, chunk.start(), chunk.length());
                case "tRNS" -> {
                    if (need(header).colourType() != 3) {
                        throw new Unsupported("a transparent colour");
                    }
                    transparency = Arrays.copyOfRange(file, chunk.start(), chunk.start() + chunk.length());
                }
                case "IEND" -> {
                    return unfilter(need(header), palette, transparency, inflate(idat.toByteArray(), need(header)));
                }
                default -> {
                    // ancillary chunks (gamma, text, time ...) change no pixel compare looks at
                }
            }
        }
    }

    private static Header need(Header header) throws CompareException {
        if (header == null) {
            throw new CompareException("no IHDR chunk before the pixels");
        }
        return header;
    }

    private record Chunk(String type, int start, int length) {
        static Chunk next(ByteBuffer in, byte[] file) throws CompareException {
            if (in.remaining() < 12) {
                throw new CompareException("the file ends before its IEND chunk");
            }
            int length = in.getInt();
            int typeAt = in.position();
            String type = new String(file, typeAt, 4, StandardCharsets.ISO_8859_1);
            if (length < 0 || length > in.remaining() - 8) {
                throw new CompareException("chunk " + type + " runs past the end of the file");
            }
            CRC32 crc = new CRC32();
            crc.update(file, typeAt, 4 + length);
            in.position(typeAt + 4 + length);
            if ((int) crc.getValue() != in.getInt()) {
                throw new CompareException("chunk " + type + " fails its checksum");
            }
            return new Chunk(type, typeAt + 4, length);
        }
    }

    private record Header(int width, int height, int colourType, int channels) {
        static Header of(byte[] file, Chunk chunk) throws CompareException, Unsupported, TooLarge {
            if (chunk.length() != 13) {
                throw new CompareException("its IHDR chunk is " + chunk.length() + " bytes, not 13");
            }
            ByteBuffer b = ByteBuffer.wrap(file, chunk.start(), 13);
            int width = b.getInt();
            int height = b.getInt();
            int depth = b.get() & 0xFF;
            int colourType = b.get() & 0xFF;
            b.get();
            b.get();
            int interlace = b.get() & 0xFF;
            if (width <= 0 || height <= 0) {
                throw new CompareException("it says it is " + width + "x" + height + " pixels");
            }
            if ((long) width * height > MAX_PIXELS) {
                throw new TooLarge(width, height);
            }
            int channels = switch (colourType) {
                case 0, 3 -> 1;
                case 4 -> 2;
                case 2 -> 3;
                case 6 -> 4;
                default -> throw new CompareException("unknown colour type " + colourType);
            };
            if (depth != 8 || interlace != 0) {
                throw new Unsupported(depth + "-bit" + (interlace != 0 ? ", interlaced" : ""));
            }
            return new Header(width, height, colourType, channels);
        }
    }

    private static byte[] inflate(byte[] compressed, Header h) throws CompareException {
        byte[] raw = new byte[(h.width() * h.channels() + 1) * h.height()];
        Inflater inflater = new Inflater();
        try {
            inflater.setInput(compressed);
            int done = 0;
            while (done < raw.length) {
                int n = inflater.inflate(raw, done, raw.length - done);
                if (n == 0 && (inflater.needsInput() || inflater.finished() || inflater.needsDictionary())) {
                    throw new CompareException("its pixels stop after " + done / (h.width() * h.channels() + 1)
                            + " of " + h.height() + " rows");
                }
                done += n;
            }
            return raw;
        } catch (DataFormatException e) {
            throw new CompareException("its compressed pixels are damaged (" + e.getMessage() + ")");
        } finally {
            inflater.end();
        }
    }

    /**
     * Undoes the five PNG row filters in place and packs the pixels as 0xRRGGBB, and their alpha apart
     * (of a palette picture, from its tRNS chunk: the alpha of its first colours, the rest opaque).
     */
    private static Pixels unfilter(Header h, byte[] palette, byte[] transparency, byte[] raw) throws CompareException {
        int bpp = h.channels();
        int stride = h.width() * bpp;
        if (h.colourType() == 3 && palette == null) {
            throw new CompareException("a palette picture without a PLTE chunk");
        }
        int[] rgb = new int[h.width() * h.height()];
        boolean seeThrough = h.colourType() == 4 || h.colourType() == 6 || transparency != null;
        byte[] alpha = seeThrough ? new byte[rgb.length] : null;
        for (int y = 0; y < h.height(); y++) {
            int row = y * (stride + 1) + 1;
            int prior = row - stride - 1;
            int filter = raw[row - 1];
            unfilterRow(raw, row, y == 0 ? -1 : prior, stride, bpp, filter);
            pack(h, palette, raw, row, rgb, y * h.width());
            if (alpha != null) {
                alphaOf(h, transparency, raw, row, alpha, y * h.width());
            }
        }
        return new Pixels(h.width(), h.height(), rgb, alpha, PictureFormat.PNG);
    }

    /** One row's filter undone; {@code prior} is the row above, or -1 for the first row. One loop per filter. */
    private static void unfilterRow(byte[] raw, int row, int prior, int stride, int bpp, int filter)
            throws CompareException {
        switch (filter) {
            case 0 -> {
                // None: the bytes are the pixels
            }
            case 1 -> {
                for (int i = bpp; i < stride; i++) {
                    raw[row + i] += raw[row + i - bpp];
                }
            }
            case 2 -> {
                for (int i = 0; prior >= 0 && i < stride; i++) {
                    raw[row + i] += raw[prior + i];
                }
            }
            case 3 -> {
                for (int i = 0; i < stride; i++) {
                    int left = i >= bpp ? raw[row + i - bpp] & 0xFF : 0;
                    int up = prior >= 0 ? raw[prior + i] & 0xFF : 0;
                    raw[row + i] += (byte) ((left + up) >>> 1);
                }
            }
            case 4 -> {
                for (int i = 0; i < stride; i++) {
                    int left = i >= bpp ? raw[row + i - bpp] & 0xFF : 0;
                    int up = prior >= 0 ? raw[prior + i] & 0xFF : 0;
                    int upLeft = prior >= 0 && i >= bpp ? raw[prior + i - bpp] & 0xFF : 0;
                    raw[row + i] += (byte) paeth(left, up, upLeft);
                }
            }
            default -> throw new CompareException("unknown row filter " + filter);
        }
    }

    private static int paeth(int a, int b, int c) {
        int p = a + b - c;
        int pa = Math.abs(p - a);
        int pb = Math.abs(p - b);
        int pc = Math.abs(p - c);
        return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
    }

    private static void pack(Header h, byte[] palette, byte[] raw, int row, int[] rgb, int at) throws CompareException {
        int bpp = h.channels();
        int w = h.width();
        if (h.colourType() == 2 || h.colourType() == 6) {
            for (int x = 0, p = row; x < w; x++, p += bpp) {
                rgb[at + x] = (raw[p] & 0xFF) << 16 | (raw[p + 1] & 0xFF) << 8 | raw[p + 2] & 0xFF;
            }
        } else if (h.colourType() == 3) {
            for (int x = 0; x < w; x++) {
                rgb[at + x] = fromPalette(palette, raw[row + x] & 0xFF);
            }
        } else {
            for (int x = 0, p = row; x < w; x++, p += bpp) {
                rgb[at + x] = (raw[p] & 0xFF) * 0x010101;
            }
        }
    }

    /** One row's alpha: the last byte of each grey+alpha or RGBA pixel, or its palette colour's. */
    private static void alphaOf(Header h, byte[] transparency, byte[] raw, int row, byte[] alpha, int at) {
        int bpp = h.channels();
        for (int x = 0, p = row; x < h.width(); x++, p += bpp) {
            if (h.colourType() != 3) {
                alpha[at + x] = raw[p + bpp - 1];
            } else {
                int index = raw[p] & 0xFF;
                alpha[at + x] = index < transparency.length ? transparency[index] : (byte) 255;
            }
        }
    }

    private static int fromPalette(byte[] palette, int index) throws CompareException {
        if (3 * index + 2 >= palette.length) {
            throw new CompareException("a pixel names colour " + index + " of a palette of " + palette.length / 3);
        }
        return (palette[3 * index] & 0xFF) << 16 | (palette[3 * index + 1] & 0xFF) << 8 | palette[3 * index + 2] & 0xFF;
    }

    /** A picture's rows for {@link #encode(int, int, Rows)}: row y (0 at the top) into {@code into}, width pixels. */
    interface Rows {
        /** Row y as 0xRRGGBB (any top byte: only the low 24 bits are written). */
        void row(int y, int[] into);
    }

    /** As {@link #encode(int, int, Rows)}, of width x height pixels row by row from the top in {@code rgb}. */
    static byte[] encode(int width, int height, int[] rgb) {
        return encode(width, height, (y, into) -> System.arraycopy(rgb, y * width, into, 0, width));
    }

    /**
     * An 8-bit RGB PNG of 0xRRGGBB pixels, every row but the first filtered
     * "Up" (the difference from the row above: pictures of panels repeat a lot
     * from row to row, so this deflates smaller and faster), at the fastest
     * level. The rows are read, filtered and deflated one at a time: beside
     * the picture, only two rows and the deflated bytes are held.
     */
    static byte[] encode(int width, int height, Rows rows) {
        int[] row = new int[width];
        int[] up = new int[width]; // the row above, 0 above the first (which then is filtered "None" alike)
        byte[] filtered = new byte[3 * width + 1];
        ByteArrayOutputStream idat = new ByteArrayOutputStream();
        byte[] buffer = new byte[1 << 16];
        Deflater deflater = new Deflater(Deflater.BEST_SPEED);
        try {
            for (int y = 0; y < height; y++) {
                rows.row(y, row);
                filtered[0] = (byte) (y == 0 ? 0 : 2);
                for (int x = 0, o = 1; x < width; x++) {
                    int c = row[x];
                    int above = up[x];
                    filtered[o++] = (byte) ((c >> 16) - (above >> 16));
                    filtered[o++] = (byte) ((c >> 8) - (above >> 8));
                    filtered[o++] = (byte) (c - above);
                }
                deflater.setInput(filtered);
                while (!deflater.needsInput()) {
                    idat.write(buffer, 0, deflater.deflate(buffer));
                }
                int[] was = up;
                up = row;
                row = was;
            }
            deflater.finish();
            while (!deflater.finished()) {
                idat.write(buffer, 0, deflater.deflate(buffer));
            }
        } finally {
            deflater.end();
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream(idat.size() + 64);
        out.writeBytes(SIGNATURE);
        ByteBuffer ihdr = ByteBuffer.allocate(13).putInt(width).putInt(height).put((byte) 8).put((byte) 2);
        chunk(out, "IHDR", ihdr.array());
        chunk(out, "IDAT", idat.toByteArray());
        chunk(out, "IEND", new byte[0]);
        return out.toByteArray();
    }

    /** One chunk of a PNG file to {@code out}: its length, type, data and CRC (tests write odd files with it too). */
    static void chunk(ByteArrayOutputStream out, String type, byte[] data) {
        byte[] name = type.getBytes(StandardCharsets.ISO_8859_1);
        CRC32 crc = new CRC32();
        crc.update(name);
        crc.update(data);
        out.writeBytes(ByteBuffer.allocate(4).putInt(data.length).array());
        out.writeBytes(name);
        out.writeBytes(data);
        out.writeBytes(ByteBuffer.allocate(4).putInt((int) crc.getValue()).array());
    }
}

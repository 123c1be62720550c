package simpview.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A file that cannot be compared is told what it is: empty, or a picture larger than simpview reads, not "damaged". */
class PictureProblemsTest {

    @TempDir
    Path dir;

    @Test
    void aPictureOverTheSizeLimitIsSaidToBeSoNotDamaged() throws Exception {
        // The header of a 12000x12000 RGB picture: what it says is read before any pixel.
        ByteArrayOutputStream png = new ByteArrayOutputStream();
        png.writeBytes(new byte[] {(byte) 0x89, 'P', 'N', 'G', 13, 10, 26, 10});
        PngCodec.chunk(png, "IHDR", ByteBuffer.allocate(13).putInt(12000).putInt(12000).put((byte) 8).put((byte) 2).array());
        PngCodec.chunk(png, "IEND", new byte[0]);
        Path file = Files.write(dir.resolve("page1.png"), png.toByteArray());

        String why = assertThrows(CompareException.class, () -> Picture.read(file)).getMessage();
        assertEquals(file + " is 12000x12000 pixels (144,000,000), more than simpview reads (67,108,864 pixels at most, "
                + "as 8192x8192): a page is 750x750 and a window capture about 872x782, so save the picture at its own "
                + "size", why);
        assertFalse(why.contains("damaged"), why);
    }

    /**
     * A GIF (or JPEG, or BMP) over the limit is refused from its header as a PNG is, before a pixel is decoded:
     * a 30000x30000 GIF of a few bytes had run a class's batch out of memory.
     */
    @Test
    void aGifOverTheSizeLimitIsRefusedFromItsHeader() throws Exception {
        ByteArrayOutputStream gif = new ByteArrayOutputStream();
        byte lo = (byte) (30000 & 0xFF);
        byte hi = (byte) (30000 >> 8);
        gif.writeBytes(new byte[] {'G', 'I', 'F', '8', '9', 'a', lo, hi, lo, hi, (byte) 0x80, 0, 0,
            0, 0, 0, (byte) 255, (byte) 255, (byte) 255, // a global colour table of two colours
            0x2C, 0, 0, 0, 0, lo, hi, lo, hi, 0, // the image: at (0, 0), 30000x30000
            2, 2, 0x4C, 0x01, 0, 0x3B});
        Path file = Files.write(dir.resolve("page2.gif"), gif.toByteArray());
        String why = assertThrows(CompareException.class, () -> Picture.read(file)).getMessage();
        assertTrue(why.startsWith(file + " is 30000x30000 pixels (900,000,000), more than simpview reads"), why);
    }

    @Test
    void anEmptyFileIsSaidToBeEmpty() throws Exception {
        Path file = Files.write(dir.resolve("page2.png"), new byte[0]);
        String why = assertThrows(CompareException.class, () -> Picture.read(file)).getMessage();
        assertTrue(why.startsWith(file + " is empty (0 bytes)"), why);
        assertFalse(why.contains("is not a picture simpview can read"), why);
    }

    /**
     * A file named .png that is no picture was told only that: a student's note saved as page4.png, or a
     * screenshot tool's WebP named page4.png, got the same words. Each is now told what it holds.
     */
    @Test
    void aFileThatIsNoPictureIsToldWhatItHolds() throws Exception {
        Path note = Files.writeString(dir.resolve("page4.png"), "\nmy renderer crashed on this one, sorry\nJudy\n");
        String why = assertThrows(CompareException.class, () -> Picture.read(note)).getMessage();
        assertEquals(note + " is not a picture simpview can read (PNG, JPEG, GIF or BMP): it holds text (\"my "
                + "renderer crashed on this one, sorry\")", why);
        Path webp = Files.write(dir.resolve("page5.png"),
                new byte[] {'R', 'I', 'F', 'F', 40, 0, 0, 0, 'W', 'E', 'B', 'P', 'V', 'P', '8', ' ', 0, 0});
        assertEquals(webp + " is not a picture simpview can read (PNG, JPEG, GIF or BMP): it holds a WebP picture, "
                + "whatever its name says; save it as PNG",
                assertThrows(CompareException.class, () -> Picture.read(webp)).getMessage());
        Path noise = Files.write(dir.resolve("page6.png"), new byte[] {1, 2, (byte) 0xFE, 0, 7, 9, 13, 10, 0});
        assertEquals(noise + " is not a picture simpview can read (PNG, JPEG, GIF or BMP)",
                assertThrows(CompareException.class, () -> Picture.read(noise)).getMessage(), "nothing known");
    }

    /**
     * An AVIF picture whose ftyp box names "mif1" as its major brand and "avif" among its compatible ones (as
     * libavif and many tools write it) was called a HEIC picture: its format is named by its brands, in order.
     */
    @Test
    void anAvifOrHeicPictureIsNamedByItsBrands() throws Exception {
        String[][] files = {
            {"mif1", "mif1miafavifMA1B", "an AVIF picture"},
            {"avif", "avifmif1miaf", "an AVIF picture"},
            {"msf1", "msf1avis", "an AVIF picture"},
            {"mif1", "mif1heicmiaf", "a HEIC picture (as an iPhone saves them)"},
            {"heic", "mif1heic", "a HEIC picture (as an iPhone saves them)"},
            {"mif1", "mif1", "a HEIF picture"},
        };
        for (String[] file : files) {
            byte[] brands = file[1].getBytes(StandardCharsets.ISO_8859_1);
            byte[] bytes = new byte[16 + brands.length + 8];
            bytes[3] = (byte) (16 + brands.length);
            System.arraycopy("ftyp".getBytes(StandardCharsets.ISO_8859_1), 0, bytes, 4, 4);
            System.arraycopy(file[0].getBytes(StandardCharsets.ISO_8859_1), 0, bytes, 8, 4);
            System.arraycopy(brands, 0, bytes, 16, brands.length);
            Path picture = Files.write(dir.resolve("page1.png"), bytes);
            assertEquals(picture + " is not a picture simpview can read (PNG, JPEG, GIF or BMP): it holds " + file[2]
                    + ", whatever its name says; save it as PNG",
                    assertThrows(CompareException.class, () -> Picture.read(picture)).getMessage(), file[1]);
        }
    }
}

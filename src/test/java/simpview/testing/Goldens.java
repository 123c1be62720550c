package simpview.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;

/**
 * Exact comparison against the golden PNGs in src/test/resources/golden.
 * On a mismatch the actual image and a diff (differing pixels red on a dimmed
 * copy of the golden) are written under build/golden-failures, and the
 * failure says how many pixels differ. `gradle updateGoldens` remakes them.
 */
public final class Goldens {

    private Goldens() {
    }

    public static Path projectDir() {
        return Path.of(System.getProperty("simpview.projectDir", "."));
    }

    public static Path goldenDir() {
        return projectDir().resolve("src/test/resources/golden");
    }

    public static void assertMatches(String name, BufferedImage actual) {
        Path goldenFile = goldenDir().resolve(name + ".png");
        if (!Files.exists(goldenFile)) {
            Path written = writeFailure(name + "-actual", actual);
            fail("no golden image " + goldenFile + "; the actual image is at " + written
                    + " (run `gradle updateGoldens` to accept it)");
        }
        BufferedImage golden = read(goldenFile);
        assertEquals(golden.getWidth() + "x" + golden.getHeight(), actual.getWidth() + "x" + actual.getHeight(),
                "size of " + name);
        int[] expected = Images.rgb(golden);
        int[] got = Images.rgb(actual);
        int differing = 0;
        for (int i = 0; i < expected.length; i++) {
            differing += expected[i] != got[i] ? 1 : 0;
        }
        if (differing > 0) {
            int w = golden.getWidth();
            BufferedImage diff = new BufferedImage(w, golden.getHeight(), BufferedImage.TYPE_INT_RGB);
            int[] marked = new int[expected.length];
            for (int i = 0; i < expected.length; i++) {
                marked[i] = expected[i] != got[i] ? 0xFF0000 : expected[i] >> 2 & 0x3F3F3F;
            }
            diff.setRGB(0, 0, w, golden.getHeight(), marked, 0, w);
            Path actualFile = writeFailure(name + "-actual", actual);
            Path diffFile = writeFailure(name + "-diff", diff);
            fail(differing + " pixels of " + name + " differ from " + goldenFile
                    + "; actual: " + actualFile + ", diff: " + diffFile);
        }
    }

    private static BufferedImage read(Path file) {
        try {
            return ImageIO.read(file.toFile());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static Path writeFailure(String name, BufferedImage image) {
        Path dir = projectDir().resolve("build/golden-failures");
        try {
            Files.createDirectories(dir);
            Path file = dir.resolve(name + ".png");
            ImageIO.write(image, "png", file.toFile());
            return file;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}

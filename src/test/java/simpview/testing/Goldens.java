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
        int differing = 0;
        BufferedImage diff = new BufferedImage(golden.getWidth(), golden.getHeight(), BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < golden.getHeight(); y++) {
            for (int x = 0; x < golden.getWidth(); x++) {
                int expected = golden.getRGB(x, y) & 0xFFFFFF;
                int got = actual.getRGB(x, y) & 0xFFFFFF;
                if (expected != got) {
                    differing++;
                    diff.setRGB(x, y, 0xFF0000);
                } else {
                    diff.setRGB(x, y, expected >> 2 & 0x3F3F3F);
                }
            }
        }
        if (differing > 0) {
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

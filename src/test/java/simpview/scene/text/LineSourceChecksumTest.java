package simpview.scene.text;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.scene.FileChecksum;

/** The checksum a source takes of the bytes it reads is the file's, each byte taken once. */
class LineSourceChecksumTest {

    @TempDir
    Path dir;

    /**
     * A source suspended deep in an include chain reopens its file at its
     * place and reads again the bytes it had buffered past it; the checksum
     * takes them once.
     */
    @Test
    void aSourceSuspendedAndReopenedTakesEachByteOnce() throws Exception {
        Path file = Files.writeString(dir.resolve("big.simp"), "line 1 2 3\n".repeat(20_000));
        LineSource source = LineSource.open(file).checksummed();
        for (int i = 0; i < 10; i++) {
            source.nextLine();
        }
        source.suspend();
        assertEquals(FileChecksum.NONE, source.checksumOfWhole(), "not read to its end yet");
        int lines = 10;
        while (source.nextLine()) {
            lines++;
        }
        source.close();
        assertEquals(20_000, lines);
        assertEquals(FileChecksum.of(file), source.checksumOfWhole());
    }
}

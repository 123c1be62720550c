package simpview.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A file's stamp: equal when size, time and key are, as a record's own equals has it. */
class FileStampTest {

    @Test
    void equalInEveryComponentOrNotEqual() {
        FileStamp stamp = new FileStamp(256, "2026-12-08T01:00:00.123456789Z", "(dev=fe01,ino=42)");
        FileStamp same = new FileStamp(256, new String("2026-12-08T01:00:00.123456789Z"),
                new String("(dev=fe01,ino=42)"));
        assertEquals(stamp, same);
        assertEquals(stamp.hashCode(), same.hashCode());
        assertNotEquals(stamp, new FileStamp(257, stamp.modified(), stamp.key()), "size");
        assertNotEquals(stamp, new FileStamp(256, "2026-12-08T01:00:00.123456788Z", stamp.key()), "time");
        assertNotEquals(stamp, new FileStamp(256, stamp.modified(), "(dev=fe01,ino=43)"), "key");
        assertNotEquals(stamp, null);
        assertNotEquals(stamp, (Object) "256");
        FileStamp nulls = new FileStamp(1, null, null);
        assertEquals(nulls, new FileStamp(1, null, null));
        assertEquals(nulls.hashCode(), new FileStamp(1, null, null).hashCode());
        assertNotEquals(nulls, new FileStamp(1, "", null));
    }

    @Test
    void aFileStampedTwiceUnchangedIsOneVersion(@TempDir Path dir) throws IOException {
        Path file = Files.writeString(dir.resolve("cube.simp"), "polygon (0,0,0) (1,0,0) (0,1,0)\n");
        FileStamp before = FileStamp.of(file);
        assertEquals(before, FileStamp.of(file));
        assertEquals(FileStamp.MISSING, FileStamp.of(dir.resolve("none.simp")));
        Files.writeString(file, "polygon (0,0,0) (1,0,0) (0,1,0) (1,1,0)\n");
        assertNotEquals(before, FileStamp.of(file), "a longer file");
        assertNotEquals(FileStamp.MISSING, FileStamp.of(file));
    }
}

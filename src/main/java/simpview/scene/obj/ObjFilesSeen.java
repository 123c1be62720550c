package simpview.scene.obj;

import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import simpview.scene.FileStamp;

/**
 * The .obj files one picture has drawn ({@link ObjLibrary#draw}): where each
 * name led and the attributes the file had when the picture first looked at
 * it, and which files' bytes the picture has read. A picture looks at a file
 * once, however many times it draws the model: finding a real path costs a
 * system call per folder, and A4's page-g draws one model 123 times, which
 * took its reading thread about 0.8 ms a picture in system calls (session
 * 16). So every draw of a model in one picture is the same model; a save
 * while the picture is drawn is seen by the next picture.
 *
 * <p>One picture's own: not shared between threads.
 */
public final class ObjFilesSeen {

    /**
     * A file as the picture first looked at it.
     *
     * @param real its real path, which names its kept model
     * @param attributes its attributes then
     * @param stamp its stamp then, made once a picture: making one formats the time
     * @param lookedAt when, in milliseconds since the epoch
     */
    record Look(Path real, BasicFileAttributes attributes, FileStamp stamp, long lookedAt) {
    }

    private final Map<Path, Look> looks = new HashMap<>();
    private final Set<Path> read = new HashSet<>();

    /** The look at {@code file} (as named) this picture took, or null. */
    Look look(Path file) {
        return looks.get(file);
    }

    void looked(Path file, Look look) {
        looks.put(file, look);
    }

    /** True when this picture has read the bytes of the file whose real path is {@code real}. */
    boolean hasRead(Path real) {
        return read.contains(real);
    }

    void reading(Path real) {
        read.add(real);
    }
}

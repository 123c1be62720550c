package simpview.scene.obj;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import simpview.scene.FileLook;

/**
 * The .obj files one picture has drawn ({@link ObjLibrary#draw}): where each
 * name led and the attributes the file had when the picture first looked at
 * it, and which files' bytes the picture has read. A picture looks at a file
 * once, however many times it draws the model: finding a real path costs a
 * system call per folder, and A4's page-g draws one model 123 times, which
 * took its reading thread about 1 ms a picture in system calls (session
 * 16). So every draw of a model in one picture is the same model; a save
 * while the picture is drawn is seen by the next picture.
 *
 * <p>One picture's own: not shared between threads.
 */
public final class ObjFilesSeen {

    private final Map<Path, FileLook> looks = new HashMap<>();
    private final Set<Path> read = new HashSet<>();

    /** The look at {@code file} (as named) this picture took, or null. */
    FileLook look(Path file) {
        return looks.get(file);
    }

    void looked(Path file, FileLook look) {
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

package simpview.scene.obj;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import simpview.scene.FileLook;
import simpview.scene.FileVersion;

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
 * <p>It also keeps what the picture drew of each file ({@link #asRead}): the
 * stamp it looked at and the checksum of the bytes the model was parsed
 * from, so that whoever watches the files for a save holds the file against
 * the very bytes drawn, not against the file as it is when it first looks.
 *
 * <p>One picture's own: not shared between threads.
 */
public final class ObjFilesSeen {

    private final Map<Path, FileLook> looks = new HashMap<>();
    private final Set<Path> read = new HashSet<>();
    /** By real path: the version of each file the picture drew its model from. */
    private final Map<Path, FileVersion> drawn = new HashMap<>();

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

    /** Notes that the picture drew {@code real}'s model from this version of it (the first one noted stays). */
    void drew(Path real, FileVersion version) {
        drawn.putIfAbsent(real, version);
    }

    /**
     * The version of {@code file} (as named) this picture drew its model
     * from: the stamp looked at before reading and the checksum of the bytes
     * parsed (also when the model was kept from an earlier picture: those it
     * was parsed from); null when none was drawn (the file could not be read,
     * or had an error).
     */
    public FileVersion asRead(Path file) {
        FileLook look = looks.get(file);
        return look == null ? null : drawn.get(look.real());
    }
}

package simpview.scene;

import java.nio.file.Path;

/**
 * A path as a person writes it: without its "." parts, which name no folder
 * of their own ("./bad.simp" is bad.simp, "pics/./page1.png" is
 * pics/page1.png), so a folder named "." or "./" lists its files by their
 * names. It leads to the same file, whatever links are on the way; ".."
 * is kept, since through a link to a folder it leads elsewhere than the
 * name before it suggests.
 */
public final class PlainPath {

    private PlainPath() {
    }

    /** {@code path} without its "." parts; "." alone stays ".". */
    public static Path of(Path path) {
        Path plain = path.getRoot();
        for (Path part : path) {
            if (!part.toString().equals(".")) {
                plain = plain == null ? part : plain.resolve(part);
            }
        }
        return plain == null ? path : plain;
    }
}

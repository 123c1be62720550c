package simpview.scene.simp;

import java.nio.file.Path;

/** A line of a scene file: where a command stands, or one step of an include chain. */
public record SourcePlace(Path file, int line) {

    /** "cube.simp:7". */
    @Override
    public String toString() {
        return file.getFileName() + ":" + line;
    }
}

package simpview.scene.simp;

import java.nio.file.Path;
import java.util.List;
import simpview.geometry.Matrix4;
import simpview.scene.FileVersion;
import simpview.stage.PrimitiveTrace;

/**
 * What a scene being drawn tells the outside, and how it can be stopped.
 * Called on the thread that draws the scene.
 */
public interface SceneMonitor {

    /** Nothing watches and nothing cancels. */
    SceneMonitor NONE = new SceneMonitor() { };

    /** Called now and then with the number of lines read so far, over all files. */
    default void linesRead(long lines) {
    }

    /**
     * Called with each {@link #linesRead}: the share of the top file's bytes
     * read so far, 0 to 1 (the fraction a progress bar shows; included files
     * are read in between).
     */
    default void topFileRead(double share) {
    }

    /**
     * Called when the scene is drawn by the lit rules (SPEC Part 2: its camera, lights and fog colour it), from its
     * first command or from the command that turned it lit, before it is drawn whole; perhaps more than once. A
     * depth-cued scene never calls it.
     */
    default void turnedLit() {
    }

    /** Polled now and then; true stops the scene with a {@link SceneCancelledException}. */
    default boolean cancelled() {
        return false;
    }

    /**
     * Once, when the scene ends however it ends: every file it read or looked
     * for, in the order met (what a window watches for a save; see
     * {@link ScenePipeline.Drawn#files}).
     */
    default void reached(List<Path> files) {
    }

    /**
     * Told just before {@link #reached}: the files as the scene read them, in
     * the same order: each one's stamp before it was read and, where known,
     * the checksum of the bytes read (see {@link FileStack#versionsAsRead}).
     */
    default void versionsAsRead(List<FileVersion> versions) {
    }

    /** Something worth telling that is not an error, e.g. a '{' never closed. */
    default void warning(String message) {
    }

    /**
     * What this monitor's reader calls {@code setting}, for the messages that
     * tell them to change it: the library's method unless the monitor is told
     * otherwise (the command line's monitors name its options).
     */
    default String nameOf(Setting setting) {
        return setting.method();
    }

    /** Who follows the scene's primitives one by one (the window's instruments), or null: nobody, at no cost. */
    default PrimitiveTrace trace() {
        return null;
    }

    /**
     * A turn of the view (the window's orbit), in camera space: a point goes
     * to the camera by turn * W * CTM (W the identity for a depth-cued scene,
     * so the world turns before the depth cue; for a lit scene the camera
     * moves about the world); null for none.
     */
    default Matrix4 viewTurn() {
        return null;
    }

    /**
     * Once a lit scene that was traced is drawn: the centre of the
     * camera-space box around what its view showed (x, y, z), what the
     * window's orbit turns about. Not called when nothing was in view.
     */
    default void shownCentre(double[] xyz) {
    }

    /** The inspector's replay: what it sets into the drawing (see {@link DrawingWatch}); null, the default, for none. */
    default DrawingWatch watch() {
        return null;
    }
}

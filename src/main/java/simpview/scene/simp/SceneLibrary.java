package simpview.scene.simp;

import simpview.scene.obj.ObjLibrary;

/**
 * Every file scenes read, kept from picture to picture while it is
 * unchanged: the small .simp files' commands ({@link SimpLibrary}) and the
 * .obj models ({@link ObjLibrary}). One belongs to whoever draws picture
 * after picture (a window's render thread, a page renderer, a benchmark), and
 * is handed to {@link ScenePipeline} in its options; a redraw of an
 * unchanged scene then neither reads nor parses its files again. Thread
 * safe, as both libraries are.
 */
public final class SceneLibrary {

    private final SimpLibrary scenes;
    private final ObjLibrary models;

    /** Empty libraries of the default budgets. */
    public SceneLibrary() {
        this(new SimpLibrary(), new ObjLibrary());
    }

    public SceneLibrary(SimpLibrary scenes, ObjLibrary models) {
        this.scenes = scenes;
        this.models = models;
    }

    /** The small .simp files read so far. */
    public SimpLibrary scenes() {
        return scenes;
    }

    /** The .obj models drawn so far. */
    public ObjLibrary models() {
        return models;
    }

    /** Drops everything kept. */
    public void clear() {
        scenes.clear();
        models.clear();
    }
}

package simpview.scene.obj;

import simpview.stage.ObjFace;

import simpview.scene.SceneException;

/**
 * Takes the faces of an .obj model one at a time, in file order, as they are
 * read (or replayed from a kept {@link ObjModel}).
 *
 * <p>The {@link ObjFace} handed over is one reused view: it is valid only
 * during the call and changes at the next face, so a sink copies out what it
 * needs and never keeps the face itself.
 */
public interface ObjSink {

    /** One face of three or more counter-clockwise vertices. */
    void face(ObjFace face) throws SceneException;

    /**
     * Whether the sink reads which earlier face shares each edge of a face
     * ({@link ObjFace#edgeFirstFace}): a kept model then works that out once
     * and gives it with every replay. A face streamed as it is read knows
     * none.
     */
    default boolean readsEdges() {
        return false;
    }

    /**
     * Called now and then (every {@link ObjReader#PROGRESS_LINES} lines read,
     * or as many faces replayed) with the obj line reached, so a sink can show
     * progress or stop a long model by throwing.
     */
    default void progress(int line) throws SceneException {
    }
}

package simpview.scene.simp;

/**
 * Thrown by {@link SimpClient} when a scene being drawn depth-cued meets a
 * command of the lit rules and cannot simply go on lit: it has drawn a
 * primitive already (the scene is drawn again from the start by the lit
 * rules), or its caller asked for depth-cue colours (the scene is not drawn
 * at all). {@link ScenePipeline} catches it; it never reaches a user.
 */
final class SceneTurnsLit extends RuntimeException {

    private static final long serialVersionUID = 1L;

    /** Where the first lit command stands, "pageA.simp:3 camera". */
    final String because;

    SceneTurnsLit(String because) {
        super(because, null, false, false);
        this.because = because;
    }
}

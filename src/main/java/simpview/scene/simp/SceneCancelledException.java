package simpview.scene.simp;

/** Thrown out of a scene when its monitor asked to stop. */
public final class SceneCancelledException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    public SceneCancelledException() {
        super("scene cancelled");
    }
}

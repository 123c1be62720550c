package simpview.scene.simp;

/**
 * A setting that a message tells its reader to change, with the name the
 * reader changes it by: a Java caller by a method of the library, a user of
 * the command line (and of the window it opens) by an option. Whoever draws
 * says which names its reader knows, through its monitor
 * ({@link SceneMonitor#nameOf}); the library's own are the default.
 */
public enum Setting {

    /** The folder of the course's scene files, page6.simp to page8.simp. */
    COURSE_FOLDER("PageContext.withSimpDir(folder)", "--simp-dir DIR"),

    /** A depth-cued scene drawn in its vertices' own colours, without the cue. */
    OWN_COLOURS("ScenePipeline.Options.withOwnColours(true) (PageContext.withOwnColours(true) for a page)",
            "--own-colors (render, compare, check, inspect), or C in the window");

    private final String method;
    private final String option;

    Setting(String method, String option) {
        this.method = method;
        this.option = option;
    }

    /** Its name for a Java caller: the library's method that sets it. */
    public String method() {
        return method;
    }

    /** Its name on the command line: the option, and where the window has one, its key. */
    public String option() {
        return option;
    }
}

package simpview.app;

/**
 * How the window asks for a picture to be drawn, beyond which one.
 *
 * @param ownColours scenes in their vertices' own colours instead of the depth cue
 * @param record whether to record who drew each pixel (the inspector); off on the command line
 */
record DrawSettings(boolean ownColours, boolean record) {

    /** The picture as the pages and the command line draw it. */
    static final DrawSettings PLAIN = new DrawSettings(false, false);

    DrawSettings withOwnColours(boolean own) {
        return new DrawSettings(own, record);
    }
}

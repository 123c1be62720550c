package simpview.inspect;

/** What became of one write attempted at a pixel, in the words of the JSON and the text. */
public enum Outcome {
    /** Passed every test and is what the pixel showed after it. */
    WRITTEN("written"),
    /** Lost the depth test: the stored depth was as near or nearer. */
    DEPTH_FAILED("depth-failed"),
    /** Dropped by the scissor: outside the depth range of the view. */
    SCISSORED("scissored"),
    /** The primitive was clipped away where it would have covered the pixel. */
    CLIPPED("clipped"),
    /** The primitive was culled whole (every vertex outside one plane of the view). */
    CULLED("culled"),
    /** Mixed with what was there by a coverage (antialiased or ghost writes). */
    BLENDED("blended");

    private final String word;

    Outcome(String word) {
        this.word = word;
    }

    public String word() {
        return word;
    }
}

package simpview.inspect;

import java.nio.file.Path;
import java.util.Objects;
import simpview.pages.Page;
import simpview.pages.PageContext;
import simpview.pages.Assignment2;
import simpview.pages.ScenePage;
import simpview.scene.SceneException;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.Rgb;

/**
 * A scene to replay, drawn as the program draws it: by the rules its
 * commands call for (lit, or depth-cued from a near to a far colour), or
 * always depth-cued (the pages), or in its vertices' own colours.
 */
public record InspectedScene(Path file, Rgb near, Rgb far, boolean ownColours, ScenePipeline.Rules rules) {

    /** A scene file drawn as {@code render --scene} draws it: by its own rules, depth-cued white to black. */
    public static InspectedScene of(Path file) {
        Objects.requireNonNull(file, "file must not be null");
        return new InspectedScene(file, Rgb.WHITE, Rgb.BLACK, false, ScenePipeline.Rules.BY_COMMANDS);
    }

    /**
     * A scene file depth-cued from near to far, as {@code render --scene
     * --near-color --far-color} draws it: a lit scene cannot take the
     * colours, and its replay draws nothing (the report says so).
     */
    public static InspectedScene cued(Path file, Rgb near, Rgb far) {
        Objects.requireNonNull(file, "file must not be null");
        Objects.requireNonNull(near, "near must not be null");
        Objects.requireNonNull(far, "far must not be null");
        return new InspectedScene(file, near, far, false, ScenePipeline.Rules.DEPTH_CUED_OR_NOTHING);
    }

    /** A depth-cued scene in its vertices' own colours (white where none), without the cue. */
    public static InspectedScene ownColours(Path file) {
        Objects.requireNonNull(file, "file must not be null");
        return new InspectedScene(file, Rgb.WHITE, Rgb.BLACK, true, ScenePipeline.Rules.BY_COMMANDS);
    }

    /**
     * Page n (4 to 8) as the pages draw it: depth-cued, whatever its files hold.
     *
     * @throws IllegalArgumentException for a page that is not a scene file (1 to 3), or no page
     * @throws SceneException when the page's scene file is missing
     */
    public static InspectedScene page(int number, PageContext context) throws SceneException {
        Objects.requireNonNull(context, "context must not be null");
        if (number < 1 || number > Assignment2.COUNT) {
            throw new IllegalArgumentException("InspectedScene.page takes pages 4 to " + Assignment2.COUNT
                    + " (the pages drawn from scene files), not " + number);
        }
        Page page = Assignment2.page(number);
        if (!(page instanceof ScenePage scene)) {
            throw new IllegalArgumentException("page " + number + " (" + page.title()
                    + ") is drawn by the program, not from a scene file: inspect reads pages 4 to 8 and scenes");
        }
        Path file = scene.existingFile(context);
        return new InspectedScene(file, scene.near(), Rgb.BLACK, context.ownColours(), ScenePipeline.Rules.DEPTH_CUED);
    }

    /**
     * Whether {@code error} means that nothing of this scene could be read
     * (its own file, at no line: not there, or not text), rather than that it
     * stops part of the way, where the page shows what was drawn before the
     * error and a replay goes as far.
     */
    boolean nothingRead(SceneException error) {
        return error.line() == 0 && error.file() != null && error.file().equals(file);
    }

    /** The same scene in its own colours, or depth-cued again. */
    public InspectedScene withOwnColours(boolean own) {
        return new InspectedScene(file, near, far, own, rules);
    }
}

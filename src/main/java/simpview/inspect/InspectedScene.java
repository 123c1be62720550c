package simpview.inspect;

import java.nio.file.Files;
import java.nio.file.Path;
import simpview.pages.Page;
import simpview.pages.PageContext;
import simpview.pages.Pages;
import simpview.pages.ScenePage;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneRules;
import simpview.surface.Rgb;

/**
 * A scene to replay, with the rules it is drawn by: lit, or depth-cued from
 * a near to a far colour (or, with a null near colour, in its vertices' own
 * colours).
 */
public record InspectedScene(Path file, boolean lit, Rgb near, Rgb far) {

    /** A scene file drawn as {@code render --scene} draws it: by its own rules, depth-cued white to black. */
    public static InspectedScene of(Path file) {
        return of(file, Rgb.WHITE, Rgb.BLACK);
    }

    /** A scene file by its own rules; depth-cued from near to far when it is not lit. */
    public static InspectedScene of(Path file, Rgb near, Rgb far) {
        boolean lit = SceneRules.of(file).lit();
        return new InspectedScene(file, lit, lit ? null : near, lit ? null : far);
    }

    /**
     * Page n (4 to 8) as the pages draw it.
     *
     * @throws IllegalArgumentException for a page that is not a scene file (1 to 3), or no page
     * @throws SceneException when the page's scene file is missing
     */
    public static InspectedScene page(int number, PageContext context) throws SceneException {
        if (number < 1 || number > Pages.COUNT) {
            throw new IllegalArgumentException("--page must be 1 to " + Pages.COUNT + ", not " + number);
        }
        Page page = Pages.page(number);
        if (!(page instanceof ScenePage scene)) {
            throw new IllegalArgumentException("page " + number + " (" + page.title()
                    + ") is drawn by the program, not from a scene file: inspect reads pages 4 to 8 and scenes");
        }
        Path file = scene.file(context);
        if (!Files.isRegularFile(file)) {
            throw new SceneException(file, 0, 0, "", scene.fileName() + " was not found in "
                    + file.toAbsolutePath().normalize().getParent());
        }
        return new InspectedScene(file, false, scene.near(), Rgb.BLACK);
    }
}

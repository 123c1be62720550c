package simpview.pages;

import java.util.List;
import simpview.scene.SceneException;
import simpview.surface.PageCanvas;

/** One of the eight pages. Draws onto a canvas that has just been cleared. */
public interface Page {

    /** A short name for the title bar, e.g. "Wireframe mesh". */
    String title();

    /** True for the pages whose picture depends on the seed. */
    default boolean usesSeed() {
        return false;
    }

    /**
     * What each primitive the page draws is, in drawing order, for a page
     * that is not a scene file (a scene's come from its lines); empty when
     * the page does not say.
     */
    default List<String> primitiveNames(PageContext context) {
        return List.of();
    }

    /**
     * Whether drawing the page records which primitive wrote each pixel (when
     * a provenance record is kept): false for a page drawn straight onto the
     * panel, whose pixels would all read as the background's.
     */
    default boolean keepsOwners() {
        return true;
    }

    /**
     * The lines and triangles the page makes itself, panel by panel and in
     * drawing order within each panel, as given to its drawers; empty for a
     * page that draws a scene file, whose primitives are the file's.
     */
    List<ListedPrimitive> primitives(PageContext context);

    /**
     * Draws the page. On a scene error what was drawn before it stays on the
     * canvas and the exception says what went wrong.
     */
    void draw(PageCanvas canvas, PageContext context) throws SceneException;
}

package simpview.cli;

import simpview.scene.simp.SceneDrawer;
import simpview.scene.simp.SceneSheet;

import java.io.PrintWriter;
import java.nio.file.Path;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneMonitor;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;

/**
 * The one way the command line draws a picture, a page or any scene as a
 * page: {@code render} and {@code compare} both draw through here, on one
 * canvas that is reused (the canvas returned is overwritten by the next call).
 */
public final class PageDrawing {

    private final PageRenderer renderer = new PageRenderer();
    private final SceneMonitor monitor;

    PageDrawing(SceneMonitor monitor) {
        this.monitor = monitor;
    }

    /** Page n; on a scene error the canvas keeps what was drawn before it and the error is thrown on. */
    PageCanvas page(int number, PageContext context) throws SceneException {
        return renderer.render(number, context.withMonitor(monitor));
    }

    /** A scene as a whole page, depth-cued from near (default white) to far (default black). */
    PageCanvas scene(Path file, Rgb near, Rgb far) throws SceneException {
        return scene(file, near, far, false);
    }

    /** The same, or with {@code ownColours} in the vertices' own colours without the depth cue. */
    PageCanvas scene(Path file, Rgb near, Rgb far, boolean ownColours) throws SceneException {
        SceneSheet sheet = new SceneSheet(file, near == null ? Rgb.WHITE : near, far == null ? Rgb.BLACK : far);
        sheet.drawOn(renderer.canvas(), monitor, SceneDrawer.SIMP, ownColours);
        return renderer.canvas();
    }

    /** The pages' context from the command line's options (null where not given), warnings to {@code monitor}. */
    static PageContext context(Long seed, Path simpDir, SceneMonitor monitor) {
        PageContext context = PageContext.defaults().withMonitor(monitor);
        if (seed != null) {
            context = context.withSeed(seed);
        }
        return simpDir == null ? context : context.withSimpDir(simpDir);
    }

    /** A monitor that prints each warning as a "warning: ..." line on {@code err}. */
    static SceneMonitor warningsTo(PrintWriter err) {
        return new SceneMonitor() {
            @Override
            public void warning(String message) {
                err.println("warning: " + message);
            }
        };
    }
}

package simpview.window;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import simpview.pages.PageContext;

/**
 * How the window starts.
 *
 * @param seed seed of the random pages
 * @param simpDir where the course's page6.simp to page8.simp are looked for
 * @param scene a scene to open at start as an extra view (stepping goes on to the pages)
 * @param sceneList scenes that are the window's first pages, before the eight; empty for none
 */
public record WindowOptions(long seed, Path simpDir, Optional<Path> scene, List<Path> sceneList) {

    public WindowOptions {
        sceneList = List.copyOf(sceneList);
    }

    /** The eight pages, and perhaps a scene to open at start. */
    public WindowOptions(long seed, Path simpDir, Optional<Path> scene) {
        this(seed, simpDir, scene, List.of());
    }

    static WindowOptions defaults() {
        return new WindowOptions(PageContext.DEFAULT_SEED, PageContext.defaultSimpDir(), Optional.empty());
    }

    WindowOptions withSeed(long newSeed) {
        return new WindowOptions(newSeed, simpDir, scene, sceneList);
    }

    PageContext pageContext() {
        return PageContext.defaults().withSeed(seed).withSimpDir(simpDir);
    }
}

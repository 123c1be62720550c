package simpview.app;

import java.nio.file.Path;
import java.util.Optional;
import simpview.pages.PageContext;

/**
 * How the window starts.
 *
 * @param seed seed of the random pages
 * @param simpDir where the course's page6.simp to page8.simp are looked for
 * @param scene a scene to open once the first page is up
 */
record WindowOptions(long seed, Path simpDir, Optional<Path> scene) {

    static WindowOptions defaults() {
        return new WindowOptions(PageContext.DEFAULT_SEED, PageContext.defaultSimpDir(), Optional.empty());
    }

    PageContext pageContext() {
        return PageContext.defaults().withSeed(seed).withSimpDir(simpDir);
    }
}

package simpview.window;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import simpview.pages.A1Rule;
import simpview.pages.PageContext;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.Setting;

/**
 * How the window starts.
 *
 * @param seed seed of the random pages
 * @param simpDir where the course's page6.simp to page8.simp are looked for
 * @param scene a scene to open at start as an extra view (stepping goes on to the pages)
 * @param sceneList scenes that are the window's first pages, before the eight; empty for none
 * @param ownScenes where the project's own scenes (pages 4 and 5) are
 * @param threads how many threads draw each picture: the window's render thread and its helpers
 * @param a1Rule the first assignment's rule for its Bresenham panels and fills
 */
public record WindowOptions(long seed, Path simpDir, Optional<Path> scene, List<Path> sceneList, Path ownScenes,
        int threads, A1Rule a1Rule) {

    /** Warns nobody; names each setting as the command line that opened the window does, by its option. */
    private static final SceneMonitor NAMING_OPTIONS = new SceneMonitor() {
        @Override
        public String nameOf(Setting setting) {
            return setting.option();
        }
    };

    public WindowOptions {
        sceneList = List.copyOf(sceneList);
        if (threads < 1) {
            throw new IllegalArgumentException("threads must be at least 1, got " + threads);
        }
    }

    /** SPEC's rule for the first assignment. */
    public WindowOptions(long seed, Path simpDir, Optional<Path> scene, List<Path> sceneList, Path ownScenes,
            int threads) {
        this(seed, simpDir, scene, sceneList, ownScenes, threads, A1Rule.SPEC);
    }

    /** Drawn by one thread per processor. */
    public WindowOptions(long seed, Path simpDir, Optional<Path> scene, List<Path> sceneList, Path ownScenes) {
        this(seed, simpDir, scene, sceneList, ownScenes, Runtime.getRuntime().availableProcessors());
    }

    /** Started from the repository's folder: the project's scenes in simp/. */
    public WindowOptions(long seed, Path simpDir, Optional<Path> scene, List<Path> sceneList) {
        this(seed, simpDir, scene, sceneList, PageContext.PROJECT_SCENES);
    }

    /** The eight pages, and perhaps a scene to open at start. */
    public WindowOptions(long seed, Path simpDir, Optional<Path> scene) {
        this(seed, simpDir, scene, List.of());
    }

    static WindowOptions defaults() {
        return new WindowOptions(PageContext.DEFAULT_SEED, PageContext.PROJECT_SCENES, Optional.empty());
    }

    WindowOptions withSeed(long newSeed) {
        return new WindowOptions(newSeed, simpDir, scene, sceneList, ownScenes, threads, a1Rule);
    }

    WindowOptions withA1Rule(A1Rule rule) {
        return new WindowOptions(seed, simpDir, scene, sceneList, ownScenes, threads, rule);
    }

    /** The pages' context; its messages name settings as the command line that opened the window does. */
    PageContext pageContext() {
        return PageContext.of(ownScenes).withSeed(seed).withSimpDir(simpDir).withA1Rule(a1Rule)
                .withMonitor(NAMING_OPTIONS);
    }
}

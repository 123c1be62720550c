package simpview.pages;

import java.nio.file.Path;
import java.util.Objects;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;

/**
 * What a page needs besides its canvas.
 *
 * @param seed the seed of the random pages (1 to 3)
 * @param simpDir where page6.simp to page8.simp are looked for
 * @param ownSimpDir where the project's own scenes (page 4 and 5) live
 * @param monitor progress, warnings and cancelling of scene pages
 * @param ownColours draw the scene pages with their vertices' own colours, without the depth cue
 *     (SPEC: "without depth cueing, that colour is used"); the pages themselves are cued
 * @param a1Rule the rule of the first assignment's Bresenham panels and fills
 * @param library the scene pages' files, kept from picture to picture while unchanged: give a context
 *     made afresh for each picture the library of whoever draws them ({@link #withLibrary})
 */
public record PageContext(long seed, Path simpDir, Path ownSimpDir, SceneMonitor monitor, boolean ownColours,
        A1Rule a1Rule, SceneLibrary library) {

    /** The seed of the random pages unless told otherwise ({@code --seed}). */
    public static final long DEFAULT_SEED = 361;

    /**
     * The project's own scenes as seen from the repository's folder (where
     * the tests, the benchmarks and {@code gradle run} work). An installed or
     * packaged simpview is told its own folder by its entry point instead.
     */
    public static final Path PROJECT_SCENES = Path.of("simp");

    /** The pages as they are meant to look: depth-cued, from a library of their own. */
    public PageContext(long seed, Path simpDir, Path ownSimpDir, SceneMonitor monitor) {
        this(seed, simpDir, ownSimpDir, monitor, false, A1Rule.SPEC, new SceneLibrary());
    }

    /** The defaults with the project's scenes in {@link #PROJECT_SCENES}. */
    public static PageContext defaults() {
        return of(PROJECT_SCENES);
    }

    /** The defaults with the project's own scenes (and, until told otherwise, the course's) in {@code ownScenes}. */
    public static PageContext of(Path ownScenes) {
        Objects.requireNonNull(ownScenes, "ownScenes must not be null");
        return new PageContext(DEFAULT_SEED, ownScenes, ownScenes, SceneMonitor.NONE);
    }

    /** The same, the random pages (1 to 3, and the first assignment's 3 to 5) seeded with {@code newSeed}: {@code --seed}. */
    public PageContext withSeed(long newSeed) {
        return new PageContext(newSeed, simpDir, ownSimpDir, monitor, ownColours, a1Rule, library);
    }

    /** The same, page6.simp to page8.simp read from {@code dir}, the course's folder: {@code --simp-dir}. */
    public PageContext withSimpDir(Path dir) {
        Objects.requireNonNull(dir, "dir must not be null");
        return new PageContext(seed, dir, ownSimpDir, monitor, ownColours, a1Rule, library);
    }

    /** The same, the scene pages' progress and warnings told to {@code newMonitor}. */
    public PageContext withMonitor(SceneMonitor newMonitor) {
        Objects.requireNonNull(newMonitor, "newMonitor must not be null");
        return new PageContext(seed, simpDir, ownSimpDir, newMonitor, ownColours, a1Rule, library);
    }

    /** The same, the first assignment's Bresenham panels and fills drawn by {@code rule}: {@code --a1-rule}. */
    public PageContext withA1Rule(A1Rule rule) {
        Objects.requireNonNull(rule, "rule must not be null");
        return new PageContext(seed, simpDir, ownSimpDir, monitor, ownColours, rule, library);
    }

    /** The same, the scene pages in their vertices' own colours, without the depth cue, when {@code own}: {@code --own-colors}. */
    public PageContext withOwnColours(boolean own) {
        return new PageContext(seed, simpDir, ownSimpDir, monitor, own, a1Rule, library);
    }

    /** The same, the scene pages' files kept in {@code kept}, to be read again only when changed. */
    public PageContext withLibrary(SceneLibrary kept) {
        Objects.requireNonNull(kept, "kept must not be null");
        return new PageContext(seed, simpDir, ownSimpDir, monitor, ownColours, a1Rule, kept);
    }
}

package simpview.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Optional;
import simpview.pages.PageContext;
import simpview.pages.UnpackedScenes;

/**
 * Where the project's own scenes are when nobody said: a simpview started
 * from simpview.jar carries them inside the jar, under simp/, and unpacks
 * them ({@link UnpackedScenes}) into a fresh temporary folder, deleted when
 * simpview exits, so that scenes that include each other, the file dialog
 * and error messages all see ordinary files. The start scripts and
 * {@code gradle run} name their folder with -Dsimpview.simpDir, which wins;
 * the entry point asks here once and hands the folder on as a value
 * ({@link SimpviewCommand}).
 */
public final class OwnScenes {

    /** How a launcher (the start scripts, {@code gradle run}) names the scenes' folder; read only here. */
    static final String LAUNCHER_PROPERTY = "simpview.simpDir";

    private OwnScenes() {
    }

    /**
     * Where the project's own scenes are: the folder the launcher named,
     * else the scenes packed in the running jar (unpacked, and deleted when
     * the program ends), else simp/ in the working directory (a run from the
     * repository's folder, or an IDE's).
     */
    static Path folder() {
        String named = System.getProperty(LAUNCHER_PROPERTY);
        if (named != null) {
            return Path.of(named);
        }
        Optional<Path> jar = UnpackedScenes.simpviewJar();
        if (jar.isEmpty()) {
            return PageContext.PROJECT_SCENES;
        }
        try {
            UnpackedScenes unpacked = UnpackedScenes.from(jar.get());
            // The entry point owns the process: its scenes go with it, however it ends (the window's last close).
            Runtime.getRuntime().addShutdownHook(new Thread(() -> deleteQuietly(unpacked), "simpview-scenes-cleanup"));
            return unpacked.folder();
        } catch (IOException e) {
            System.err.println("simpview: " + e.getMessage() + "; looking for the scenes in "
                    + PageContext.PROJECT_SCENES.toAbsolutePath());
            return PageContext.PROJECT_SCENES;
        }
    }

    private static void deleteQuietly(UnpackedScenes unpacked) {
        try {
            unpacked.close();
        } catch (IOException e) {
            // left in the system's temporary folder, as a crash would leave it
        }
    }
}

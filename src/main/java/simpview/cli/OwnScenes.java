package simpview.cli;

import java.io.IOException;
import java.io.InputStream;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.CodeSource;
import java.util.Enumeration;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;
import simpview.pages.PageContext;

/**
 * Where the project's own scenes are when nobody said: a simpview started
 * from simpview.jar carries them inside the jar, under simp/. They are
 * unpacked into a fresh temporary folder (removed when simpview exits), so
 * that scenes that include each other, the file dialog and error messages
 * all see ordinary files. The start scripts and {@code gradle run} name
 * their folder with -Dsimpview.simpDir, which wins; the entry point asks
 * here once and hands the folder on as a value ({@link SimpviewCommand}).
 */
public final class OwnScenes {

    /** How a launcher (the start scripts, {@code gradle run}) names the scenes' folder; read only here. */
    static final String LAUNCHER_PROPERTY = "simpview.simpDir";
    private static final String FOLDER = "simp/";

    private OwnScenes() {
    }

    /**
     * Where the project's own scenes are: the folder the launcher named,
     * else the scenes packed in the running jar (unpacked), else simp/ in the
     * working directory (a run from the repository's folder, or an IDE's).
     */
    static Path folder() {
        String named = System.getProperty(LAUNCHER_PROPERTY);
        if (named != null) {
            return Path.of(named);
        }
        Path jar = runningJar();
        if (jar == null) {
            return PageContext.PROJECT_SCENES;
        }
        try {
            Path dir = unpack(jar);
            return dir != null ? dir : PageContext.PROJECT_SCENES;
        } catch (IOException e) {
            System.err.println("simpview: cannot unpack the scenes of " + jar + " (" + e.getMessage()
                    + "); looking for them in " + PageContext.PROJECT_SCENES.toAbsolutePath());
            return PageContext.PROJECT_SCENES;
        }
    }

    private static Path runningJar() {
        CodeSource source = OwnScenes.class.getProtectionDomain().getCodeSource();
        if (source == null || source.getLocation() == null) {
            return null;
        }
        try {
            Path path = Path.of(source.getLocation().toURI());
            return Files.isRegularFile(path) && path.toString().endsWith(".jar") ? path : null;
        } catch (URISyntaxException | IllegalArgumentException e) {
            return null;
        }
    }

    /** The scenes of the jar in a new temporary folder, or null when the jar has none. */
    static Path unpack(Path jar) throws IOException {
        try (JarFile file = new JarFile(jar.toFile())) {
            if (file.getEntry(FOLDER) == null && !hasScenes(file)) {
                return null;
            }
            Path dir = Files.createTempDirectory("simpview-scenes");
            dir.toFile().deleteOnExit();
            Enumeration<JarEntry> entries = file.entries();
            while (entries.hasMoreElements()) {
                JarEntry entry = entries.nextElement();
                String name = entry.getName();
                if (name.startsWith(FOLDER) && !entry.isDirectory() && name.indexOf('/', FOLDER.length()) < 0) {
                    Path target = dir.resolve(name.substring(FOLDER.length()));
                    try (InputStream in = file.getInputStream(entry)) {
                        Files.copy(in, target);
                    }
                    target.toFile().deleteOnExit();
                }
            }
            return dir;
        }
    }

    private static boolean hasScenes(JarFile file) {
        return file.stream().anyMatch(e -> e.getName().startsWith(FOLDER));
    }
}

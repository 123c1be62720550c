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
 * their folder with -Dsimpview.simpDir, which always wins.
 */
public final class OwnScenes {

    static final String PROPERTY = "simpview.simpDir";
    private static final String FOLDER = "simp/";

    private OwnScenes() {
    }

    /** Sets -Dsimpview.simpDir to the unpacked scenes when running from a jar that has them. */
    static void locate() {
        if (System.getProperty(PROPERTY) != null) {
            return;
        }
        Path jar = runningJar();
        if (jar == null) {
            return;
        }
        try {
            Path dir = unpack(jar);
            if (dir != null) {
                System.setProperty(PROPERTY, dir.toString());
            }
        } catch (IOException e) {
            System.err.println("simpview: cannot unpack the scenes of " + jar + " (" + e.getMessage()
                    + "); looking for them in " + PageContext.defaultSimpDir().toAbsolutePath());
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

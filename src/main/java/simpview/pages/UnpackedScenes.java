package simpview.pages;

import java.io.IOException;
import java.io.InputStream;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.security.CodeSource;
import java.util.Comparator;
import java.util.Enumeration;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;
import java.util.stream.Stream;
import java.util.zip.ZipException;
import simpview.scene.FileProblem;

/**
 * The project's own scenes (page4.simp, page5.simp and the shapes they
 * include) as simpview.jar carries them under simp/, unpacked into a new
 * temporary folder of their own, so that scenes that include each other and
 * error messages all see ordinary files. The folder belongs to whoever
 * unpacked it: {@link #close} deletes it and every file in it. Each call
 * unpacks afresh; nothing is kept between calls.
 *
 * <p>A Java program with simpview.jar on its classpath draws page 4 with
 * <pre>{@code
 * try (UnpackedScenes own = UnpackedScenes.fromSimpviewJar()) {
 *     BufferedImage page = new PageRenderer().renderImage(4, own.context());
 * }
 * }</pre>
 */
public final class UnpackedScenes implements AutoCloseable {

    /** The folder of the scenes inside the jar. */
    private static final String FOLDER = "simp/";
    /** The start of the temporary folder's name. */
    private static final String PREFIX = "simpview-scenes";

    private final Path folder;

    private UnpackedScenes(Path folder) {
        this.folder = folder;
    }

    /**
     * The scenes of the simpview.jar this class was loaded from, unpacked.
     *
     * @throws IOException when simpview was not loaded from a jar that
     *     carries its scenes (its classes in a folder, or the jar
     *     {@code installDist} makes, whose scenes are beside it in simp/: name
     *     that folder with {@link PageContext#of}), or when they cannot be
     *     unpacked; the message says which
     */
    public static UnpackedScenes fromSimpviewJar() throws IOException {
        Path loadedFrom = loadedFrom();
        if (loadedFrom == null || !isJar(loadedFrom)) {
            throw new IOException("simpview was not loaded from simpview.jar"
                    + (loadedFrom == null ? "" : " but from " + loadedFrom)
                    + ", so it carries no scenes: name the folder of its scenes (simp/ in the repository) with "
                    + "PageContext.of(folder)");
        }
        return from(loadedFrom);
    }

    /**
     * The jar simpview was loaded from, when it carries the project's
     * scenes: what {@link #fromSimpviewJar} unpacks. Looked at without
     * unpacking anything.
     */
    public static Optional<Path> simpviewJar() {
        Path loadedFrom = loadedFrom();
        if (loadedFrom == null || !isJar(loadedFrom)) {
            return Optional.empty();
        }
        try (JarFile jar = new JarFile(loadedFrom.toFile())) {
            return hasScenes(jar) ? Optional.of(loadedFrom) : Optional.empty();
        } catch (IOException e) {
            return Optional.empty();
        }
    }

    /**
     * The scenes {@code jar} carries under simp/, unpacked into a new folder
     * of the system's temporary folder.
     *
     * @throws IOException when {@code jar} cannot be read, carries no
     *     scenes, or they cannot be written; nothing is left behind
     */
    public static UnpackedScenes from(Path jar) throws IOException {
        Objects.requireNonNull(jar, "jar must not be null");
        return into(jar, null);
    }

    /**
     * As {@link #from(Path)}, the new folder made in {@code parent} (null:
     * the system's temporary folder).
     */
    static UnpackedScenes into(Path jar, Path parent) throws IOException {
        try (JarFile file = open(jar)) {
            if (!hasScenes(file)) {
                throw new IOException(jar + " carries no scenes (no " + FOLDER + " in it)");
            }
            Path dir = parent == null ? Files.createTempDirectory(PREFIX) : Files.createTempDirectory(parent, PREFIX);
            try {
                Enumeration<JarEntry> entries = file.entries();
                while (entries.hasMoreElements()) {
                    JarEntry entry = entries.nextElement();
                    String name = entry.getName();
                    if (name.startsWith(FOLDER) && !entry.isDirectory() && name.indexOf('/', FOLDER.length()) < 0) {
                        Path target = dir.resolve(name.substring(FOLDER.length()));
                        try (InputStream in = file.getInputStream(entry)) {
                            Files.copy(in, target);
                        }
                    }
                }
            } catch (IOException e) {
                try {
                    new UnpackedScenes(dir).close();
                } catch (IOException left) {
                    e.addSuppressed(left);
                }
                throw new IOException("cannot unpack the scenes of " + jar + " into " + dir + ": " + e.getMessage(), e);
            }
            return new UnpackedScenes(dir);
        }
    }

    /** {@code jar} opened, or an IOException that names it and says why not (a file that is no zip archive). */
    private static JarFile open(Path jar) throws IOException {
        try {
            return new JarFile(jar.toFile());
        } catch (ZipException e) {
            throw new IOException(jar + " cannot be read as a jar: it is no zip archive (" + e.getMessage() + ")", e);
        } catch (IOException e) {
            throw new IOException(jar + " cannot be read: " + FileProblem.of(jar, e), e);
        }
    }

    /** The folder the scenes are in, until {@link #close}. */
    public Path folder() {
        return folder;
    }

    /** The pages' defaults with their own scenes (and, until told otherwise, the course's) here: {@link PageContext#of}. */
    public PageContext context() {
        return PageContext.of(folder);
    }

    /**
     * Deletes the folder and everything in it: the scenes unpacked, and
     * whatever else was put there since.
     *
     * @throws IOException when a file cannot be deleted, saying which
     */
    @Override
    public void close() throws IOException {
        if (!Files.exists(folder, LinkOption.NOFOLLOW_LINKS)) {
            return;
        }
        List<Path> inside;
        try (Stream<Path> walk = Files.walk(folder)) {
            inside = walk.sorted(Comparator.reverseOrder()).toList();
        }
        for (Path path : inside) {
            Files.deleteIfExists(path);
        }
    }

    /** Where simpview's classes were loaded from: a jar or a folder; null when the system does not say. */
    private static Path loadedFrom() {
        CodeSource source = UnpackedScenes.class.getProtectionDomain().getCodeSource();
        if (source == null || source.getLocation() == null) {
            return null;
        }
        try {
            return Path.of(source.getLocation().toURI());
        } catch (URISyntaxException | IllegalArgumentException e) {
            return null;
        }
    }

    private static boolean isJar(Path path) {
        return Files.isRegularFile(path) && path.toString().endsWith(".jar");
    }

    private static boolean hasScenes(JarFile file) {
        return file.stream().anyMatch(e -> e.getName().startsWith(FOLDER) && !e.isDirectory());
    }
}

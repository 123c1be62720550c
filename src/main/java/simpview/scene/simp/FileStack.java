package simpview.scene.simp;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.function.Function;
import java.util.function.IntConsumer;
import simpview.scene.FileChecksum;
import simpview.scene.FileLook;
import simpview.scene.FileProblem;
import simpview.scene.FileStamp;
import simpview.scene.FileVersion;
import simpview.scene.SceneException;
import simpview.scene.text.LineSource;

/**
 * The files being read, innermost on top: {@code file} pushes, the end of a
 * file pops, and commands always come from the top. An explicit stack, so an
 * include chain of any depth costs heap, never Java call stack.
 *
 * <p>File descriptors: only the top {@link #MAX_OPEN} readers keep their file
 * open; a deeper one is suspended (closed, its offset remembered) and reopens
 * where it was when it is on top again. Small files, which scenes include
 * over and over (a cube, a sphere), are read whole, and once read to the
 * end their bytes and commands are kept in a {@link SimpLibrary}: later
 * includes, and later pictures given the same library, replay them without
 * reading or scanning the file again. Where a name leads is looked up only
 * once a scene.
 */
final class FileStack implements AutoCloseable {

    static final int MAX_OPEN = 8;
    /**
     * A chain of files (an error's includes, a file cycle) longer than twice this is named in an error by this
     * many files at each end, "... N more ..." between (docs/simp.md: longer than ten, first five and last five).
     */
    static final int CHAIN_ENDS = 5;
    static final int SMALL_FILE = LineSource.CHUNK;

    private final List<SimpReader> readers = new ArrayList<>();
    /** The file each reader reads, as it was resolved. */
    private final List<Resolved> resolvedReaders = new ArrayList<>();
    private final Set<Path> onStack = new HashSet<>();
    private final Map<Name, Found> found = new HashMap<>();
    /** Where each .obj name led, for {@link #locateModel}. */
    private final Map<Name, Path> models = new HashMap<>();
    /** The place in {@link #reached} of each model {@link #locateModel} found, by the path it gave. */
    private final Map<Path, Integer> modelsReached = new HashMap<>();
    private final long smallFileLimit;
    private final SimpLibrary library;
    /** The real paths of the files whose bytes this scene has read: replayed on their stamps from then on. */
    private final Set<Path> readThisPicture = new HashSet<>();
    /** The working directory names are also looked for in (where the course's programs looked), absolute. */
    private final Path workingDir;
    /** Every file the scene read or looked for, each once, in the order met: what a window watches. */
    private final List<Path> reached = new ArrayList<>();
    /** Each reached file's place in {@link #reached}, by its real path (where it is known). */
    private final Map<Path, Integer> reachedKeys = new HashMap<>();
    /**
     * Each reached file as it was read: its stamp when it was reached, before it was read, and the checksum of the
     * bytes read once they are (see {@link #versionsAsRead}).
     */
    private final List<FileVersion> versions = new ArrayList<>();
    private long linesOfFinishedFiles;
    /** The top file's size when it was opened, for the share of it read so far. */
    private long topFileBytes;
    /** The top file's folder, absolute, without "." and "x/..": what {@link #shown} names files from. */
    private Path topFolder;

    FileStack() {
        this(SMALL_FILE);
    }

    /** @param smallFileLimit files up to this many bytes are read whole and kept; -1 streams every file */
    FileStack(long smallFileLimit) {
        this(smallFileLimit, Path.of("").toAbsolutePath(), new SimpLibrary());
    }

    /**
     * @param workingDir the folder names are looked for in after the including file's, absolute
     * @param library where small files read whole are kept, and looked for first
     */
    FileStack(long smallFileLimit, Path workingDir, SimpLibrary library) {
        this.smallFileLimit = smallFileLimit;
        this.workingDir = workingDir;
        this.library = library;
    }

    /** Starts with the scene's top file. */
    void openTop(Path named) throws SceneException {
        Path file = withExtension(named);
        // named without .simp and found neither way: say both were looked for
        String alsoLooked = file == named && named.getFileName() != null && !named.toString().endsWith(".simp")
                ? " (nor " + named.getFileName() + ".simp)" : "";
        Resolved top = resolve(file, null, problem -> new SceneException(file, 0, 0, "",
                problem.startsWith("file not found") ? problem + alsoLooked : problem));
        topFileBytes = top.stamp.size();
        topFolder = file.toAbsolutePath().normalize().getParent();
        push(open(file, top), top);
    }

    /**
     * A file as the scene's messages name it at their start ("parts/car.simp:3"): by its path from the top
     * file's folder when it lies there or below, so a scene of one folder (the course's) names its files by
     * their names alone and a part in a folder of its own by that folder too, whichever folder simpview runs
     * in; else by its path as it was opened, without "." and "x/.." (relative stays relative), as an error
     * names the file at fault ({@link SceneException}). Never by the name alone when two folders' files of
     * that name could be meant.
     */
    String shown(Path file) {
        Path absolute = file.toAbsolutePath().normalize();
        if (topFolder != null && absolute.startsWith(topFolder) && !absolute.equals(topFolder)) {
            return topFolder.relativize(absolute).toString().replace('\\', '/');
        }
        return file.normalize().toString();
    }

    /**
     * The top file as named, or with .simp added when it was named without
     * and only that exists (SPEC: a scene may be named without .simp, as the
     * course's programs took it).
     */
    static Path withExtension(Path named) {
        Path name = named.getFileName();
        if (name == null || name.toString().endsWith(".simp") || Files.exists(named)) {
            return named;
        }
        Path simp = named.resolveSibling(name + ".simp");
        return Files.exists(simp) ? simp : named;
    }

    /**
     * Reads the next command of the innermost file, going back to the file
     * that included it at each end of file.
     *
     * @return false when the top file is finished
     */
    boolean next(Command c) throws SceneException {
        while (!readers.isEmpty()) {
            if (top().next(c)) {
                return true;
            }
            pop();
        }
        return false;
    }

    /**
     * {@code e}, an error met while reading the top file, saying which lines
     * included that file: "cube.simp:3:1, included from page4.simp:12". An
     * error in another file (an {@code obj} command's model) names the top
     * file's line that read it too: "bad.obj:3:7, included from page-d.simp:20".
     */
    SceneException placed(SceneException e) {
        if (readers.isEmpty() || e.file() == null) {
            return e;
        }
        int innermost = top().file().equals(e.file()) ? readers.size() - 2 : readers.size() - 1;
        if (innermost < 0) {
            return e;
        }
        // file 0 is e's own, which the error names itself; file i > 0 is the reader i - 1 below the innermost
        int files = innermost + 2;
        StringBuilder chain = new StringBuilder();
        forEachNamed(files, i -> {
            if (i == 0) {
                return;
            }
            SimpReader including = readers.get(innermost - i + 1);
            Path before = i == 1 ? e.file() : readers.get(innermost - i + 2).file();
            chain.append(chain.length() == 0 ? "" : ", included from ")
                    .append(named(including.file(), before)).append(':').append(including.lineNumber());
        }, hidden -> chain.append(", ... ").append(hidden).append(" more ..."));
        return e.includedFrom(chain.toString());
    }

    /**
     * An including file as the chain names it: by its name alone when it is in the folder of the file named
     * before it (the course's scenes include each other so), else by its path as it was opened, without "." and
     * "x/.." (relative stays relative), so that two folders' part.simp do not read alike.
     */
    private static Path named(Path including, Path before) {
        Path folder = including.toAbsolutePath().normalize().getParent();
        Path beforeFolder = before.toAbsolutePath().normalize().getParent();
        return folder != null && folder.equals(beforeFolder) ? including.getFileName() : including.normalize();
    }

    /** Acts on a {@code file} command just read from the top file. */
    void include(Command c) throws SceneException {
        SimpReader from = top();
        Name name = Name.of(from, c);
        Found found = found(name, from, c);
        if (onStack.contains(found.resolved.real)) {
            throw from.error(c.argumentIndex, "file cycle: " + chain(found.resolved.real, found.path));
        }
        SimpReader reader;
        try {
            reader = open(found.path, found.resolved);
        } catch (SceneException e) {
            throw from.error(c.argumentIndex, e.problem());
        }
        push(reader, found.resolved);
    }

    /**
     * Where a name leads, looked up on the file system once per scene: finding
     * the real path costs a system call per folder, and scenes name the same
     * small files hundreds of times. A lookup that fails ends the scene, so
     * only successes are kept.
     */
    private Found found(Name name, SimpReader from, Command c) throws SceneException {
        Found known = found.get(name);
        if (known != null) {
            return known;
        }
        Located located = locate(c.fileName, ".simp", from, c);
        Resolved resolved = resolve(located.path, located.alsoWatched,
                problem -> from.error(c.argumentIndex, problem));
        Found result = new Found(located.path, resolved);
        found.put(name, result);
        return result;
    }

    /**
     * A file name as a command in a file of folder {@code dir} gives it (dir may be null). Its equals and
     * hashCode are written out, as FileStamp's are: a map key looked up at every include.
     */
    private record Name(Path dir, String name) {

        /** The name command c of the file {@code from} gives: how the scene keeps where a file or model name led. */
        static Name of(SimpReader from, Command c) {
            return new Name(from.file().getParent(), c.fileName);
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof Name other && Objects.equals(dir, other.dir) && Objects.equals(name, other.name);
        }

        @Override
        public int hashCode() {
            return Objects.hashCode(dir) * 31 + Objects.hashCode(name);
        }
    }

    /** The path to show in messages, and where it really leads. */
    private record Found(Path path, Resolved resolved) {
    }

    /**
     * Where a name was found ({@link #locate}), and the other place to
     * watch with it, or null: the one beside the including file, when the
     * name was found in the working directory (a file appearing there would
     * take over).
     */
    private record Located(Path path, Path alsoWatched) {
    }

    /**
     * A file to read: its real path, which identifies it, its stamp when it
     * was reached, and whether it had settled then ({@link SimpLibrary}).
     */
    private record Resolved(Path real, FileStamp stamp, boolean settled) {
    }

    /**
     * The file that {@code name} + {@code extension}, named by command c of
     * the file {@code from}, stands for: looked for in the folder of the file
     * holding the command, then in the working directory (where the course's
     * programs looked), by {@link FilePlaces}. When it is in neither, the
     * error names every place looked, and both are noted as reached; when
     * it is found, the caller notes it (and the place that would take over).
     */
    private Located locate(String name, String extension, SimpReader from, Command c) throws SceneException {
        FilePlaces places;
        try {
            places = FilePlaces.of(from.file(), name, extension, workingDir);
        } catch (InvalidPathException e) {
            throw from.error(c.argumentIndex, "not a valid file name: '" + name + "'");
        }
        Path found = places.found();
        if (found == null) {
            reach(places.here());
            reach(places.working());
            String looked = "; looked for " + places.here().toAbsolutePath().normalize()
                    + (places.hereIsWorking() ? "" : " and " + places.working().normalize());
            // a link that leads nowhere is there, as ls shows it: "file not found" would send one looking for a file
            String link = FileProblem.brokenLink(places.here());
            if (link != null) {
                throw from.error(c.argumentIndex, places.fileName() + " " + link + looked);
            }
            link = places.hereIsWorking() ? null : FileProblem.brokenLink(places.working());
            if (link != null) {
                throw from.error(c.argumentIndex, places.working().normalize() + " " + link + looked);
            }
            String hint = (name.endsWith(extension) ? " (" + extension + " is added to the name for you)" : "")
                    + places.nearMisses(name) + besideAnIncluder(name, extension, from, c);
            throw from.error(c.argumentIndex, "file not found: " + places.fileName() + hint + looked);
        }
        boolean takesOver = !places.hereIsWorking() && found.equals(places.working());
        return new Located(found, takesOver ? places.here() : null);
    }

    /**
     * When a name not found from the folder of the file holding the command
     * is there from the folder of a file that included it (most often the
     * scene's own: a student names a model from the scene's folder, inside a
     * part in a folder of its own), says so and how to name it from here;
     * else "". Found that way only from the working directory, the scene
     * reads it when started in its folder and not from elsewhere.
     */
    private String besideAnIncluder(String name, String extension, SimpReader from, Command c) {
        Path fromDir = from.file().toAbsolutePath().normalize().getParent();
        for (int i = readers.size() - 1; i >= 0 && fromDir != null; i--) {
            SimpReader includer = readers.get(i);
            if (fromDir.equals(includer.file().toAbsolutePath().normalize().getParent())) {
                continue; // the same folder: looked for there already
            }
            Path there;
            try {
                there = FilePlaces.of(includer.file(), name, extension, workingDir).here().toAbsolutePath().normalize();
            } catch (InvalidPathException e) {
                return "";
            }
            if (Files.isRegularFile(there)) {
                String relative = fromDir.relativize(there).toString().replace('\\', '/');
                String meant = relative.substring(0, relative.length() - extension.length());
                return "; there is " + there + ", this name read from the folder of " + includer.file().getFileName()
                        + ", but a name is looked for from the folder of the file that holds the command, "
                        + from.file().getFileName() + ": write " + c.kind.spelling + " \"" + meant + "\"";
            }
        }
        return "";
    }

    /**
     * The .obj file an {@code obj} command of the file being read names,
     * found as {@code file} names are, and looked up once per scene as they
     * are ({@link #found}): a page may draw one model a hundred times.
     */
    Path locateModel(Command c) throws SceneException {
        SimpReader from = top();
        Name name = Name.of(from, c);
        Path known = models.get(name);
        if (known != null) {
            return known;
        }
        Located located = locate(c.fileName, ".obj", from, c);
        modelsReached.put(located.path, reach(located.path));
        reachAlso(located.alsoWatched);
        models.put(name, located.path);
        return located.path;
    }

    /** "file:line" of the command being carried out, for messages: the file as {@link #shown} names it. */
    String place() {
        SimpReader r = top();
        return shown(r.file()) + ":" + r.lineNumber();
    }

    /** Notes a file the scene read or looked for, once; returns its place in {@link #reached}. */
    private int reach(Path file) {
        return reach(file, realOrAbsolute(file), FileStamp.of(file));
    }

    /** Where {@code file} really leads, or where it would be when it cannot be told: what it is reached by. */
    private static Path realOrAbsolute(Path file) {
        try {
            return file.toRealPath();
        } catch (IOException | SecurityException e) {
            return file.toAbsolutePath().normalize();
        }
    }

    /**
     * Notes {@code file}, really {@code key}, as it is now ({@code stamp}), unless it is noted already; returns its
     * place in {@link #reached}.
     */
    private int reach(Path file, Path key, FileStamp stamp) {
        Integer at = reachedKeys.putIfAbsent(key, reached.size());
        if (at != null) {
            return at;
        }
        reached.add(file);
        versions.add(FileVersion.of(stamp));
        return reached.size() - 1;
    }

    /**
     * Notes the checksum of the bytes the scene read of the reached file
     * {@code real} (a {@link FileChecksum#NONE} is no news): the first one
     * noted stays, so a file read twice in one picture (a big file streamed
     * at each include) is held against its first reading.
     */
    private void readAs(Path real, long checksum) {
        Integer at = reachedKeys.get(real);
        if (at != null && checksum != FileChecksum.NONE && !versions.get(at).checksummed()) {
            versions.set(at, new FileVersion(versions.get(at).stamp(), checksum));
        }
    }

    /**
     * Notes the model {@code file}, found by {@link #locateModel}, as it was
     * drawn ({@code drawn}: the stamp its reader looked at before reading it
     * and the checksum of the bytes parsed); null, when none was drawn, is
     * no news. The first one noted stays.
     */
    void modelDrawn(Path file, FileVersion drawn) {
        if (drawn == null) {
            return;
        }
        Integer at = modelsReached.get(file);
        if (at != null && !versions.get(at).checksummed()) {
            versions.set(at, drawn);
        }
    }

    /**
     * Every file the scene read or looked for so far, each once, in the order
     * met: the top file, each included .simp file and each .obj model, and
     * for a name found in neither place both places (for a name found only in
     * the working directory, also the place that would take it over), so
     * that a window watching them sees a file appear too.
     */
    List<Path> reached() {
        return List.copyOf(reached);
    }

    /**
     * {@link #reached()}'s files as the scene read them, in the same order:
     * each one's stamp, taken before it was read, and the checksum of the
     * very bytes read ({@link FileChecksum}), where they were read whole (a
     * small file, one streamed to its end, a model parsed to its end) and
     * are checksummed at all. A save made after the stamp was taken differs
     * from them whenever it is looked at, also one that keeps size, time
     * and inode (two saves within one tick of the file system's clock), so a
     * window that watches the files sees it.
     */
    List<FileVersion> versionsAsRead() {
        return List.copyOf(versions);
    }

    /**
     * Where {@code candidate} really leads, if that is a file to read, noted
     * as reached (and {@code alsoWatched} after it, if not null), whether or
     * not it can be read. The top file and an included one are checked here
     * alike, so a missing file or a folder gets the same words wherever it is
     * named; {@code error} places the problem (a top file has no line, an
     * include its command's column). The real path is looked up and the
     * attributes read once: the stamp, the check that it is a file and its
     * size all come from them.
     */
    private Resolved resolve(Path candidate, Path alsoWatched, Function<String, SceneException> error)
            throws SceneException {
        String shown = candidate.toAbsolutePath().normalize().toString();
        FileLook look;
        try {
            look = FileLook.at(candidate);
        } catch (IOException | SecurityException e) {
            reach(candidate);
            reachAlso(alsoWatched);
            String link = FileProblem.brokenLink(candidate);
            if (link != null) {
                throw error.apply(shown + " " + link);
            }
            if (e instanceof NoSuchFileException) {
                throw error.apply("file not found: " + shown);
            }
            if (e instanceof IOException io) {
                throw error.apply("cannot open " + shown + ": " + FileProblem.of(candidate, io));
            }
            throw error.apply("cannot open " + shown + ": access denied");
        }
        reach(candidate, look.real(), look.stamp());
        reachAlso(alsoWatched);
        String notAFile = FileProblem.notAFile(look.attributes());
        if (notAFile != null) {
            throw error.apply(notAFile + ": " + shown);
        }
        return new Resolved(look.real(), look.stamp(), library.settled(look));
    }

    private void reachAlso(Path alsoWatched) {
        if (alsoWatched != null) {
            reach(alsoWatched); // a file appearing beside the including one would take over
        }
    }

    /**
     * "a.simp → b.simp → a.simp": the files from the first visit of {@code real} to its second, {@code closing}
     * (the name that leads back to it), each as {@link #shown} names files, so that two folders' files of one
     * name are told apart.
     */
    private String chain(Path real, Path closing) {
        StringBuilder sb = new StringBuilder();
        int first = 0;
        while (!resolvedReaders.get(first).real.equals(real)) {
            first++;
        }
        // file i is reader first + i, and the last is the first again, where the cycle closes
        int start = first;
        int files = readers.size() - first + 1;
        forEachNamed(files, i -> sb.append(sb.length() == 0 ? "" : " → ")
                .append(shown(i == files - 1 ? closing : readers.get(start + i).file())),
                hidden -> sb.append(" → ... ").append(hidden).append(" more ..."));
        return sb.toString();
    }

    /**
     * Walks a chain of {@code files} files, first to last, handing {@code named} the index of each file an
     * error names: all of a chain of up to twice {@link #CHAIN_ENDS}, else only that many at each end, with
     * {@code gap} told how many it leaves out in their place. A chain thousands of files deep would otherwise
     * print tens of kilobytes, and its ends say where and why.
     */
    private static void forEachNamed(int files, IntConsumer named, IntConsumer gap) {
        boolean shortened = files > 2 * CHAIN_ENDS;
        for (int i = 0; i < files; i++) {
            if (shortened && i == CHAIN_ENDS) {
                gap.accept(files - 2 * CHAIN_ENDS);
                i = files - CHAIN_ENDS;
            }
            named.accept(i);
        }
    }

    /**
     * A reader of {@code file}: a small one from the library (its commands
     * replayed when kept and unchanged, else read whole and recorded), a
     * bigger one streamed (and checksummed as it is read, when not too big
     * for that: {@link FileChecksum#taken}). A small file's size is the one it had when it was
     * reached; readAllBytes reads what is there now.
     */
    private SimpReader open(Path file, Resolved resolved) throws SceneException {
        if (resolved.stamp.size() > smallFileLimit) {
            SimpReader streamed = SimpReader.open(file);
            return FileChecksum.taken(resolved.stamp.size()) ? streamed.checksummed() : streamed;
        }
        try {
            return library.open(file, resolved.real, resolved.stamp, resolved.settled, readThisPicture);
        } catch (IOException e) {
            throw new SceneException(file, 0, 0, "", "cannot read " + file + ": " + FileProblem.of(file, e));
        }
    }

    private void push(SimpReader reader, Resolved resolved) throws SceneException {
        readAs(resolved.real, reader.checksumAsRead());
        readers.add(reader);
        resolvedReaders.add(resolved);
        onStack.add(resolved.real);
        int deepestOpen = readers.size() - 1 - MAX_OPEN;
        if (deepestOpen >= 0) {
            readers.get(deepestOpen).suspend();
        }
    }

    /** Ends the top file; a small one read to its end without an error is kept in the library. */
    private void pop() {
        SimpReader done = readers.remove(readers.size() - 1);
        done.close();
        linesOfFinishedFiles += done.linesRead();
        Resolved resolved = resolvedReaders.remove(resolvedReaders.size() - 1);
        onStack.remove(resolved.real);
        readAs(resolved.real, done.checksumAsRead());
        library.keep(resolved.real, resolved.stamp, resolved.settled, done);
    }

    private SimpReader top() {
        return readers.get(readers.size() - 1);
    }

    /** True while {@code reader} is one of the files being read: the top one or one that included it. */
    boolean reading(SimpReader reader) {
        for (int i = readers.size() - 1; i >= 0; i--) {
            if (readers.get(i) == reader) {
                return true;
            }
        }
        return false;
    }

    /** The file the last command came from. */
    SimpReader current() {
        return top();
    }

    int depth() {
        return readers.size();
    }

    /**
     * Where the command being carried out stands, with every {@code file}
     * command that led to it: the top file's line first, the innermost last.
     */
    List<SourcePlace> chain() {
        List<SourcePlace> chain = new ArrayList<>(readers.size());
        for (SimpReader r : readers) {
            chain.add(new SourcePlace(r.file(), r.lineNumber()));
        }
        return chain;
    }

    /** How many of the readers hold an open file now (for tests). */
    int openFiles() {
        int open = 0;
        for (SimpReader r : readers) {
            open += r.holdsFile() ? 1 : 0;
        }
        return open;
    }

    /** The share of the top file's bytes read so far, 0 to 1: what a progress bar shows. */
    double topFileShare() {
        if (readers.isEmpty()) {
            return 1;
        }
        return topFileBytes <= 0 ? 0 : Math.min(1, (double) readers.get(0).bytesRead() / topFileBytes);
    }

    /** Physical lines read so far over all files. */
    long linesRead() {
        long n = linesOfFinishedFiles;
        for (SimpReader r : readers) {
            n += r.linesRead();
        }
        return n;
    }

    @Override
    public void close() {
        while (!readers.isEmpty()) {
            pop();
        }
    }
}

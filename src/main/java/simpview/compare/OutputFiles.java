package simpview.compare;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.concurrent.ThreadLocalRandom;

/**
 * The one place every file simpview writes (pictures, diff images, tables,
 * reports) is written, whole or not at all: into a temporary file beside it,
 * then moved into place. A write that fails half-way (a full disk) leaves the
 * file that was there before as it was, and no temporary behind. A file that
 * is there and is not a regular one (a FIFO, /dev/null, /dev/stdout) is
 * written straight into instead, as any program writes it: a file moved over
 * it would replace it, and its reader would get nothing. Its messages say
 * which file and why, in words a user can act on.
 */
public final class OutputFiles {

    /** What goes into a file: written to {@code out}, which the caller closes. */
    @FunctionalInterface
    public interface Content {
        void writeTo(OutputStream out) throws IOException;
    }

    /** The end of a temporary's name; a picture's is never this, so a folder being compared never lists one. */
    static final String TEMPORARY_ENDING = ".tmp";
    /** How much of the file's name a temporary keeps, so that its name stays within a file system's limit. */
    private static final int NAME_KEPT = 100;

    private OutputFiles() {
    }

    /**
     * Writes {@code content} to {@code file}, making missing parent folders;
     * the file is replaced only once all of it is written. A FIFO or a
     * device there is written into instead, never replaced.
     *
     * @throws IOException whose message says which file and why, e.g.
     *     "cannot write out/x.png: permission denied"
     */
    public static void write(Path file, Content content) throws IOException {
        Path target = file.toAbsolutePath();
        if (Files.isDirectory(target)) {
            throw new IOException("cannot write " + file + ": it is a folder");
        }
        if (isSpecial(target)) {
            writeInto(file, target, content);
            return;
        }
        // A link is followed, as writing through it would: the file it names is replaced, not the link.
        Path place = Files.isSymbolicLink(target) ? target.toRealPath() : target;
        Path temporary = null;
        try {
            Path parent = place.getParent();
            if (parent != null) {
                Files.createDirectories(parent);
            }
            temporary = temporaryBeside(place);
            try (OutputStream out = Files.newOutputStream(temporary, StandardOpenOption.WRITE)) {
                content.writeTo(out);
            }
            moveIntoPlace(temporary, place);
            temporary = null;
        } catch (IOException e) {
            throw new IOException("cannot write " + file + ": " + reason(e, target), e);
        } finally {
            if (temporary != null) {
                deleteQuietly(temporary);
            }
        }
    }

    /**
     * True when {@code target} (a link followed) is there and is no regular
     * file or folder: a FIFO, a device, a socket. Such a file is a place the
     * bytes go through, not one they are kept in, so it is written into, not
     * replaced.
     */
    private static boolean isSpecial(Path target) {
        return Files.exists(target) && !Files.isRegularFile(target) && !Files.isDirectory(target);
    }

    /**
     * Writes {@code content} straight into {@code target}, a file that
     * {@link #isSpecial} says is not one to replace. It is opened for writing
     * only, as it is: not made (it is there), not truncated (a FIFO or a
     * device has nothing to cut), nothing made beside it. What it was given
     * before a failure has gone to its reader, as from any program.
     */
    private static void writeInto(Path file, Path target, Content content) throws IOException {
        try (OutputStream out = Files.newOutputStream(target, StandardOpenOption.WRITE)) {
            content.writeTo(out);
        } catch (IOException e) {
            throw new IOException("cannot write " + file + ": " + reason(e, target), e);
        }
    }

    /**
     * For a run that failed, and may not have written {@code file}: a FIFO
     * (or another file that is no regular one, nor a folder) there is opened
     * and closed at once, so that a reader waiting on it sees the end of the
     * file instead of waiting for ever. It is opened for reading and writing,
     * an open that never waits for a reader to come (Linux; POSIX leaves it
     * to the system), so nothing hangs when none is there; nothing is written
     * into it. A regular file is left as it is, never truncated nor deleted:
     * what a run wrote before it failed is kept. Nothing there: nothing done.
     * Never throws: a file that cannot be opened is left as it is.
     */
    public static void release(Path file) {
        Path target = file.toAbsolutePath();
        if (!isSpecial(target)) {
            return;
        }
        try {
            FileChannel.open(target, StandardOpenOption.READ, StandardOpenOption.WRITE).close();
        } catch (IOException e) {
            // a device or socket that cannot be opened so: no reader waits on it as on a FIFO
        }
    }

    /** Writes {@code text} as UTF-8, as {@link #write} writes. */
    public static void writeString(Path file, String text) throws IOException {
        write(file, out -> out.write(text.getBytes(StandardCharsets.UTF_8)));
    }

    /**
     * Why a file could not be written at {@code file}, or null when nothing
     * is known to stop it: it is a folder, a file is in the way of its folder,
     * or its folder may not be written to. Looked at without writing anything.
     */
    public static String fileProblem(Path file) {
        Path target = file.toAbsolutePath().normalize();
        if (Files.isDirectory(target)) {
            return target + " is a folder";
        }
        if (isSpecial(target)) {
            // written into, not replaced: its folder need not be writable (/dev), the file itself must
            return Files.isWritable(target) ? null : "permission denied (" + target + ")";
        }
        return target.getParent() == null ? null : folderProblem(target.getParent());
    }

    /** Why files could not be written into {@code folder} (made when missing), or null: as {@link #fileProblem}. */
    public static String folderProblem(Path folder) {
        Path existing = nearestExisting(folder.toAbsolutePath().normalize());
        if (existing == null) {
            return null;
        }
        if (!Files.isDirectory(existing)) {
            return existing + " is in the way: it is a file, not a folder";
        }
        return Files.isWritable(existing) ? null : "permission denied (" + existing + ")";
    }

    /**
     * The path {@code file} is known by, so that two names of one file are
     * equal: its real path as far as it exists (links followed), and the
     * rest as given, normalized.
     */
    public static Path identity(Path file) {
        Path absolute = file.toAbsolutePath().normalize();
        Path existing = nearestExisting(absolute);
        if (existing == null) {
            return absolute;
        }
        try {
            return existing.toRealPath().resolve(existing.relativize(absolute));
        } catch (IOException e) {
            return absolute;
        }
    }

    /** {@code absolute} itself if it exists, else its nearest folder above that does; null when none does. */
    private static Path nearestExisting(Path absolute) {
        Path existing = absolute;
        while (existing != null && !Files.exists(existing)) {
            existing = existing.getParent();
        }
        return existing;
    }

    /**
     * Why {@code e} kept {@code target} from being written, in words:
     * "permission denied", "out is in the way: it is a file, not a folder".
     */
    static String reason(IOException e, Path target) {
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof FileAlreadyExistsException already) {
            return already.getFile() + " is in the way: it is a file, not a folder";
        }
        if (e instanceof FileSystemException fs && fs.getReason() != null) {
            boolean elsewhere = fs.getFile() != null && !Path.of(fs.getFile()).equals(target)
                    && !fs.getFile().endsWith(TEMPORARY_ENDING);
            return fs.getReason() + (elsewhere ? " (" + fs.getFile() + ")" : "");
        }
        if (e instanceof FileSystemException fs) {
            return "no such file or folder: " + fs.getFile();
        }
        return e.getMessage() == null || e.getMessage().isBlank() ? "the system could not write it" : e.getMessage();
    }

    /** A new empty file beside {@code place}, named after it: ".page3.png.k2x9q1.tmp". */
    private static Path temporaryBeside(Path place) throws IOException {
        String name = place.getFileName().toString();
        String kept = name.length() > NAME_KEPT ? name.substring(0, NAME_KEPT) : name;
        while (true) {
            String random = Long.toUnsignedString(ThreadLocalRandom.current().nextLong(), 36);
            Path temporary = place.resolveSibling("." + kept + "." + random + TEMPORARY_ENDING);
            try {
                // not Files.createTempFile: its file may be read by its owner only, and the move would keep that
                Files.newOutputStream(temporary, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE).close();
                return temporary;
            } catch (FileAlreadyExistsException taken) {
                // another name, then
            }
        }
    }

    /** Moves the finished temporary over the file, atomically where the file system can. */
    private static void moveIntoPlace(Path temporary, Path place) throws IOException {
        try {
            Files.move(temporary, place, StandardCopyOption.ATOMIC_MOVE);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(temporary, place, StandardCopyOption.REPLACE_EXISTING);
        }
    }

    private static void deleteQuietly(Path temporary) {
        try {
            Files.deleteIfExists(temporary);
        } catch (IOException e) {
            // the write's own failure is the one reported
        }
    }
}

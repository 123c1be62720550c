package simpview.scene;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * What went wrong with a file, in the words of a person: "file not found",
 * "permission denied", "not a file but a folder". Never a Java class name.
 */
public final class FileProblem {

    private FileProblem() {
    }

    /** Why {@code file} could not be opened or read, from the exception that said so. */
    public static String of(Path file, IOException e) {
        if (e instanceof NoSuchFileException) {
            return "file not found";
        }
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (Files.isDirectory(file)) {
            return "not a file but a folder";
        }
        return systemWords(e);
    }

    /**
     * Why a folder could not be listed, from the exception that said so: "permission denied", "no such folder",
     * "not a folder but a file", or the system's own words; never the exception's message alone, which for most
     * is the folder's path again.
     */
    public static String ofFolder(IOException e) {
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof NoSuchFileException) {
            return "no such folder";
        }
        if (e instanceof NotDirectoryException) {
            return "not a folder but a file";
        }
        return systemWords(e);
    }

    /**
     * Why {@code path} leads to nothing through a symbolic link, when it does: the first link on its way (itself,
     * or a folder it lies in) that leads to no file or folder, in words that follow the path's name: "is a loop
     * of symbolic links (loop.simp → b.simp → loop.simp)", each link as it is written, as {@code ls -l} shows
     * it; "is a link to gone.simp, which does not exist"; "is in parts, a loop of symbolic links (parts →
     * parts)". Null when no link on its way is broken: it is missing, or cannot be read, for another reason.
     */
    public static String brokenLink(Path path) {
        Path absolute = path.toAbsolutePath();
        Path on = absolute.getRoot();
        for (Path part : absolute) {
            on = on == null ? part : on.resolve(part);
            if (Files.isSymbolicLink(on) && !Files.exists(on)) {
                String trouble = linkTrouble(on);
                return trouble == null ? null : on.equals(absolute) ? "is " + trouble
                        : "is in " + on.getFileName() + ", " + trouble;
            }
            if (!Files.exists(on, LinkOption.NOFOLLOW_LINKS)) {
                return null; // missing from here on: no link to blame
            }
        }
        return null;
    }

    /** The most links a chain is followed through, as systems do (40 on Linux) before they call it a loop. */
    private static final int MOST_LINKS = 40;

    /** Why the link {@code link}, which leads to nothing, does: a loop, or a link to what does not exist. */
    private static String linkTrouble(Path link) {
        List<String> written = new ArrayList<>();
        written.add(String.valueOf(link.getFileName()));
        Set<Path> seen = new HashSet<>();
        Path at = link;
        while (seen.add(at.normalize()) && written.size() <= MOST_LINKS) {
            Path target;
            try {
                target = Files.readSymbolicLink(at);
            } catch (IOException | UnsupportedOperationException | SecurityException e) {
                return null;
            }
            written.add(target.toString());
            Path next = at.getParent() == null ? target : at.getParent().resolve(target);
            if (!Files.isSymbolicLink(next)) {
                return "a link to " + target + ", which does not exist";
            }
            at = next;
        }
        if (written.size() > MOST_LINKS) {
            return "a chain of more than " + MOST_LINKS + " symbolic links (" + String.join(" → ", written.subList(0, 3))
                    + " → …), which the system does not follow";
        }
        return "a loop of symbolic links (" + String.join(" → ", written) + ")";
    }

    /** The system's own words for {@code e} (its reason, not the path it names), or a plain phrase when it gave none. */
    private static String systemWords(IOException e) {
        String reason = e instanceof FileSystemException fs ? fs.getReason() : e.getMessage();
        return reason == null || reason.isBlank() ? "the system could not read it" : lowerFirst(reason);
    }

    /**
     * Why a path with these attributes (read once by the caller, who also
     * stamps the file with them) is not a file to read as text, or null when
     * it is one: a folder, or a device or pipe, which may stream bytes for
     * ever.
     */
    public static String notAFile(BasicFileAttributes attributes) {
        if (attributes.isRegularFile()) {
            return null;
        }
        return attributes.isDirectory() ? "not a file but a folder" : NOT_REGULAR;
    }

    private static final String NOT_REGULAR = "not a regular file (a device or a pipe?)";

    private static String lowerFirst(String s) {
        return s.length() > 1 && Character.isUpperCase(s.charAt(0)) && Character.isLowerCase(s.charAt(1))
                ? Character.toLowerCase(s.charAt(0)) + s.substring(1) : s;
    }
}

package simpview.scene;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;

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

package simpview.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Why a file or a folder could not be read, in a person's words, never the path again nor a class name. */
class FileProblemTest {

    @TempDir
    Path dir;

    @Test
    void aFolderThatCannotBeListedIsToldWhy() {
        Path folder = dir.resolve("bob");
        assertEquals("permission denied", FileProblem.ofFolder(new AccessDeniedException(folder.toString())));
        assertEquals("no such folder", FileProblem.ofFolder(new NoSuchFileException(folder.toString())));
        assertEquals("not a folder but a file", FileProblem.ofFolder(new NotDirectoryException(folder.toString())));
        assertEquals("input/output error",
                FileProblem.ofFolder(new FileSystemException(folder.toString(), null, "Input/output error")));
        assertEquals("the system could not read it", FileProblem.ofFolder(new FileSystemException(folder.toString())));
        assertEquals("input/output error", FileProblem.ofFolder(new IOException("Input/output error")));
    }
}

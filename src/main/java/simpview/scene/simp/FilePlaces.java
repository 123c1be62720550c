package simpview.scene.simp;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import simpview.scene.text.CopiedText;

/**
 * The two places a name given to {@code file} or {@code obj} is looked for,
 * with the extension always added ("bowling" is bowling.obj, "a.obj" is
 * a.obj.obj): the folder of the file holding the command, then the working
 * directory (where the course's programs looked). The reader and the
 * window's watch list both ask here, so they cannot disagree on which file a
 * name means.
 *
 * @param fileName the name with its extension, as looked for
 * @param here the name in the folder of the file holding the command
 * @param working the name in the working directory, absolute
 */
record FilePlaces(String fileName, Path here, Path working) {

    /**
     * The places of {@code name} + {@code extension} named in the file
     * {@code from}, with the working directory the program runs in.
     *
     * @throws InvalidPathException the name is no valid file name here
     */
    static FilePlaces of(Path from, String name, String extension) {
        return of(from, name, extension, Path.of("").toAbsolutePath());
    }

    /** As {@link #of(Path, String, String)}, with {@code workingDir} (absolute) as the working directory. */
    static FilePlaces of(Path from, String name, String extension, Path workingDir) {
        String fileName = name + extension;
        Path dir = from.getParent();
        // "x/../c.simp" named as "c.simp" in every message, the path still relative when the including one is
        Path here = (dir == null ? Path.of(fileName) : dir.resolve(fileName)).normalize();
        return new FilePlaces(fileName, here, workingDir.resolve(fileName).normalize());
    }

    /**
     * The file the reader reads: the one beside the including file when it
     * exists, else the one in the working directory when that exists; null
     * when it is in neither (the same words wherever the program runs).
     */
    Path found() {
        if (Files.exists(here)) {
            return here;
        }
        return !hereIsWorking() && Files.exists(working) ? working : null;
    }

    /**
     * For a name found in neither place ({@code name}, as the command gave
     * it): what was likely meant, or "". A file that differs only in case,
     * beside the including file or else in the working directory: "(there is
     * Teapot.obj: names are case-sensitive here)"; a backslash, which is part
     * of a name here, not a folder separator (one or a doubled one, as a C
     * string writes it); curly quotes, as a name copied from a PDF has them
     * (obj “filename” in the handouts). Looked for only once the name
     * was not found, so a scene that finds its files costs nothing more.
     */
    String nearMisses(String name) {
        StringBuilder hints = new StringBuilder();
        Path otherCase = otherCase(here);
        // beside the including file: named as the command would name it; in the working directory: in full
        Path shown = otherCase == null ? null : Path.of(fileName).resolveSibling(otherCase.getFileName());
        if (otherCase == null && !hereIsWorking()) {
            shown = otherCase(working);
        }
        if (shown != null) {
            hints.append(" (there is ").append(shown).append(": names are case-sensitive here)");
        }
        if (CopiedText.hasCurlyQuote(name)) {
            String plain = CopiedText.withoutQuotes(name);
            hints.append(" (the name").append(CopiedText.hint(name, "")).append(": write ")
                    .append(fileName.endsWith(".obj") ? "obj" : "file").append(" \"").append(plain).append("\")");
        }
        if (name.indexOf('\\') >= 0) {
            hints.append(" (a backslash is part of a name here: write \"").append(name.replaceAll("\\\\+", "/"))
                    .append("\", with / between folders)");
        }
        return hints.toString();
    }

    /** A file in the folder of {@code wanted} whose name is that of {@code wanted} but for case; null when none. */
    private static Path otherCase(Path wanted) {
        Path dir = wanted.toAbsolutePath().normalize().getParent();
        String name = wanted.getFileName().toString();
        if (dir == null || !Files.isDirectory(dir)) {
            return null;
        }
        try (DirectoryStream<Path> entries = Files.newDirectoryStream(dir)) {
            for (Path entry : entries) {
                String entryName = entry.getFileName().toString();
                if (!entryName.equals(name) && entryName.equalsIgnoreCase(name)) {
                    return entry;
                }
            }
        } catch (IOException | SecurityException e) {
            return null; // no hint: the error names the places looked, as before
        }
        return null;
    }

    /** True when both places are one, the including file lying in the working directory. */
    boolean hereIsWorking() {
        return here.toAbsolutePath().normalize().equals(working.normalize());
    }
}

package simpview.scene.simp;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.List;
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
     * (obj “filename” in the handouts); single quotes, as Python or a shell
     * quotes a name ('cube'); a file the name misses only by its extension
     * ({@link #otherExtension}). Looked for only once the name
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
        String command = fileName.endsWith(".obj") ? "obj" : "file";
        if (CopiedText.hasCurlyQuote(name)) {
            String plain = CopiedText.withoutQuotes(name);
            hints.append(" (the name").append(CopiedText.hint(name, "")).append(": write ")
                    .append(command).append(" \"").append(plain).append("\")");
        }
        if (name.length() > 2 && name.startsWith("'") && name.endsWith("'")) {
            hints.append(" (a name is quoted with '\"', not with \"'\": write ").append(command).append(" \"")
                    .append(name, 1, name.length() - 1).append("\")");
        }
        hints.append(otherExtension(name));
        if (name.indexOf('\\') >= 0) {
            hints.append(" (a backslash is part of a name here: write \"").append(name.replaceAll("\\\\+", "/"))
                    .append("\", with / between folders)");
        }
        return hints.toString();
    }

    /**
     * For a name found in neither place ({@code name}, as the command gave it): a file there that the name
     * meant with another extension, beside the including file or else in the working directory, and what to
     * write; or "". The name names a model where a scene file is wanted, or the other way round ({@code file
     * "teapot"} beside teapot.obj, {@code file "teapot.obj"}, {@code obj "cube"} beside cube.simp): the other
     * command draws it. The name as written is a file with another extension (Oct.OBJ, teapot.txt): the file is
     * to be renamed. The name's extension replaced by the right one is a file ({@code obj "teapot.simp"} beside
     * teapot.obj): the extension is to be left off. A name ending in the extension added already has its hint.
     */
    private String otherExtension(String name) {
        String extension = fileName.substring(name.length());
        boolean model = extension.equals(".obj");
        String command = model ? "obj" : "file";
        String otherExtension = model ? ".simp" : ".obj";
        String other = model ? "a scene file: file \"" : "a model: obj \"";
        String otherDoes = model ? "\" includes it" : "\" draws it";
        int slash = name.lastIndexOf('/');
        int dot = name.lastIndexOf('.');
        String suffix = dot > slash + 1 ? name.substring(dot) : "";
        String base = suffix.isEmpty() ? name : name.substring(0, dot);
        String baseFile = base.substring(slash + 1);
        for (Path place : hereIsWorking() ? List.of(here) : List.of(here, working)) {
            boolean beside = place == here;
            if (suffix.equalsIgnoreCase(otherExtension) && isFile(place, name)) {
                return " (there is " + shown(place, name, beside) + ", " + other + base + otherDoes + ")";
            }
            if (!name.endsWith(extension) && isFile(place, name)) {
                return " (there is " + shown(place, name, beside) + ", but " + command + " adds " + extension
                        + " to the name it is given: rename the file " + baseFile + extension + " and write "
                        + command + " \"" + base + "\")";
            }
            if (!suffix.isEmpty() && !name.endsWith(extension) && isFile(place, base + extension)) {
                return " (there is " + shown(place, base + extension, beside) + ": " + command + " adds " + extension
                        + " to the name it is given, so write " + command + " \"" + base + "\")";
            }
            if (isFile(place, name + otherExtension)) {
                return " (there is " + shown(place, name + otherExtension, beside) + ", " + other + name + otherDoes
                        + ")";
            }
        }
        return "";
    }

    /** True when {@code file}, a name as a command gives it, is a file in the folder of {@code place}. */
    private boolean isFile(Path place, String file) {
        Path folder = place.toAbsolutePath().normalize().getParent();
        try {
            Path last = Path.of(file).getFileName(); // none for "/"
            return folder != null && last != null && Files.isRegularFile(folder.resolve(last.toString()));
        } catch (InvalidPathException e) {
            return false;
        }
    }

    /**
     * {@code file}, in the folder of {@code place}, as a hint names it: as the command would name it when it is
     * beside the including file, in full in the working directory.
     */
    private static String shown(Path place, String file, boolean beside) {
        Path named = Path.of(file);
        return (beside ? named : place.toAbsolutePath().normalize().resolveSibling(named.getFileName())).toString();
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

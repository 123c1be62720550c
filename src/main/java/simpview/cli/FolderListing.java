package simpview.cli;

import java.io.IOException;
import java.nio.file.FileSystemLoopException;
import java.nio.file.FileVisitOption;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import simpview.compare.Count;
import simpview.compare.WithoutPictures;
import simpview.pages.SceneList;

/**
 * The pictures of a folder (and its subfolders) as a batch takes them, in natural order of their paths
 * (page2 before page10), and how many were left out as hidden: a file or folder whose name starts with
 * '.', or a folder named __MACOSX. A Mac's zip puts a "._page1.png" of a few bytes beside every file in
 * __MACOSX/, and a hidden copy is no picture the student meant to hand in.
 *
 * @param pictures the pictures, by their paths under the folder (the folder prepended)
 * @param hidden how many pictures were left out as hidden
 * @param unreadable the files, not hidden, in a picture format simpview does not read (page6.tif, page2.webp)
 * @param others every file, not hidden, that is not a picture simpview reads (a zip, notes.txt, page6.tif): what
 *     a folder without pictures holds instead
 */
record FolderListing(List<Path> pictures, int hidden, List<Path> unreadable, List<Path> others) {

    /** The endings of the pictures simpview reads (PNG, JPEG, GIF, BMP), in lower case. */
    static final List<String> PICTURE_ENDINGS = List.of(".png", ".jpg", ".jpeg", ".gif", ".bmp");
    /**
     * The endings of pictures (and of a page exported as a document) that simpview does not read: a file so
     * named is no row of the table, but the page it is named like is told of it when it has no picture.
     */
    static final List<String> UNREAD_ENDINGS = List.of(".webp", ".tif", ".tiff", ".heic", ".heif", ".avif", ".jxl",
            ".jp2", ".jfif", ".svg", ".psd", ".xcf", ".ppm", ".pgm", ".pbm", ".pnm", ".tga", ".ico", ".exr", ".hdr",
            ".pdf");
    /** Documents a student may paste pictures into (a PDF is among UNREAD_ENDINGS), in lower case. */
    static final List<String> DOCUMENTS = List.of(".doc", ".docx", ".odt", ".pages", ".ppt", ".pptx", ".key", ".odp");

    /**
     * Whether a file (a path under the folder) may be a student's pictures handed in another way: an archive, a
     * picture in a format simpview does not read, a document. A folder of a class's that holds none of these
     * (reports, a rubric, scripts) is no student's.
     */
    static boolean mayHoldPictures(String file) {
        Path path = Path.of(file);
        return endsLike(path, WithoutPictures.ARCHIVES) || endsLike(path, UNREAD_ENDINGS) || endsLike(path, DOCUMENTS);
    }

    /** The folder a Mac's zip puts its resource forks in. */
    static final String MAC_LEFTOVERS = "__MACOSX";

    /** The pictures under {@code dir}, hidden ones left out and counted, and the files in formats it does not read. */
    static FolderListing of(Path dir) throws IOException {
        List<Path> files = new ArrayList<>();
        // A link is taken as what it links to, as a file manager shows it: a link to a folder is looked into (one
        // that leads back to a folder on its way is not, as all it holds is listed already), and a link to a
        // picture is that picture. A link to nothing is listed as it is named: a picture that cannot be read,
        // which says why, and not a page silently missing.
        Files.walkFileTree(dir, EnumSet.of(FileVisitOption.FOLLOW_LINKS), Integer.MAX_VALUE,
                new SimpleFileVisitor<>() {
                    @Override
                    public FileVisitResult visitFile(Path file, BasicFileAttributes attributes) {
                        if (attributes.isRegularFile() || attributes.isSymbolicLink()) {
                            files.add(file);
                        }
                        return FileVisitResult.CONTINUE;
                    }

                    @Override
                    public FileVisitResult visitFileFailed(Path file, IOException e) throws IOException {
                        if (e instanceof FileSystemLoopException) {
                            return FileVisitResult.CONTINUE;
                        }
                        throw e;
                    }
                });
        List<Path> all = files.stream()
                .sorted((a, b) -> SceneList.NATURAL_ORDER.compare(dir.relativize(a).toString(),
                        dir.relativize(b).toString()))
                .toList();
        List<Path> pictures = all.stream().filter(f -> endsLike(f, PICTURE_ENDINGS)).toList();
        List<Path> shown = pictures.stream().filter(f -> !hidden(dir.relativize(f))).toList();
        List<Path> unreadable = all.stream().filter(f -> endsLike(f, UNREAD_ENDINGS) && !hidden(dir.relativize(f)))
                .toList();
        List<Path> others = all.stream().filter(f -> !endsLike(f, PICTURE_ENDINGS) && !hidden(dir.relativize(f)))
                .toList();
        return new FolderListing(shown, pictures.size() - shown.size(), unreadable, others);
    }

    /** Whether a file's name ends with one of {@code endings} (lower case), letters of either case alike. */
    private static boolean endsLike(Path file, List<String> endings) {
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        return endings.stream().anyMatch(name::endsWith);
    }

    /** Whether a path under the folder is hidden: a name on its way starts with '.', or a folder is __MACOSX. */
    static boolean hidden(Path relative) {
        for (Path part : relative) {
            String name = part.toString();
            if (name.startsWith(".") || name.equals(MAC_LEFTOVERS)) {
                return true;
            }
        }
        return false;
    }

    /** What the batch says of the hidden pictures it left out, once: "" when there were none. */
    String hiddenNote() {
        return hidden == 0 ? "" : Count.of(hidden, "hidden picture") + " left out (a name starting "
                + "with '.', or in a " + MAC_LEFTOVERS + " folder: a Mac's zip leftovers)";
    }
}

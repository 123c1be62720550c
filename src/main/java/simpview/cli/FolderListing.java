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
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Enumeration;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;
import java.util.zip.ZipEntry;
import java.util.zip.ZipException;
import java.util.zip.ZipFile;
import simpview.compare.Count;
import simpview.compare.SubmissionNames;
import simpview.compare.WithoutPictures;
import simpview.pages.SceneList;
import simpview.scene.PlainPath;

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
 * @param outside the links, not hidden, that lead out of the folder (not followed), each with where it leads as
 *     written in it: a link to a folder outside is not looked into, one named like a picture is not read
 */
record FolderListing(List<Path> pictures, int hidden, List<Path> unreadable, List<Path> others,
        Map<Path, Path> outside) {

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

    /** Whether a file (a path under the folder) is an archive (bob.zip, pages.tar.gz), which simpview does not open. */
    static boolean isArchive(String file) {
        return endsLike(Path.of(file), WithoutPictures.ARCHIVES);
    }

    /**
     * Whether a file (a path under the folder) is what a student of a class hands in instead of pictures, told from
     * what one student's upload holds beside its pictures: an archive (bob.zip), or a picture in a format simpview
     * does not read named for a page (page1.tif, page2.webp). A PDF, a document, a texture (sky.hdr) is not: a
     * write-up or a project's assets.
     */
    static boolean handedInInstead(String file) {
        Path path = Path.of(file);
        Path name = path.getFileName();
        return endsLike(path, WithoutPictures.ARCHIVES) || endsLike(path, UNREAD_ENDINGS) && !endsLike(path,
                List.of(".pdf")) && name != null && SubmissionNames.pageNumber(name.toString()).isPresent();
    }

    /**
     * The folders of {@code students} that a zip holds pictures in, at any depth of its entries' names, whichever
     * separator they were written with (class\alice\page1.png from Windows, class/alice/page1.png): a zip holding
     * two or more is a copy of the class (the teacher's class-backup.zip), not one student's pages. Empty for a file
     * that is no zip or cannot be read.
     */
    static Set<String> studentsInZip(Path zip, Set<String> students) {
        Set<String> found = new TreeSet<>();
        try (ZipFile file = new ZipFile(zip.toFile())) {
            for (Enumeration<? extends ZipEntry> entries = file.entries(); entries.hasMoreElements();) {
                String[] names = entries.nextElement().getName().split("[/\\\\]");
                String last = names[names.length - 1].toLowerCase(Locale.ROOT);
                if (names.length > 1 && PICTURE_ENDINGS.stream().anyMatch(last::endsWith)) {
                    for (int i = 0; i < names.length - 1; i++) {
                        if (students.contains(names[i])) {
                            found.add(names[i]);
                        }
                    }
                }
            }
        } catch (ZipException e) {
            return Set.of(); // no zip: what it holds is said as for any file
        } catch (IOException e) {
            return Set.of(); // unreadable: no class's copy that can be told
        }
        return found;
    }

    /** The folder a Mac's zip puts its resource forks in. */
    static final String MAC_LEFTOVERS = "__MACOSX";

    /**
     * The pictures under {@code dir}, hidden ones left out and counted, the files in formats it does not read, and
     * the links that lead out of {@code dir}.
     */
    static FolderListing of(Path dir) throws IOException {
        Path root = dir.toRealPath();
        List<Path> files = new ArrayList<>();
        Map<Path, Path> outside = new LinkedHashMap<>();
        // A link is taken as what it links to, as a file manager shows it, when that is in the folder: a link to a
        // folder is looked into (one that leads back to a folder on its way is not, as all it holds is listed
        // already), and a link to a picture is that picture. A link out of the folder is not followed: it may lead
        // anywhere on the disk (/usr: thousands of pictures, read for minutes), to what nobody handed in (the
        // teacher's files, which a row quoting what a file holds would show the student). A link to a folder
        // outside is left out, said by outsideNote; one named like a picture is listed, a row saying where it
        // leads. A link to nothing is listed as it is named: a picture that cannot be read, which says why, and
        // not a page silently missing.
        Files.walkFileTree(dir, EnumSet.of(FileVisitOption.FOLLOW_LINKS), Integer.MAX_VALUE,
                new SimpleFileVisitor<>() {
                    @Override
                    public FileVisitResult preVisitDirectory(Path folder, BasicFileAttributes attributes) {
                        if (!folder.equals(dir) && leadsOut(folder, root)) {
                            outside.put(folder, target(folder));
                            return FileVisitResult.SKIP_SUBTREE;
                        }
                        return FileVisitResult.CONTINUE;
                    }

                    @Override
                    public FileVisitResult visitFile(Path file, BasicFileAttributes attributes) {
                        if (attributes.isRegularFile() || attributes.isSymbolicLink()) {
                            files.add(file);
                        }
                        if (attributes.isRegularFile() && leadsOut(file, root)) {
                            outside.put(file, target(file));
                        }
                        return FileVisitResult.CONTINUE;
                    }

                    @Override
                    public FileVisitResult visitFileFailed(Path file, IOException e) throws IOException {
                        if (e instanceof FileSystemLoopException) {
                            return FileVisitResult.CONTINUE;
                        }
                        if (leadsOut(file, root)) { // a link to a folder outside that cannot be opened
                            outside.put(file, target(file));
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
        outside.keySet().removeIf(link -> hidden(dir.relativize(link)));
        return new FolderListing(shown, pictures.size() - shown.size(), unreadable, others, outside);
    }

    /**
     * Whether a path found in the walk is a link (or lies behind one) that leads out of the folder, whose real path
     * is {@code root}: false for one that leads nowhere (listed as it is named) and for one that cannot be told.
     */
    private static boolean leadsOut(Path path, Path root) {
        if (!Files.isSymbolicLink(path)) {
            return false; // the walk follows only links that stay inside, so what is not one is inside
        }
        try {
            return !path.toRealPath().startsWith(root);
        } catch (IOException e) {
            return false;
        }
    }

    /** Where a link leads, as it is written in it (../renders, /usr); the link itself when that cannot be read. */
    private static Path target(Path link) {
        try {
            return Files.readSymbolicLink(link);
        } catch (IOException | UnsupportedOperationException e) {
            return link;
        }
    }

    /**
     * Where the link that a picture of this listing is leads, when it leads out of the folder {@code dir} (the
     * picture is not read: its row says so): "bob/page2.png is a link to /etc/passwd, outside subs: ...". Empty
     * for any other picture.
     */
    Optional<String> linkOut(Path picture, Path dir) {
        Path target = outside.get(picture);
        return target == null ? Optional.empty() : Optional.of(PlainPath.of(picture) + " is a link to " + target
                + ", which is outside " + folderNamed(dir) + ": simpview follows no link out of the folder it grades; "
                + "put the picture itself in its place");
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

    /**
     * What the batch says of the links to folders outside {@code dir} it did not look into, once: "" when there
     * were none. "bob/stuff is a link to /usr, a folder outside subs: not looked into (...)".
     */
    String outsideNote(Path dir) {
        List<Map.Entry<Path, Path>> folders = outside.entrySet().stream().filter(e -> Files.isDirectory(e.getKey()))
                .toList();
        if (folders.isEmpty()) {
            return "";
        }
        String why = " (simpview follows no link out of the folder it grades: put what it leads to itself in its place)";
        if (folders.size() == 1) {
            return dir.relativize(folders.get(0).getKey()) + " is a link to " + folders.get(0).getValue()
                    + ", a folder outside " + folderNamed(dir) + ": it was not looked into" + why;
        }
        List<String> named = folders.stream().map(e -> dir.relativize(e.getKey()) + " (to " + e.getValue() + ")")
                .toList();
        return Count.of(folders.size(), "link") + " to folders outside " + folderNamed(dir)
                + " were not looked into: " + UsageWords.firstThree(named) + why;
    }

    /**
     * The folder graded as a note of a link out of it names it: as it was given, without "." parts, or in full when
     * it was given as "." ("outside ." would name nothing).
     */
    private static String folderNamed(Path dir) {
        Path plain = PlainPath.of(dir);
        return plain.toString().equals(".") ? dir.toAbsolutePath().normalize().toString() : plain.toString();
    }

    /** What the batch says of the hidden pictures it left out, once: "" when there were none. */
    String hiddenNote() {
        return hidden == 0 ? "" : Count.of(hidden, "hidden picture") + " left out (a name starting "
                + "with '.', or in a " + MAC_LEFTOVERS + " folder: a Mac's zip leftovers)";
    }
}

package simpview.cli;

import static simpview.cli.CompareBatch.CSV;
import static simpview.cli.CompareBatch.DIFFS;
import static simpview.cli.CompareBatch.TABLE;
import static simpview.cli.CompareBatch.TOTALS;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import simpview.cli.CompareBatch.Outputs;
import simpview.compare.Count;
import simpview.compare.HtmlReport;
import simpview.compare.JUnitResults;
import simpview.compare.Rubric;
import simpview.compare.RubricRule;
import simpview.compare.SubmissionNames;
import simpview.compare.WithoutPictures;
import simpview.pages.SceneList;

/**
 * What a student or a class handed in, in the folder a batch is given: which folder in it is the class's, whose
 * first-level folders are the submissions (a class unzipped into a folder of its own, or unzipped flat from a
 * Windows zip); which of its pictures and other files were handed in, and which are the teacher's (the rubric's
 * accepted alternates, a folder of reports) or some batch's own output; and which submissions hold no picture.
 * Once it has found a class unzipped flat, it names each picture without the class's folder.
 */
final class HandedIn {

    private final Rubric rubric;
    private final PrintWriter err;
    /** What its messages start with: the command that runs the batch ("simpview compare: "). */
    private final String says;
    /**
     * The folder a class was zipped in on Windows and unzipped flat, as its files' names begin ("class\\", from
     * class\alice\page1.png), when {@link #classFolder} found the class in it; "" otherwise. Its pictures are
     * named without it, as those of a class unzipped into folders are named from the class's folder.
     */
    private String flatClass = "";

    /** What was handed in, the rubric's alternates being the teacher's; said on {@code err} after {@code says}. */
    HandedIn(Rubric rubric, PrintWriter err, String says) {
        this.rubric = rubric;
        this.err = err;
        this.says = says;
    }

    /**
     * What was found handed in to the folder graded: its {@code listing}; the {@code pictures} handed in, those of the
     * class's folder; the {@code others}, the files that are no picture simpview reads, by their paths in the folder
     * graded; the submissions {@code withoutPictures}; and the files taken for the {@code teachers}, each with why.
     */
    record Found(FolderListing listing, List<Path> pictures, List<String> others,
            List<WithoutPictures> withoutPictures, List<String> teachers) {
    }

    /**
     * The folder a teacher's batch of {@code dir} grades, whose first-level folders are the submissions: {@code dir}
     * itself, or, when every picture in it is in one folder inside it (a class's folder unzipped into a folder of
     * its own: subs/class/alice/page1.png, subs/class/bob/page1.png) and every picture of that folder is in its
     * folders, two or more of them, that folder, said on stderr. Graded as {@code dir}, the whole class would be
     * one submission, each page counted once (the first student's), every other picture not counted, and the run
     * could pass whatever the others handed in. A chain of such single folders is followed down; a student's own
     * folder nested so (subs/A2/page1.png) is graded as given, and so is one whose folders hold no page (nor scene
     * of {@code sceneFolder}, when that is a folder) twice (subs/output/part1/page1.png, subs/output/part2/page5.png:
     * one student's parts, not a class's students; nor a class of one, subs/class/alice/A2, subs/class/alice/A3).
     * The batch's own output folders are left out.
     */
    Path classFolder(Path dir, Outputs outputs, Path sceneFolder) {
        if (outputs.student() || !Files.isDirectory(dir)) {
            return dir;
        }
        List<Path> pictures;
        List<Path> alternates;
        try {
            alternates = alternatesInside(dir);
            List<Path> names = picturesHandedIn(dir, FolderListing.of(dir), teachersFolders(dir, outputs)).stream()
                    .map(dir::relativize).toList();
            // a Windows zip's names unzipped flat: class\alice\page1.png is in class/alice, as unzipped into folders
            List<String> refused = names.stream().filter(p -> asFolders(p).isEmpty()).map(Path::toString).toList();
            if (!refused.isEmpty()) {
                err.println(says + UsageWords.firstThree(refused.stream().map(r -> dir.resolve(r).toString())
                        .toList()) + (refused.size() == 1 ? ": its name leads" : ": their names lead") + " out of "
                        + dir + " ('..', a drive such as C: or a '\\' at the start) if its backslashes are read as "
                        + "folders, as a Windows zip writes them: they are not, and it is in no student's folder");
            }
            pictures = names.stream().map(HandedIn::asFolders).flatMap(Optional::stream).toList();
        } catch (IOException | UncheckedIOException e) {
            return dir; // said when the batch lists it
        }
        Set<String> scenes = sceneFolder != null && Files.isDirectory(sceneFolder)
                ? CompareBatch.scenesIn(sceneFolder).keySet() : Set.of();
        String handed = alternates.isEmpty() ? "every picture in " + dir : "every picture handed in to " + dir
                + " (the rubric's accepted alternates, in " + UsageWords.joined(alternates.stream()
                        .map(Path::toString).toList(), "and") + ", are the teacher's)";
        Path inside = Path.of("");
        for (int depth = 0; !pictures.isEmpty(); depth++) {
            int level = depth;
            if (pictures.stream().anyMatch(p -> p.getNameCount() <= level + 1)) {
                return dir; // a picture at this folder's top: it is a submission's, or the class's folder is here
            }
            Set<String> folders = pictures.stream().map(p -> p.getName(level).toString())
                    .collect(Collectors.toCollection(TreeSet::new));
            if (folders.size() > 1) {
                Optional<String> theClass = theClassBesideOthers(pictures, level, scenes);
                if (theClass.isPresent()) {
                    Path graded = gradedIn(dir, inside.resolve(theClass.get()));
                    Path here = dir.resolve(inside);
                    List<Path> in = pictures.stream().filter(p -> p.getName(level).toString().equals(theClass.get()))
                            .toList();
                    List<String> others = folders.stream().filter(f -> !f.equals(theClass.get()))
                            .map(f -> here.resolve(f).toString()).toList();
                    err.println(says + "the pictures in " + dir + " are the students' of one class, in "
                            + shown(graded) + ": its folders (" + UsageWords.firstThree(studentsOf(in, level + 1))
                            + ") are graded as the submissions" + asDir(graded) + "; "
                            + Count.of(pictures.size() - in.size(), "picture") + " beside it, in "
                            + UsageWords.joined(others, "and") + ", " + (pictures.size() - in.size() == 1 ? "is" : "are")
                            + " taken for the teacher's (reference pictures: no student's folder of a class) and not "
                            + "graded. Were they a student's, grade that folder with --dir of its own, or move it into "
                            + shown(graded));
                    return graded;
                }
                if (depth == 0 || !someNameInTwo(pictures, level, scenes)) {
                    return dir; // a class's folder as given, or one student's pictures foldered by part
                }
                Path graded = gradedIn(dir, inside);
                err.println(says + handed + " is in " + shown(graded) + ": its folders ("
                        + UsageWords.firstThree(studentsOf(pictures, level))
                        + ") are graded as the submissions" + asDir(graded));
                return graded;
            }
            inside = inside.resolve(folders.iterator().next());
        }
        return dir;
    }

    /**
     * The folder {@code inside} names under {@code dir}, as far as it is folders on disk; the rest of it, folders
     * only in its files' names (a Windows zip unzipped flat: class\alice\page1.png), becomes {@link #flatClass}.
     */
    private Path gradedIn(Path dir, Path inside) {
        Path real = dir;
        int at = 0;
        while (at < inside.getNameCount() && Files.isDirectory(real.resolve(inside.getName(at)))) {
            real = real.resolve(inside.getName(at));
            at++;
        }
        StringBuilder flat = new StringBuilder();
        for (int k = at; k < inside.getNameCount(); k++) {
            flat.append(inside.getName(k)).append('\\');
        }
        flatClass = flat.toString();
        return real;
    }

    /** The class's folder {@code graded} as a teacher finds it: with the folder in its files' names, if any. */
    private String shown(Path graded) {
        return flatClass.isEmpty() ? graded.toString() : graded.resolve(flatClass).toString() + " (folders in its "
                + "files' names, as a Windows zip writes them, unzipped flat)";
    }

    /** ", as --dir F grades them", for a class's folder on disk; nothing for one in its files' names alone. */
    private String asDir(Path graded) {
        return flatClass.isEmpty() ? ", as --dir " + graded + " grades them" : "";
    }

    /**
     * A path under a folder as the folders in its names say, backslashes (a Windows zip's, unzipped flat) read as
     * the folders they stand for: class\alice\page1.png is class/alice/page1.png. Empty when a name would lead
     * out of the folder or start at a root or drive ("..", "\\x", "C:"): such a name is refused as folders.
     */
    private static Optional<Path> asFolders(Path relative) {
        String path = relative.toString();
        if (path.indexOf('\\') < 0) {
            return Optional.of(relative);
        }
        String[] names = path.split("[/\\\\]", -1);
        for (String name : names) {
            if (name.isEmpty() || name.equals(".") || name.equals("..") || name.matches("[A-Za-z]:")) {
                return Optional.empty();
            }
        }
        return Optional.of(Path.of(names[0], Arrays.copyOfRange(names, 1, names.length)));
    }

    /** The folders at {@code level} of the pictures' paths, in natural order: the students of a class's folder. */
    private static List<String> studentsOf(List<Path> pictures, int level) {
        return pictures.stream().map(p -> p.getName(level).toString()).distinct().sorted(SceneList.NATURAL_ORDER)
                .toList();
    }

    /**
     * The one folder at {@code level} of the pictures' paths that is a class's folder beside others that are not
     * (subs/class/alice, subs/class/bob beside subs/reference/page1.png, the teacher's pictures): its pictures are
     * all in its own folders, two or more of which hold a picture named alike ({@link #someNameInTwo}), and no two
     * of the other folders at this level do (they would be students of a class themselves, as a class's folder
     * beside subs/late/cy and subs/late/dee is: ann and bob at its top are two students). Empty when there is
     * none, or more than one.
     */
    private static Optional<String> theClassBesideOthers(List<Path> pictures, int level, Set<String> scenes) {
        Map<String, List<Path>> byFolder = new TreeMap<>();
        pictures.forEach(p -> byFolder.computeIfAbsent(p.getName(level).toString(), f -> new ArrayList<>()).add(p));
        List<String> classes = byFolder.entrySet().stream()
                .filter(e -> e.getValue().stream().allMatch(p -> p.getNameCount() > level + 2)
                        && e.getValue().stream().map(p -> p.getName(level + 1)).distinct().count() > 1
                        && someNameInTwo(e.getValue(), level + 1, scenes))
                .map(Map.Entry::getKey).toList();
        if (classes.size() != 1) {
            return Optional.empty();
        }
        List<Path> others = pictures.stream().filter(p -> !p.getName(level).toString().equals(classes.get(0)))
                .toList();
        return someNameInTwo(others, level, scenes) ? Optional.empty() : Optional.of(classes.get(0));
    }

    /**
     * Whether two of the folders at {@code level} of the pictures' paths hold a picture named alike: of the same
     * scene of {@code scenes} (pageA.png and bob_pageA.png), of the same page (page1.png and alice_page1.png), or,
     * naming neither, of the same name; in a folder none of whose pictures names a page or scene, a number names
     * its page (p1.png). Each student of a class hands in the same pages; one student's pictures foldered by part
     * (output/part1/page1.png, output/part2/page5.png, a draft part2/p1.png) are each page once, and are one
     * submission.
     */
    private static boolean someNameInTwo(List<Path> pictures, int level, Set<String> scenes) {
        // the folders some picture of which names a page or a scene
        Set<String> naming = new HashSet<>();
        for (Path picture : pictures) {
            String name = picture.getFileName().toString();
            if (SubmissionNames.sceneName(name, scenes).isPresent() || SubmissionNames.pageNumber(name).isPresent()) {
                naming.add(picture.getName(level).toString());
            }
        }
        Map<String, Set<String>> folders = new HashMap<>();
        for (Path picture : pictures) {
            String name = picture.getFileName().toString();
            Optional<String> scene = SubmissionNames.sceneName(name, scenes);
            OptionalInt page = SubmissionNames.pageNumber(name);
            // a picture named like no page by its number (p1.png, Page-one 1.png) is taken for that page in a folder
            // that names no page at all: two students, one of whom named every page so, were one student's parts,
            // the other's pages never asked. Beside a named page (part2/page2.png) it is a draft of one student's.
            OptionalInt number = page.isPresent() || naming.contains(picture.getName(level).toString()) ? page
                    : SubmissionNames.numberIn(name);
            String key = scene.isPresent() ? "scene " + scene.get() : number.isPresent() ? "page " + number.getAsInt()
                    : SubmissionNames.stem(name).toLowerCase(Locale.ROOT);
            folders.computeIfAbsent(key, k -> new HashSet<>()).add(picture.getName(level).toString());
        }
        return folders.values().stream().anyMatch(in -> in.size() > 1);
    }

    /**
     * What was handed in to {@code dir}, the folder graded: the pictures in the class's folder (those beside it are
     * said on stderr and left out), the other files and the submissions without a picture. The batch's own output,
     * the rubric's alternates and the reports of earlier runs are none of it.
     *
     * @throws IOException when the folder cannot be listed (or an {@link UncheckedIOException})
     */
    Found find(Path dir, Outputs outputs) throws IOException {
        List<String> teachers = new ArrayList<>();
        List<Path> written = teachersFolders(dir, outputs);
        FolderListing listing = FolderListing.of(dir);
        List<Path> all = picturesHandedIn(dir, listing, written);
        List<Path> inClass = all.stream().filter(p -> dir.relativize(p).toString().startsWith(flatClass))
                .toList();
        if (inClass.size() < all.size()) {
            err.println(says + UsageWords.firstThree(all.stream().filter(p -> !inClass.contains(p))
                    .map(Path::toString).toList()) + ": beside the class in " + shown(dir)
                    + ", not in it: not graded");
        }
        List<String> others = othersHandedIn(dir, listing, written, outputs);
        List<WithoutPictures> withoutPictures = withoutPictures(dir, inClass, others, written, outputs, teachers);
        return new Found(listing, inClass, others, withoutPictures, teachers);
    }

    /**
     * Says on stderr what a teacher should know of what was found in {@code dir} before its results: the hidden files
     * left out, the rubric's alternates inside it, the files taken for the teacher's, the links out of it, and a class
     * of which one student alone handed in pictures.
     */
    void sayWhatWasFound(Path dir, Found found) {
        FolderListing listing = found.listing();
        if (!listing.hiddenNote().isEmpty()) {
            err.println(says + listing.hiddenNote());
        }
        try {
            List<Path> alternates = alternatesInside(dir);
            if (!alternates.isEmpty()) {
                err.println(says + "the rubric's accepted alternates, in " + UsageWords.joined(alternates.stream()
                        .map(a -> dir.resolve(a).toString()).toList(), "and") + ", are the teacher's pictures: read "
                        + "as alternates, not graded as a submission");
            }
        } catch (IOException e) {
            // the folder was listed just now; a rubric's folder that cannot be told is no note
        }
        if (!found.teachers().isEmpty()) {
            err.println(says + "taken for the teacher's, not a student's, and not graded: " + String.join("; ",
                    found.teachers()) + "; a student who hands in a zip has it in a folder of their own");
        }
        if (!listing.outsideNote(dir).isEmpty()) {
            err.println(says + listing.outsideNote(dir));
        }
        List<String> studentsWithPictures = found.pictures().stream()
                .map(p -> JUnitResults.submission(name(dir, p))).distinct().toList();
        List<String> studentsWithout = found.withoutPictures().stream().map(WithoutPictures::submission)
                .filter(w -> !w.isEmpty()).toList();
        if (studentsWithPictures.size() == 1 && !studentsWithout.isEmpty()) {
            err.println(says + "only " + studentsWithPictures.get(0) + " in " + dir + " holds pictures; "
                    + UsageWords.firstThree(studentsWithout) + (studentsWithout.size() == 1 ? ", which holds" : ", which hold")
                    + " only what a class's pictures may be handed in as (a zip, a page in a format simpview does not read), "
                    + (studentsWithout.size() == 1 ? "is" : "are") + " graded as " + Count.of(studentsWithout.size(),
                    "student") + " of the class who handed in no picture (were " + dir + " one student's folder, "
                    + "grade --dir " + dir.resolve(studentsWithPictures.get(0)) + ")");
        }
    }

    /**
     * Whether the pictures handed in to {@code dir} are one submission however they are foldered: those of a
     * student's own folder ({@code check}) are; so are a teacher's folder's, when it holds pictures at its top and in
     * one folder ({@link #theOneFolder}, said on stderr) and not each picture is a submission of its own
     * ({@code eachAlone}: one scene for every picture).
     */
    boolean oneStudent(Path dir, Outputs outputs, List<Path> pictures, boolean eachAlone) {
        Optional<String> theOneFolder = outputs.student() || eachAlone ? Optional.empty() : theOneFolder(dir, pictures);
        theOneFolder.ifPresent(folder -> err.println(says + dir + " holds pictures at its top and in one folder, "
                + folder + ": they are graded as one student's submission (were they two students', put each one's "
                + "pictures in a folder of its own)"));
        return outputs.student() || theOneFolder.isPresent();
    }

    /**
     * A picture's name in the folder graded: its path under {@code dir}, without the folder of a class unzipped flat
     * ({@link #flatClass}): alice\page1.png for class\alice\page1.png.
     */
    String name(Path dir, Path picture) {
        String relative = dir.relativize(picture).toString();
        return relative.startsWith(flatClass) ? relative.substring(flatClass.length()) : relative;
    }

    /** The file name of a path relative to the submissions folder. */
    static String fileName(String relative) {
        Path name = Path.of(relative).getFileName();
        String file = name == null ? relative : name.toString();
        // alice\page1.png, unzipped flat from a Windows zip: its name is page1.png, in the folder alice
        return file.substring(file.lastIndexOf('\\') + 1);
    }

    /**
     * The file of a picture's name in the folder graded ({@link #name}), with the folder of a class unzipped flat:
     * class\alice\page1.png for alice\page1.png.
     */
    Path file(Path dir, String relative) {
        return dir.resolve(flatClass + relative);
    }

    /**
     * The folders under {@code dir} whose pictures nobody handed in, relative to it: this batch's own (its diff
     * images, {@link #ownFolders}) and the rubric's folders of accepted alternates, the teacher's pictures, when
     * they are inside it (subs/alternates beside subs/class): read as alternates, never graded as a submission.
     */
    private List<Path> teachersFolders(Path dir, Outputs outputs) throws IOException {
        List<Path> folders = new ArrayList<>(ownFolders(dir, outputs));
        folders.addAll(alternatesInside(dir));
        return folders;
    }

    /**
     * The folder under {@code dir} that this batch writes pictures into, relative to it: the diffs folder of its
     * output folder (--out-dir, or --html without it) when that is inside {@code dir}, wherever inside (the class's
     * folder itself, one student's folder, a folder of its own). Its pictures are the diff images of an earlier
     * run, not pictures to compare. Nothing else of the output folder is left out: a teacher who writes the reports
     * into the class's folder, or into a student's, still has that folder graded; the tables and the web report
     * beside them are no pictures.
     */
    private static List<Path> ownFolders(Path dir, Outputs outputs) throws IOException {
        Path root = dir.toRealPath();
        Path output = outputs.outDir();
        if (output == null || !Files.isDirectory(output)) {
            return List.of(); // not there yet: no pictures in it
        }
        Path place = output.toRealPath();
        return place.startsWith(root) ? List.of(root.relativize(place).resolve(DIFFS)) : List.of();
    }

    /** The rubric's folders of accepted alternates that are inside {@code dir}, relative to it (none: empty). */
    private List<Path> alternatesInside(Path dir) throws IOException {
        Path root = dir.toRealPath();
        Set<Path> inside = new TreeSet<>();
        List<RubricRule> rules = new ArrayList<>(rubric.rules());
        rules.add(rubric.defaults());
        for (RubricRule rule : rules) {
            Path folder = rule.alternates();
            if (folder != null && Files.isDirectory(folder) && folder.toRealPath().startsWith(root)
                    && !folder.toRealPath().equals(root)) {
                inside.add(root.relativize(folder.toRealPath()));
            }
        }
        return new ArrayList<>(inside);
    }

    /**
     * The pictures of a listing of {@code dir} that were handed in: those in the folders this batch writes into
     * ({@code written}, relative to it) and the diff images of other runs are its output.
     */
    private static List<Path> picturesHandedIn(Path dir, FolderListing listing, List<Path> written) {
        return listing.pictures().stream()
                .filter(f -> {
                    Path p = dir.relativize(f);
                    return written.stream().noneMatch(p::startsWith) && !inOutputsDiffs(dir, p);
                }).toList();
    }

    /**
     * Whether a picture (relative to {@code dir}) is in the diffs folder of some batch's output folder, one
     * beside its compare.csv: another run's diff images (check with --out-dir, then compare with another).
     */
    private static boolean inOutputsDiffs(Path dir, Path picture) {
        for (Path folder = picture.getParent(); folder != null; folder = folder.getParent()) {
            if (folder.getFileName().toString().equals(DIFFS)
                    && Files.isRegularFile(dir.resolve(folder).resolveSibling(CSV))) {
                return true;
            }
        }
        return false;
    }

    /**
     * The files handed in that are no picture simpview reads, by their paths in the folder graded (in the class
     * of one unzipped flat): the listing's others but the batch's own results, and the tables and diff images of
     * this run or of an earlier one.
     */
    private List<String> othersHandedIn(Path dir, FolderListing listing, List<Path> written, Outputs outputs) {
        Set<Path> results = outputs.reports().stream().map(r -> r.file().toAbsolutePath().normalize())
                .collect(Collectors.toSet());
        return listing.others().stream()
                .filter(f -> !results.contains(f.toAbsolutePath().normalize()))
                .map(dir::relativize)
                .filter(p -> written.stream().noneMatch(p::startsWith) && !isOutputsTable(dir, p))
                .map(Path::toString).filter(f -> f.startsWith(flatClass)).map(f -> f.substring(flatClass.length()))
                .toList();
    }

    /**
     * Whether a file (relative to {@code dir}) is a table or web report some batch wrote: compare.md, compare.csv,
     * totals.csv or index.html beside a compare.csv. Only those: the folder they are in may be a student's, or the
     * class's.
     */
    private static boolean isOutputsTable(Path dir, Path file) {
        String name = file.getFileName().toString();
        Path folder = file.getParent() == null ? dir : dir.resolve(file.getParent());
        return (name.equals(TABLE) || name.equals(CSV) || name.equals(TOTALS) || name.equals(HtmlReport.INDEX))
                && Files.isRegularFile(folder.resolve(CSV));
    }

    /**
     * The submissions without a picture, each with what it holds instead (its files, hidden ones and the batch's
     * own results left out): the whole folder when it holds none; and of a class's folder, one whose pictures are
     * in first-level folders (at least two of them), each first-level folder that holds none, so that a student who
     * handed in a zip is not left out of the results but lacks every page. A student's own folder ({@code check}),
     * or one whose pictures are at its top beside a src/ folder, is one submission: its other folders are none. A
     * folder of reports (this run's, or one holding an earlier run's compare.csv) is none whatever it holds: the zips
     * and documents in it, the teacher's (class-backup.zip), are added to {@code teachers}.
     */
    private List<WithoutPictures> withoutPictures(Path dir, List<Path> pictures, List<String> others,
            List<Path> written, Outputs outputs, List<String> teachers) throws IOException {
        Set<Path> results = outputs.reports().stream().map(r -> r.file().toAbsolutePath().normalize())
                .collect(Collectors.toSet());
        List<WithoutPictures> without = new ArrayList<>();
        if (pictures.isEmpty()) {
            without.add(new WithoutPictures("", others));
            return without;
        }
        // the first-level folders that hold pictures; alice\page1.png, from a Windows zip, is in alice
        List<String> relatives = pictures.stream().map(p -> name(dir, p)).toList();
        Set<String> withPictures = relatives.stream().filter(HandedIn::inAFolder).map(JUnitResults::submission)
                .collect(Collectors.toSet());
        // a class of which one student handed in pictures, the others a zip or page1.tif; or one student's folder of
        // pictures beside a write-up (report/writeup.pdf), a project's assets (assets/sky.hdr)
        boolean oneFolderOnly = withPictures.size() == 1 && relatives.stream().allMatch(HandedIn::inAFolder);
        if (outputs.student() || withPictures.size() < 2 && !oneFolderOnly || !Files.isDirectory(dir)) {
            return without;
        }
        // the folders this run writes its reports in (--junit junit/results.xml): made before they are listed
        Path root = dir.toAbsolutePath().normalize();
        Set<String> reportFolders = results.stream()
                .filter(r -> r.startsWith(root) && root.relativize(r).getNameCount() > 1)
                .map(r -> root.relativize(r).getName(0).toString()).collect(Collectors.toSet());
        Set<String> folders = new TreeSet<>(SceneList.NATURAL_ORDER);
        if (flatClass.isEmpty()) { // a class unzipped flat has its folders in its files' names alone
            try (Stream<Path> entries = Files.list(dir)) {
                entries.filter(Files::isDirectory).forEach(p -> folders.add(p.getFileName().toString()));
            }
        }
        // and the folders in the names of a Windows zip's files unzipped flat (carol\carol.zip)
        others.stream().filter(f -> Path.of(f).getNameCount() == 1 && inAFolder(f))
                .forEach(f -> folders.add(JUnitResults.submission(f)));
        folders.removeIf(name -> FolderListing.hidden(Path.of(name)) || withPictures.contains(name));
        for (String folder : folders) {
            List<String> holds = others.stream().filter(f -> JUnitResults.submission(f).equals(folder)).toList();
            // the reports' folder of this run or of an earlier one (its tables and diff images left out above)
            boolean reports = reportFolders.contains(folder) || Files.isRegularFile(dir.resolve(folder).resolve(CSV))
                    || written.stream().anyMatch(w -> w.startsWith(folder))
                    || folder.equals(DIFFS) && Files.isRegularFile(dir.resolve(CSV));
            // a folder of reports, a rubric or scripts is no student's: one that holds what a student may hand in
            // pictures as (a zip, a .webp, a document), is, and so is one that is empty and holds no reports.
            // When only one folder holds pictures, only one that holds nothing but archives and pictures named for
            // a page simpview does not read is (bob.zip, page1.tif): an empty build/, a report/ with a PDF or an
            // assets/ of textures beside output/ is one student's submission (a Gradescope upload), not a class of
            // students lacking every page
            // A folder of reports is the teacher's whatever else it holds: a class-backup.zip kept beside the
            // reports (--out-dir class/output) is no student who handed in a zip
            // nor is one that holds nothing but zips of the class's own students' folders (backup/class-backup.zip)
            boolean backups = !holds.isEmpty() && holds.stream().allMatch(f -> FolderListing.studentsInZip(
                    dir.resolve(flatClass + f), withPictures).size() > 1);
            if (reports || backups) {
                holds.stream().filter(FolderListing::mayHoldPictures).forEach(f -> teachers.add(dir.resolve(flatClass + f) + (reports
                        ? " (in a folder of reports)" : " (a zip of the class's own folders "
                        + UsageWords.firstThree(List.copyOf(FolderListing.studentsInZip(dir.resolve(flatClass + f), withPictures)))
                        + ": a copy of the class)")));
                continue;
            }
            boolean student = oneFolderOnly ? !holds.isEmpty() && holds.stream().allMatch(FolderListing::handedInInstead)
                    : holds.stream().anyMatch(FolderListing::mayHoldPictures) || holds.isEmpty();
            if (student) {
                without.add(new WithoutPictures(folder, holds));
            }
        }
        return without;
    }

    /** Whether a file's path in the folder graded is in a folder: alice/page1.png, or alice\page1.png from a Windows zip. */
    private static boolean inAFolder(String relative) {
        return relative.indexOf('/') >= 0 || relative.indexOf('\\') >= 0;
    }

    /**
     * The one folder of a teacher's folder that is one student's though its pictures are foldered: some of its
     * pictures are at its top, and the others in one folder (page1.png ... page7.png beside renders/page8.png);
     * empty for any other. Taken as a class's, its top and its folder were two submissions, each lacking the
     * other's pages: the run failed and JUnit counted seven pages missing where results.json scored all eight and
     * check passed. A class's folder has its pictures in two or more first-level folders; one with all its
     * pictures at its top is one submission as it is. The folders are the submissions the table, JUnit and the web
     * report name: renders\page8.png (unzipped from a Windows zip) is in renders.
     */
    private Optional<String> theOneFolder(Path dir, List<Path> pictures) {
        Set<String> submissions = pictures.stream().map(p -> JUnitResults.submission(name(dir, p)))
                .collect(Collectors.toCollection(TreeSet::new));
        return submissions.size() == 2 && submissions.remove(JUnitResults.TOP)
                ? Optional.of(submissions.iterator().next()) : Optional.empty();
    }
}

package simpview.pages;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import simpview.scene.FileProblem;
import simpview.scene.PlainPath;

/**
 * Scenes named on the command line, as pages in the order given: a folder
 * stands for its .simp files in natural name order (page-a1, page-a2, ...,
 * page-b1; pageA ... pageJ; page2 before page10), and a scene may be named
 * without ".simp", as the course's programs took it.
 */
public final class SceneList {

    /** Names compared with runs of digits as numbers, and otherwise letter by letter, case first ignored. */
    public static final Comparator<String> NATURAL_ORDER = SceneList::compareNaturally;

    private SceneList() {
    }

    /**
     * The scene files the arguments name, in order.
     *
     * @throws IllegalArgumentException naming the first argument that is no scene and no folder of scenes
     */
    public static List<Path> of(List<Path> arguments) {
        List<Path> scenes = new ArrayList<>();
        for (Path argument : arguments) {
            if (Files.isDirectory(argument)) {
                // a link there that leads to no file is a scene asked for: named, and its error said, not passed over
                List<Path> inFolder = folder(argument, true);
                if (inFolder.isEmpty()) {
                    throw new IllegalArgumentException("the folder " + argument + " holds no .simp files");
                }
                scenes.addAll(inFolder);
            } else {
                scenes.add(scene(argument));
            }
        }
        return scenes;
    }

    /** A scene file as named, or with ".simp" added when only that exists. */
    public static Path scene(Path named) {
        if (Files.isRegularFile(named)) {
            return named;
        }
        Path withExtension = named.resolveSibling(named.getFileName() + ".simp");
        if (!named.toString().endsWith(".simp") && Files.isRegularFile(withExtension)) {
            return withExtension;
        }
        String link = FileProblem.brokenLink(named);
        if (link != null) { // there, as ls shows it, but leading to no file
            throw new IllegalArgumentException("no scene " + named + ": it " + link);
        }
        throw new IllegalArgumentException("no scene " + named + (named.toString().endsWith(".simp") ? ""
                : " (nor " + withExtension.getFileName() + ")") + " in " + named.toAbsolutePath().getParent());
    }

    /** The .simp files of a folder, in natural name order. */
    public static List<Path> folder(Path dir) {
        return folder(dir, false);
    }

    /** The .simp files of a folder, and with {@code brokenLinks} the links named so that lead to no file. */
    private static List<Path> folder(Path dir, boolean brokenLinks) {
        List<Path> scenes = new ArrayList<>();
        try (DirectoryStream<Path> files = Files.newDirectoryStream(dir, "*.simp")) {
            for (Path f : files) {
                if (Files.isRegularFile(f) || brokenLinks && Files.isSymbolicLink(f) && !Files.exists(f)) {
                    scenes.add(PlainPath.of(f)); // the folder "." lists bad.simp, not ./bad.simp
                }
            }
        } catch (IOException e) {
            throw new IllegalArgumentException("cannot read the folder " + dir + ": " + FileProblem.ofFolder(e));
        }
        scenes.sort(Comparator.comparing(p -> p.getFileName().toString(), NATURAL_ORDER));
        return scenes;
    }

    /** The name a scene's picture takes: its file name with .png for .simp. */
    public static String pictureName(Path scene) {
        String name = scene.getFileName().toString();
        return (name.endsWith(".simp") ? name.substring(0, name.length() - 5) : name) + ".png";
    }

    /**
     * The names the scenes' pictures take in one folder, in order: each its
     * {@link #pictureName}, but where scenes of different folders share a
     * name (ignoring case, as some file systems do: cube.simp of
     * course-simp-a3 and of course-simp-a4), each of those is named by its
     * folder too, FOLDER-NAME.png (course-simp-a3-cube.png).
     */
    public static List<String> pictureNames(List<Path> scenes) {
        Map<String, Integer> named = new HashMap<>();
        for (Path scene : scenes) {
            named.merge(pictureName(scene).toLowerCase(Locale.ROOT), 1, Integer::sum);
        }
        List<String> names = new ArrayList<>();
        for (Path scene : scenes) {
            String name = pictureName(scene);
            Path folder = scene.toAbsolutePath().normalize().getParent();
            boolean shared = named.get(name.toLowerCase(Locale.ROOT)) > 1;
            boolean byFolder = shared && folder != null && folder.getFileName() != null;
            names.add(byFolder ? folder.getFileName() + "-" + name : name);
        }
        return names;
    }

    private static int compareNaturally(String a, String b) {
        int i = 0;
        int j = 0;
        while (i < a.length() && j < b.length()) {
            char ca = a.charAt(i);
            char cb = b.charAt(j);
            if (Character.isDigit(ca) && Character.isDigit(cb)) {
                int endA = digitsEnd(a, i);
                int endB = digitsEnd(b, j);
                int byValue = compareNumbers(a.substring(i, endA), b.substring(j, endB));
                if (byValue != 0) {
                    return byValue;
                }
                i = endA;
                j = endB;
            } else {
                int byLetter = Character.compare(Character.toLowerCase(ca), Character.toLowerCase(cb));
                if (byLetter != 0) {
                    return byLetter;
                }
                i++;
                j++;
            }
        }
        int byLength = Integer.compare(a.length() - i, b.length() - j);
        return byLength != 0 ? byLength : a.compareTo(b);
    }

    private static int digitsEnd(String s, int from) {
        int i = from;
        while (i < s.length() && Character.isDigit(s.charAt(i))) {
            i++;
        }
        return i;
    }

    /** Two runs of digits by their value, however many leading zeros. */
    private static int compareNumbers(String x, String y) {
        String a = x.replaceFirst("^0+(?=.)", "");
        String b = y.replaceFirst("^0+(?=.)", "");
        return a.length() != b.length() ? Integer.compare(a.length(), b.length()) : a.compareTo(b);
    }
}

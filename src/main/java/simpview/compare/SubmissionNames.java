package simpview.compare;

import java.util.Collection;
import java.util.Locale;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Which page or scene a submitted picture is of, from its file name:
 * page3.png, Page_3.png, alice-page03.png and page3_mesh.png are page 3;
 * pageC.png, pageC_v2.png and pageJ_tomsPageJ.png are the scenes pageC and
 * tomsPageJ, page-a2.png the scene page-a2.
 */
public final class SubmissionNames {

    private static final Pattern PAGE = Pattern.compile("(?i)(?<![a-z])page[\\s_-]*0*([1-9][0-9]*)(?![0-9])");

    /** "a1", "A1", "assignment1", "assignment-1" as a word of its own: the first assignment's pages. */
    private static final Pattern FIRST_ASSIGNMENT = Pattern.compile("(?i)(?<![a-z0-9])(a|assignment[\\s_-]*)0*1(?![0-9])");

    private SubmissionNames() {
    }

    /** Whether a file name says it is one of the first assignment's pages, like a1-page2.png. */
    public static boolean namesFirstAssignment(String fileName) {
        return FIRST_ASSIGNMENT.matcher(stem(fileName)).find();
    }

    /**
     * Whether a file name is a page's name and nothing else: page3.png, Page_3.png, page 03.jpg for page 3
     * (not page3 copy.png, page3_v2.png or old_page3.png). Of several pictures of one page, it is the one
     * that counts.
     */
    public static boolean isPageName(String fileName, int page) {
        return stem(fileName).strip().matches("(?i)page[\\s_-]*0*" + page);
    }

    /** The same for a page of the first assignment: a1-page2.png, A1_Page_2.png, assignment1-page2.png. */
    public static boolean isFirstAssignmentPageName(String fileName, int page) {
        return stem(fileName).strip().matches("(?i)(a|assignment[\\s_-]*)0*1[\\s_-]*page[\\s_-]*0*" + page);
    }

    /** The same for a scene: pageC.png for pageC.simp (letters of either case alike). */
    public static boolean isSceneName(String fileName, String scene) {
        return stem(fileName).strip().equalsIgnoreCase(scene);
    }

    /** The page number in a file name, if it names one. */
    public static OptionalInt pageNumber(String fileName) {
        Matcher m = PAGE.matcher(stem(fileName));
        if (!m.find()) {
            return OptionalInt.empty();
        }
        try {
            return OptionalInt.of(Integer.parseInt(m.group(1)));
        } catch (NumberFormatException e) {
            return OptionalInt.empty(); // more digits than any page number has
        }
    }

    /**
     * The scene a file name names: the longest scene name (case ignored) that
     * stands in it as a whole word, not inside a longer run of letters and digits.
     */
    public static Optional<String> sceneName(String fileName, Collection<String> sceneNames) {
        String stem = stem(fileName).toLowerCase(Locale.ROOT);
        String best = null;
        for (String scene : sceneNames) {
            if ((best == null || scene.length() > best.length()) && standsIn(stem, scene.toLowerCase(Locale.ROOT))) {
                best = scene;
            }
        }
        return Optional.ofNullable(best);
    }

    private static boolean standsIn(String stem, String word) {
        for (int at = stem.indexOf(word); at >= 0; at = stem.indexOf(word, at + 1)) {
            int end = at + word.length();
            boolean startOk = at == 0 || !Character.isLetterOrDigit(stem.charAt(at - 1));
            boolean endOk = end == stem.length() || !Character.isLetterOrDigit(stem.charAt(end));
            if (startOk && endOk) {
                return true;
            }
        }
        return false;
    }

    /** The file name without its extension. */
    public static String stem(String fileName) {
        int dot = fileName.lastIndexOf('.');
        return dot > 0 ? fileName.substring(0, dot) : fileName;
    }
}

package simpview.compare;

import java.text.Normalizer;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Which page or scene a submitted picture is of, from its file name:
 * page3.png, Page_3.png, alice-page03.png and page3_mesh.png are page 3;
 * pageC.png, pageC_v2.png and pageJ_tomsPageJ.png are the scenes pageC and
 * tomsPageJ, page-a2.png the scene page-a2. The word may be "página" or "pagina"
 * (Spanish, Portuguese, Italian and Dutch for page: página3.png is page 3), with
 * or without its accent; a number after anything else (p3.png, img3.png) names
 * no page, since "p" may as well be a part, a problem or a panel.
 */
public final class SubmissionNames {

    /** The word page ("pagina": página without its accent, as {@link #plain} leaves it), then its number. */
    private static final String PAGE_WORD = "(?:page|pagina)";
    /** A page "number" of zeros after the word: page0, page_00. */
    private static final Pattern ZERO_PAGE = Pattern.compile("(?i)(?<![a-z])" + PAGE_WORD + "[\\s_-]*0+(?![0-9])");
    private static final Pattern PAGE = Pattern.compile("(?i)(?<![a-z])" + PAGE_WORD + "[\\s_-]*0*([1-9][0-9]*)(?![0-9])");
    private static final Pattern NUMBER = Pattern.compile("[0-9]+");
    /** The counter a second copy of a file gets ("page1 (1).png", "Screenshot (3).png"): no page's number. */
    private static final Pattern COPY_COUNTER = Pattern.compile("\\(\\s*[0-9]+\\s*\\)");
    /**
     * The names screenshot tools and cameras save under ("Screenshot (3)", "Screen Shot 2024-03-05 at 1.02.03 PM",
     * "IMG_0003", "DSC_0003"): their numbers are a date, a time or a counter.
     */
    private static final Pattern SCREENSHOT = Pattern.compile("(?i)^\\s*(screen[\\s_-]*shot|capture|bildschirmfoto"
            + "|snapshot|untitled|(img|dsc|dscn|pxl)_[0-9])");
    /** A letter after the word page, as the lit scenes are named: pageC, page_C, page-c, pageJ. */
    private static final Pattern PAGE_LETTER = Pattern.compile("(?i)(?<![a-z])" + PAGE_WORD + "[\\s_-]*([a-z])(?![a-z])");

    /** The full-width forms of '!' to '~' (Ｐ, ａ, ８, ＿), U+FF01 to U+FF5E, and the full-width space. */
    private static final int FULL_WIDTH_FIRST = 0xFF01;
    private static final int FULL_WIDTH_LAST = 0xFF5E;
    private static final int IDEOGRAPHIC_SPACE = 0x3000;

    /** "a1", "A1", "assignment1", "assignment-1" as a word of its own: the first assignment's pages. */
    private static final Pattern FIRST_ASSIGNMENT = Pattern.compile("(?i)(?<![a-z0-9])(a|assignment[\\s_-]*)0*1(?![0-9])");

    private SubmissionNames() {
    }

    /** Whether a file name says it is one of the first assignment's pages, like a1-page2.png. */
    public static boolean namesFirstAssignment(String fileName) {
        return FIRST_ASSIGNMENT.matcher(plain(stem(fileName))).find();
    }

    /**
     * Whether a file name is a page's name and nothing else: page3.png, Page_3.png, page 03.jpg for page 3
     * (not page3 copy.png, page3_v2.png or old_page3.png). Of several pictures of one page, it is the one
     * that counts.
     */
    public static boolean isPageName(String fileName, int page) {
        return plain(stem(fileName)).strip().matches("(?i)" + PAGE_WORD + "[\\s_-]*0*" + page);
    }

    /** The same for a page of the first assignment: a1-page2.png, A1_Page_2.png, assignment1-page2.png. */
    public static boolean isFirstAssignmentPageName(String fileName, int page) {
        return plain(stem(fileName)).strip().matches("(?i)(a|assignment[\\s_-]*)0*1[\\s_-]*" + PAGE_WORD
                + "[\\s_-]*0*" + page);
    }

    /** The same for a scene: pageC.png for pageC.simp (letters of either case alike). */
    public static boolean isSceneName(String fileName, String scene) {
        return plain(stem(fileName)).strip().equalsIgnoreCase(plain(scene));
    }

    /** The page number in a file name, if it names one. */
    public static OptionalInt pageNumber(String fileName) {
        Matcher m = PAGE.matcher(plain(stem(fileName)));
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
     * Why a file name names no page, for a name {@link #pageNumber} finds none in: "no page number in the name
     * (expected a name like page3.png)", or, when it has a number that is not after the word page (p1.png,
     * scan_1.png), that it is not and the name it would have ("...: its number, 1, is not after the word "page"
     * (expected a name like page1.png)"); a copy's counter ("image (2).png") and a screenshot's or a camera's
     * name ("Screenshot (3).png", "IMG_0003.png") have no number that may be a page's, as for {@link #numberIn}.
     * {@code word}: the name's start it expects ("page", "a1-page"), and
     * {@code pages} how many pages there are: a number above them is no page's, and the example is page 3.
     */
    public static String noPageNumber(String fileName, String word, int pages) {
        String name = plain(stem(fileName));
        Matcher page = PAGE.matcher(name);
        String ending = fileName.equals(stem(fileName)) ? ".png" : fileName.substring(stem(fileName).length())
                .toLowerCase(Locale.ROOT);
        if (page.find()) { // more digits than any page number has
            return "no page number in the name: " + page.group(1) + " is no page's number (expected a name like " + word
                    + "3" + ending + ")";
        }
        Matcher zero = ZERO_PAGE.matcher(name);
        if (zero.find()) { // page0.png: pages count from 1
            return "no page number in the name: 0 is no page's number, pages count from 1 (expected a name like "
                    + word + "1" + ending + ")";
        }
        String expected = "(expected a name like " + word + "3" + ending + ")";
        if (SCREENSHOT.matcher(name).find()) { // its numbers are no page's, as numberIn says
            return "no page number in the name: it is named as a screenshot tool or a camera names its pictures, by "
                    + "a date, a time or a counter " + expected;
        }
        Optional<String> found = firstNumber(name);
        if (found.isEmpty()) {
            Matcher counter = COPY_COUNTER.matcher(name);
            return counter.find() ? "no page number in the name: " + counter.group().replaceAll("\\s", "")
                    + " is a copy's counter " + expected : "no page number in the name " + expected;
        }
        String number = found.get();
        boolean aPage = number.length() <= 2 && Integer.parseInt(number) >= 1 && Integer.parseInt(number) <= pages;
        return "no page number in the name: its number, " + number + ", is not after the word \"page\" (expected a "
                + "name like " + word + (aPage ? number : "3") + ending + ")";
    }

    /**
     * The number in a file name that names no page (pag3.png, p3.png, scan_03.png: 3; the "1" of a1 and assignment1
     * left out), when it is one or two digits: the page the name was likely meant for. Empty when it has none; a
     * copy's counter ("(1)") is none, and a screenshot's name ("Screenshot (3).png") has none.
     */
    public static OptionalInt numberIn(String fileName) {
        String name = plain(stem(fileName));
        if (SCREENSHOT.matcher(name).find()) {
            return OptionalInt.empty(); // its numbers are a date, a time or a counter, never the page's
        }
        Optional<String> number = firstNumber(name).filter(n -> n.length() <= 2);
        return number.isPresent() ? OptionalInt.of(Integer.parseInt(number.get())) : OptionalInt.empty();
    }

    /**
     * The first number of a name ({@code plainStem}: its stem, {@link #plain}), its leading zeros dropped: a copy's counter ("(2)") and
     * the "1" of a1 or assignment1 (which name the first assignment, not a page) left out. Empty when it has none.
     */
    private static Optional<String> firstNumber(String plainStem) {
        String counted = COPY_COUNTER.matcher(plainStem).replaceAll(" ");
        Matcher m = NUMBER.matcher(FIRST_ASSIGNMENT.matcher(counted).replaceAll(" "));
        return m.find() ? Optional.of(m.group().replaceFirst("^0+(?=[0-9])", "")) : Optional.empty();
    }

    /**
     * Whether a file name that names no scene is a slip of a scene's name: its name (case ignored) at most two
     * letters from the scene's, and less than half of it (pagC.png, pageCC.png, paegC.png for pageC).
     */
    public static boolean nearlyNames(String fileName, String scene) {
        String name = plain(stem(fileName)).strip().toLowerCase(Locale.ROOT);
        String wanted = plain(scene).toLowerCase(Locale.ROOT);
        int distance = editDistance(name, wanted);
        return distance > 0 && distance <= 2 && 2 * distance < wanted.length();
    }

    /**
     * The one scene of {@code scenes} a file name that names none was likely meant for, if there is one: the scene
     * its page letter names (page_C.png, page-c.png: pageC; pageJ.png: tomsPageJ, the one scene whose name ends in
     * pageJ), else the one scene nearest it that {@link #nearlyNames} (pagC.png, pageCC.png: pageC). Empty when
     * two are as near (pageK.png is a letter from each of pageA to pageI): a guess between them would as likely
     * be wrong.
     */
    public static Optional<String> nearestScene(String fileName, Collection<String> scenes) {
        Optional<String> lettered = pageLetter(fileName).flatMap(letter -> sceneOfLetter(letter, scenes));
        if (lettered.isPresent()) {
            return lettered;
        }
        String name = plain(stem(fileName)).strip().toLowerCase(Locale.ROOT);
        int nearest = Integer.MAX_VALUE;
        List<String> best = new ArrayList<>();
        for (String scene : scenes) {
            if (!nearlyNames(fileName, scene)) {
                continue;
            }
            int distance = editDistance(name, plain(scene).toLowerCase(Locale.ROOT));
            if (distance < nearest) {
                nearest = distance;
                best.clear();
            }
            if (distance == nearest) {
                best.add(scene);
            }
        }
        return best.size() == 1 ? Optional.of(best.get(0)) : Optional.empty();
    }

    /**
     * The one scene of {@code scenes} whose name ends in the word page and {@code letter} (pageC, tomsPageJ), case
     * ignored; empty when none or more than one does.
     */
    public static Optional<String> sceneOfLetter(char letter, Collection<String> scenes) {
        String ending = "page" + Character.toLowerCase(letter);
        List<String> found = scenes.stream().filter(s -> plain(s).toLowerCase(Locale.ROOT).endsWith(ending)).toList();
        return found.size() == 1 ? Optional.of(found.get(0)) : Optional.empty();
    }

    /** The letter after the word page in a file name (pageA.png: A), when it has one and no page number. */
    public static Optional<Character> pageLetter(String fileName) {
        Matcher letter = PAGE_LETTER.matcher(plain(stem(fileName)));
        return letter.find() ? Optional.of(Character.toUpperCase(letter.group(1).charAt(0))) : Optional.empty();
    }

    /** Letters to insert, delete, change or swap (two beside each other) to make one name the other. */
    private static int editDistance(String a, String b) {
        int[][] d = new int[a.length() + 1][b.length() + 1];
        for (int i = 0; i <= a.length(); i++) {
            for (int j = 0; j <= b.length(); j++) {
                if (i == 0 || j == 0) {
                    d[i][j] = i + j;
                    continue;
                }
                int change = a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1;
                d[i][j] = Math.min(Math.min(d[i - 1][j] + 1, d[i][j - 1] + 1), d[i - 1][j - 1] + change);
                if (i > 1 && j > 1 && a.charAt(i - 1) == b.charAt(j - 2) && a.charAt(i - 2) == b.charAt(j - 1)) {
                    d[i][j] = Math.min(d[i][j], d[i - 2][j - 2] + 1);
                }
            }
        }
        return d[a.length()][b.length()];
    }

    /**
     * A name without its letters' accents (página: pagina) and with its full-width letters, digits and spaces as
     * their plain forms (page８, as a Japanese or Chinese keyboard types the digit: page8), which the words and
     * numbers of page names are matched against. Only those: other look-alikes stay as they are, so page3².png is
     * page 3, not 32, and page1½.png page 1, not 11 (as NFKD would have them).
     */
    private static String plain(String name) {
        StringBuilder folded = new StringBuilder(name.length());
        name.codePoints().forEach(c -> folded.appendCodePoint(c >= FULL_WIDTH_FIRST && c <= FULL_WIDTH_LAST
                ? c - FULL_WIDTH_FIRST + '!' : c == IDEOGRAPHIC_SPACE ? ' ' : c));
        return Normalizer.normalize(folded, Normalizer.Form.NFD).replaceAll("\\p{M}", "");
    }

    /**
     * The scene a file name names: the longest scene name (case ignored) that
     * stands in it as a whole word, not inside a longer run of letters and digits.
     */
    public static Optional<String> sceneName(String fileName, Collection<String> sceneNames) {
        String stem = plain(stem(fileName)).toLowerCase(Locale.ROOT);
        String best = null;
        for (String scene : sceneNames) {
            if ((best == null || scene.length() > best.length())
                    && standsIn(stem, plain(scene).toLowerCase(Locale.ROOT))) {
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

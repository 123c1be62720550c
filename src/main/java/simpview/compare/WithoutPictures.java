package simpview.compare;

import java.util.List;
import java.util.Locale;

/**
 * A submission that holds no picture simpview reads (.png, .jpg, .gif, .bmp), and what it holds instead: a
 * student who handed in her pages zipped ({@code sybil/sybil_A2.zip}) lacks every page asked for, and is told
 * why. simpview does not open archives: the student, or the teacher, unzips them.
 *
 * @param submission a first-level folder of a class's folder ("sybil"), or "" for the whole folder
 * @param files what it holds, by their paths in the folder compared ("sybil/sybil_A2.zip"), hidden files left
 *     out; none when it is empty
 */
public record WithoutPictures(String submission, List<String> files) {

    /** The endings of archives, which a picture may be in but simpview does not open, in lower case. */
    public static final List<String> ARCHIVES = List.of(".zip", ".rar", ".7z", ".tar", ".tar.gz", ".tgz", ".tar.xz");
    /** How many of its files are named; the rest are counted. */
    private static final int NAMED = 3;

    /** Whether it is the one of {@code name}: a first-level folder, or (for "" or JUnit's "submission") the whole. */
    boolean isOf(String name) {
        return submission.equals(name) || submission.isEmpty() && name.equals(JUnitResults.TOP);
    }

    /**
     * Why a page is missing from it: "sybil holds no picture (.png, .jpg, .gif, .bmp), only sybil/sybil_A2.zip: unzip
     * it (simpview does not look inside a zip)"; "sybil holds no picture (...): it is empty".
     */
    public String note() {
        return (submission.isEmpty() ? "the folder" : submission) + " holds no picture (.png, .jpg, .gif, .bmp)"
                + (files.isEmpty() ? ": it is empty" : ", " + holds());
    }

    /** What it holds instead: "only sybil_A2.zip: unzip it (simpview does not look inside a zip)", or "it is empty". */
    public String instead() {
        return files.isEmpty() ? "it is empty" : "it holds " + holds();
    }

    private String holds() {
        List<String> archives = files.stream().filter(WithoutPictures::isArchive).toList();
        List<String> named = files.subList(0, Math.min(NAMED, files.size()));
        String listed = String.join(", ", named)
                + (files.size() > NAMED ? " and " + Count.of(files.size() - NAMED, "other file") : "");
        if (archives.isEmpty()) {
            return "only " + listed;
        }
        boolean zips = archives.stream().allMatch(f -> f.toLowerCase(Locale.ROOT).endsWith(".zip"));
        String them = archives.size() == 1 ? "it" : "them";
        return "only " + (files.size() == archives.size() ? listed : listed + " (the archives: "
                + String.join(", ", archives) + ")") + ": " + (zips ? "unzip " : "unpack ") + them
                + " (simpview does not look inside " + (zips ? "a zip" : "an archive") + ")";
    }

    private static boolean isArchive(String file) {
        String name = file.toLowerCase(Locale.ROOT);
        return ARCHIVES.stream().anyMatch(name::endsWith);
    }
}

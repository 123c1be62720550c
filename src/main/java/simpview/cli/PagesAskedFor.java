package simpview.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Function;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import java.util.stream.Stream;
import simpview.cli.CompareBatch.Match;
import simpview.compare.BatchRow;
import simpview.compare.JUnitResults;
import simpview.compare.Rubric;
import simpview.compare.SubmissionNames;
import simpview.compare.Wanted;
import simpview.compare.WithoutPictures;
import simpview.pages.Assignment1;
import simpview.pages.Assignment2;
import simpview.pages.PageContext;

/**
 * What a batch asks of each submission, and what one that lacks a page holds instead. Asked for are the pages and
 * scenes the batch was given, every one that some picture was matched to (of a class's, those that at least half of
 * its submissions handed in) and the first assignment's pages asked for or handed in; each is told of the files
 * named like it in a format simpview does not read, of the pictures skipped whose names may have been meant as it,
 * and of the archives beside them, for the MISSING rows of those who lack it.
 */
final class PagesAskedFor {

    private final PageContext context;
    private final Rubric rubric;
    private final FirstAssignmentGrading firstAssignment;
    private final HandedIn handedIn;
    /**
     * Whether the pages of the range are asked for only when something handed in is named like one of them
     * ({@code check} without --pages).
     */
    private final boolean pagesIfHandedIn;
    /**
     * The batch's pictures that are first-assignment pages where the eight pages were asked for by --pages, by their
     * paths under the folder.
     */
    private final Set<String> firstAssignmentUnasked;
    private final PrintWriter err;
    /** What its messages start with: the command that runs the batch ("simpview check: "). */
    private final String says;

    /**
     * What a batch drawn in {@code context} and judged by {@code rubric} asks; the pictures named as {@code handedIn}
     * names them; said on {@code err} after {@code says}.
     */
    PagesAskedFor(PageContext context, Rubric rubric, FirstAssignmentGrading firstAssignment, HandedIn handedIn,
            boolean pagesIfHandedIn, Set<String> firstAssignmentUnasked, PrintWriter err, String says) {
        this.context = context;
        this.rubric = rubric;
        this.firstAssignment = firstAssignment;
        this.handedIn = handedIn;
        this.pagesIfHandedIn = pagesIfHandedIn;
        this.firstAssignmentUnasked = firstAssignmentUnasked;
        this.err = err;
        this.says = says;
    }

    /**
     * What each submission of {@code dir} is asked for, one {@link Wanted} a page or scene, from what was
     * {@code found} there: its pictures, each compared as {@code matches} says and giving {@code rows}, and the files
     * beside them; of a class's folder unless {@code oneStudent}. {@code wanted}: the pages and scenes the batch was
     * given; {@code firstAssignmentWanted}: the first assignment's pages it asks for; {@code firstAssignmentDrawn}:
     * those some picture was compared with; {@code matcher}: what a file's path under {@code dir} names (a file
     * simpview does not read is told to the page it would be compared with).
     */
    List<Wanted> of(Path dir, HandedIn.Found found, List<Match> matches, List<BatchRow> rows, boolean oneStudent,
            List<CompareTarget> wanted, Set<Integer> firstAssignmentWanted, Set<Integer> firstAssignmentDrawn,
            Function<String, Match> matcher) {
        List<Path> pictures = found.pictures();
        FolderListing listing = found.listing();
        List<WithoutPictures> withoutPictures = found.withoutPictures();
        List<String> others = found.others();
        // A picture named like one of the eight pages that holds a first-assignment page was compared as that: it
        // names none of the eight pages.
        Set<String> firstAssignmentPictures = rows.stream().filter(firstAssignment::isOfAPage).map(BatchRow::file)
                .collect(Collectors.toSet());
        List<Match> matchedAsNamed = new ArrayList<>();
        for (int i = 0; i < pictures.size(); i++) {
            if (!firstAssignmentPictures.contains(handedIn.name(dir, pictures.get(i)))) {
                matchedAsNamed.add(matches.get(i));
            }
        }
        List<Match> unreadMatches = listing.unreadable().stream()
                .map(file -> matcher.apply(handedIn.name(dir, file))).toList();
        boolean firstAssignmentFolder = pagesIfHandedIn && firstAssignmentOnly(rows)
                && unreadMatches.stream().allMatch(m -> m.target() == null
                        || m.target().isPage() && m.target().page() <= Assignment1.COUNT);
        if (firstAssignmentFolder) {
            // as --assignment 1 checks it: page2.webp is named like the first assignment's page 2
            unreadMatches = listing.unreadable().stream()
                    .map(file -> FirstAssignmentGrading.match(HandedIn.fileName(handedIn.name(dir, file)), null, null))
                    .toList();
            err.println(says + "every picture in " + dir + " is a page of the first assignment, so its pages 1 to "
                    + Assignment1.COUNT + " are asked for, as --assignment 1 asks for them, and not the eight pages "
                    + "(--pages RANGE asks for those)");
        }
        Map<String, List<String>> unreadable = unreadableByLabel(dir, listing.unreadable(), unreadMatches);
        // Asked for: the given targets, and every one some picture was matched to (so a class's batch
        // shows who lacks a page that others handed in), of a class's batch those that at least half of its
        // submissions handed in: one student's picture of a scene the others were not set (cube.simp, which
        // the pages include) asks nothing of them.
        LinkedHashSet<CompareTarget> all = new LinkedHashSet<>(firstAssignmentFolder
                ? wanted.stream().filter(t -> !t.isPage()).toList()
                : askedFor(wanted, matchedAsNamed, unreadMatches));
        // one scene for every picture: each picture is a student's, wherever it is (never one student's folder)
        Map<CompareTarget, Set<String>> handedInBy = new HashMap<>();
        for (int i = 0; i < pictures.size(); i++) {
            CompareTarget target = matches.get(i).target();
            if (target != null) {
                handedInBy.computeIfAbsent(target, t -> new HashSet<>())
                        .add(JUnitResults.submission(handedIn.name(dir, pictures.get(i))));
            }
        }
        // the submissions: those with pictures, and a class's folders without (each is asked what the others are)
        long submissions = pictures.stream().map(p -> JUnitResults.submission(handedIn.name(dir, p)))
                .distinct().count() + withoutPictures.stream().filter(w -> !w.submission().isEmpty()).count();
        for (Match match : matchedAsNamed) {
            CompareTarget target = match.target();
            if (target != null && (oneStudent || 2L * handedInBy.get(target).size() >= submissions)) {
                all.add(target);
            }
        }
        Set<Integer> firstPages = new TreeSet<>(firstAssignmentWanted);
        if (firstAssignmentFolder) {
            IntStream.rangeClosed(1, Assignment1.COUNT).forEach(firstPages::add);
        }
        firstPages.addAll(firstAssignmentDrawn);
        Map<String, List<Wanted.Misnamed>> misnamed = misnamed(dir, pictures, matches, all, firstPages,
                oneStudent ? relative -> "" : JUnitResults::submission);
        // the archives a submission holds beside its pictures, never opened: a page it lacks may be in one (those of a
        // folder without pictures are said by its WithoutPictures; a zip elsewhere in a class's folder is no
        // submission's)
        Set<String> submissionsWithPictures = pictures.stream().map(p -> JUnitResults.submission(handedIn.name(dir, p)))
                .collect(Collectors.toSet());
        List<String> archives = others.stream().filter(FolderListing::isArchive)
                .filter(f -> oneStudent || submissionsWithPictures.contains(JUnitResults.submission(f))).toList();
        List<Wanted> asked = new ArrayList<>();
        for (CompareTarget target : all) {
            String label = target.label(context);
            asked.add(new Wanted(label, target.ruleIn(rubric), unreadable.getOrDefault(label, List.of()),
                    target.isPage() ? "page" + target.page() + ".png" : Wanted.PAGE_EXAMPLE, withoutPictures,
                    misnamed.getOrDefault(label, List.of()), archives));
        }
        for (int page : firstPages) {
            String label = firstAssignment.label(page);
            asked.add(new Wanted(label, firstAssignment.pageRule(page), unreadable.getOrDefault(label, List.of()),
                    "a1-page" + page + ".png", withoutPictures, misnamed.getOrDefault(label, List.of()), archives));
        }
        return asked;
    }

    /**
     * Whether the pictures compared (or broken) are all of the first assignment's pages, and there is one: the eight
     * pages asked for by --pages are then a teacher's slip for --assignment 1. Files skipped do not count either way.
     */
    boolean firstAssignmentOnly(List<BatchRow> rows) {
        List<BatchRow> compared = rows.stream().filter(r -> r.result() != BatchRow.Result.SKIPPED
                || firstAssignmentUnasked.contains(r.file())).toList();
        return !compared.isEmpty() && compared.stream()
                .allMatch(r -> firstAssignment.isOfAPage(r) || firstAssignmentUnasked.contains(r.file()));
    }

    /**
     * The targets asked for of those given: all of them; or, when the pages are asked for only if handed in,
     * the pages only when some picture compared as the page it names ({@code matches}), or a file in a format
     * simpview does not read, is named like one.
     */
    private List<CompareTarget> askedFor(List<CompareTarget> given, List<Match> matches, List<Match> unread) {
        boolean handedIn = Stream.concat(matches.stream(), unread.stream())
                .anyMatch(m -> m.target() != null && m.target().isPage());
        return pagesIfHandedIn && !handedIn ? given.stream().filter(t -> !t.isPage()).toList() : given;
    }

    /**
     * The files in a picture format simpview does not read (page6.tif, a1-page2.webp) by the label of the page or
     * scene their names name ({@code matches}, one a file, as a picture so named would be matched): a page missing
     * from their submission is told of them.
     */
    private Map<String, List<String>> unreadableByLabel(Path dir, List<Path> files, List<Match> matches) {
        Map<String, List<String>> named = new HashMap<>();
        for (int i = 0; i < files.size(); i++) {
            Match match = matches.get(i);
            String label = match.target() != null ? match.target().label(context)
                    : match.firstAssignmentPage() > 0 ? firstAssignment.label(match.firstAssignmentPage()) : null;
            if (label != null) {
                named.computeIfAbsent(label, t -> new ArrayList<>()).add(handedIn.name(dir, files.get(i)));
            }
        }
        return named;
    }

    /**
     * The pictures that were skipped but may have been meant as a page or scene asked for, by its label, each with
     * why: a name like no page with a number of a page asked for ("pag3.png is named like no page (its number, 3, is
     * not after the word "page"): did you mean page3.png?"), a name a slip from a scene's ("pagC.png is named like
     * no scene: did you mean pageC.png?"), and a name of a page there is not ("page9.png is named for page 9, and
     * there is no page 9 (the pages are 1 to 8): was it meant as page 3 or 5, which bob lacks?"), told once, on the
     * first page its submission lacks ({@code submissionOf} names a picture's submission). A MISSING row of the
     * submission tells of them.
     */
    private Map<String, List<Wanted.Misnamed>> misnamed(Path dir, List<Path> pictures, List<Match> matches,
            Set<CompareTarget> asked, Set<Integer> firstPages, Function<String, String> submissionOf) {
        Map<String, List<Wanted.Misnamed>> misnamed = new HashMap<>();
        List<CompareTarget> pages = asked.stream().filter(CompareTarget::isPage).toList();
        List<CompareTarget> scenes = asked.stream().filter(t -> !t.isPage()).toList();
        for (int i = 0; i < pictures.size(); i++) {
            Match match = matches.get(i);
            if (match.target() != null || match.firstAssignmentPage() > 0 || match.skipped() == null) {
                continue;
            }
            String relative = handedIn.name(dir, pictures.get(i));
            String name = HandedIn.fileName(relative);
            OptionalInt page = SubmissionNames.pageNumber(name);
            BiConsumerOfLabel add = (label, why) -> misnamed.computeIfAbsent(label, l -> new ArrayList<>())
                    .add(new Wanted.Misnamed(relative, relative + " " + why));
            String submission = submissionOf.apply(relative);
            Set<String> its = new HashSet<>(); // the pages and scenes its submission has a picture of
            for (int j = 0; j < pictures.size(); j++) {
                if (submissionOf.apply(handedIn.name(dir, pictures.get(j))).equals(submission)) {
                    its.add(matches.get(j).target() != null ? matches.get(j).target().label(context)
                            : matches.get(j).firstAssignmentPage() > 0
                                    ? firstAssignment.label(matches.get(j).firstAssignmentPage()) : "");
                }
            }
            String whose = submission.isEmpty() ? "the folder" : submission.equals(JUnitResults.TOP)
                    ? "the top of the folder" : submission;
            if (page.isPresent()) {
                // named for a page there is not: said once, on the first page its submission lacks, naming them all
                int number = page.getAsInt();
                if (firstAssignmentUnasked.contains(relative) && number <= Assignment1.COUNT) {
                    // a1-page2.png where the eight pages are graded: the wrong assignment's page, or page 2 misnamed
                    pages.stream().filter(t -> t.page() == number && !its.contains(t.label(context)))
                            .forEach(t -> add.to(t.label(context), "is named as the first assignment's page "
                                    + number + ", not graded here (--pages names the eight pages): if it is page "
                                    + number + " of the eight pages, name it page" + number + ".png"));
                }
                if (number > Assignment2.COUNT) {
                    List<CompareTarget> lacks = pages.stream().filter(t -> !its.contains(t.label(context)))
                            .sorted(Comparator.comparingInt(CompareTarget::page)).toList();
                    if (!lacks.isEmpty()) {
                        add.to(lacks.get(0).label(context), "is named for page " + number + ", and there is no "
                                + "page " + number + " (the pages are 1 to " + Assignment2.COUNT + "): was it meant as "
                                + UsageWords.joined(lacks.stream().map(t -> "page " + t.page()).toList(), "or")
                                + ", which " + whose + " lacks?");
                    }
                }
                if (number > Assignment1.COUNT
                        && (pages.isEmpty() || FirstAssignmentGrading.namesFirstAssignment(relative))) {
                    List<Integer> lacks = firstPages.stream()
                            .filter(p -> !its.contains(firstAssignment.label(p))).toList();
                    if (!lacks.isEmpty()) {
                        add.to(firstAssignment.label(lacks.get(0)), "is named for page " + number
                                + ", and the first assignment has pages 1 to " + Assignment1.COUNT + ": was it meant as "
                                + UsageWords.joined(lacks.stream().map(p -> "A1 page " + p).toList(), "or")
                                + ", which " + whose + " lacks?");
                    }
                }
                if (pages.isEmpty() && number <= 'Z' - 'A' + 1) {
                    // page1.png where the scenes are lettered (pageA to pageI): the scene of the number's letter
                    char letter = (char) ('A' + number - 1);
                    SubmissionNames.sceneOfLetter(letter, scenes.stream().map(CompareTarget::key).toList())
                            .flatMap(k -> scenes.stream().filter(t -> t.key().equals(k)).findFirst())
                            .ifPresent(t -> add.to(t.label(context), "is named for page " + number + ", and the "
                                    + "scenes here are lettered: did you mean " + t.key() + ".png (page " + letter
                                    + ")?"));
                }
                continue;
            }
            OptionalInt number = SubmissionNames.numberIn(name);
            Optional<String> nearest = SubmissionNames.nearestScene(name, scenes.stream().map(CompareTarget::key)
                    .toList());
            Optional<Character> letter = SubmissionNames.pageLetter(name);
            if (nearest.isEmpty() && number.isEmpty() && letter.isPresent() && letter.get() - 'A' + 1 <= Assignment2.COUNT) {
                // pageA.png where the pages are numbered: the page of the letter's number
                int lettered = letter.get() - 'A' + 1;
                pages.stream().filter(t -> t.page() == lettered).forEach(t -> add.to(t.label(context),
                        "is named for page " + letter.get() + ", and the pages are numbered 1 to " + Assignment2.COUNT
                                + ": did you mean page" + lettered + ".png?"));
            }
            String noPage = "is named like no page (its number, " + (number.isPresent() ? number.getAsInt() : 0)
                    + ", is not after the word \"page\"): did you mean ";
            if (number.isPresent()) {
                pages.stream().filter(t -> t.page() == number.getAsInt())
                        .forEach(t -> add.to(t.label(context), noPage + "page" + t.page() + ".png?"));
                if (firstPages.contains(number.getAsInt())
                        && (pages.isEmpty() || FirstAssignmentGrading.namesFirstAssignment(relative))) {
                    add.to(firstAssignment.label(number.getAsInt()),
                            noPage + "a1-page" + number.getAsInt() + ".png?");
                }
            }
            // the one scene it is nearest, never each scene two letters from it (pageJ.png is as near pageA as pageI)
            nearest.flatMap(k -> scenes.stream().filter(t -> t.key().equals(k)).findFirst())
                    .ifPresent(t -> add.to(t.label(context), "is named like no scene: did you mean " + t.key()
                            + ".png?"));
            if (number.isEmpty() && nearest.isEmpty() && letter.isEmpty()) {
                // no number, letter or scene in its name (Screenshot 2026-12-01 at 10.00.00.png, image.png): it may be
                // any page its submission lacks, told once, on the first of them, naming them all
                List<String[]> lacks = new ArrayList<>(); // label, words, file name
                if (!pages.isEmpty() || !scenes.isEmpty()) {
                    (pages.isEmpty() ? scenes : pages).stream()
                            .sorted(Comparator.<CompareTarget>comparingInt(CompareTarget::page)
                                    .thenComparing(CompareTarget::key))
                            .filter(t -> !its.contains(t.label(context)))
                            .forEach(t -> lacks.add(new String[] {t.label(context),
                                t.isPage() ? "page " + t.page() : t.key(), t.key() + ".png"}));
                } else {
                    firstPages.stream().filter(p -> !its.contains(firstAssignment.label(p))).forEach(p -> lacks.add(
                            new String[] {firstAssignment.label(p), "A1 page " + p, "a1-page" + p + ".png"}));
                }
                if (!lacks.isEmpty()) {
                    add.to(lacks.get(0)[0], "has no page number in its name: was it meant as "
                            + UsageWords.joined(lacks.stream().map(l -> l[1]).toList(), "or") + ", which " + whose
                            + " lacks? If so, name it " + (lacks.size() == 1 ? lacks.get(0)[2]
                                    : "for its page, like " + lacks.get(0)[2]));
                }
            }
        }
        return misnamed;
    }

    /** Adds a note to the label of a page or scene. */
    private interface BiConsumerOfLabel {
        void to(String label, String why);
    }
}

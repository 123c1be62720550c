package simpview.build;

import java.util.Set;
import java.util.regex.Pattern;

/**
 * One construct of a Gradle build script whose life is bounded: it came in
 * with {@code since} (null: already in Gradle 4.4) and went with
 * {@code removedIn} (null: still in 9.x).
 *
 * @param construct what the construct is, as the upgrade guides name it
 * @param pattern where it occurs, matched on the script with comments and string contents blanked
 * @param since the first Gradle that has it, or null
 * @param removedIn the first Gradle without it, or null
 * @param instead what to write instead
 * @param exemptInside blocks inside which a match does not count (convention
 *        properties stay valid inside their extension's block); "*" for any block
 */
record GradleRule(String construct, Pattern pattern, GradleVersionNumber since, GradleVersionNumber removedIn,
        String instead, Set<String> exemptInside) {

    private static final Set<String> NONE = Set.of();

    static GradleRule removed(String construct, String regex, String removedIn, String instead) {
        return new GradleRule(construct, Pattern.compile(regex, Pattern.MULTILINE), null,
                GradleVersionNumber.of(removedIn), instead, NONE);
    }

    static GradleRule convention(String construct, String regex, String instead) {
        return new GradleRule(construct, Pattern.compile(regex, Pattern.MULTILINE), null,
                GradleVersionNumber.of("9.0"), instead, Set.of("application", "java", "base"));
    }

    static GradleRule added(String construct, String regex, String since, String instead) {
        return new GradleRule(construct, Pattern.compile(regex, Pattern.MULTILINE), GradleVersionNumber.of(since),
                null, instead, NONE);
    }

    /** A block added later, counted only at the top level of the script. */
    static GradleRule addedBlock(String construct, String regex, String since, String instead) {
        return new GradleRule(construct, Pattern.compile(regex, Pattern.MULTILINE), GradleVersionNumber.of(since),
                null, instead, Set.of("*"));
    }

    /** Whether code that runs on every Gradle of the range may use the construct. */
    boolean allowedIn(GradleRange range) {
        boolean known = since == null || range.lowest().compareTo(since) >= 0;
        boolean kept = removedIn == null || range.belowOrUnbounded() != null
                && range.belowOrUnbounded().compareTo(removedIn) <= 0;
        return known && kept;
    }
}

package simpview.build;

/**
 * The Gradle versions a piece of the build script runs on: from
 * {@code lowest} up to, not including, {@code below} (null: no upper bound).
 */
record GradleRange(GradleVersionNumber lowest, GradleVersionNumber below) {

    /** Every Gradle the build supports: Debian's 4.4.1 and everything newer. */
    static final GradleRange SUPPORTED = new GradleRange(GradleVersionNumber.of("4.4.1"), null);

    GradleVersionNumber belowOrUnbounded() {
        return below;
    }

    /** The part of this range below version v: the then-branch of {@code if (gradleBelow('v'))}. */
    GradleRange under(GradleVersionNumber v) {
        return new GradleRange(lowest, below == null || v.compareTo(below) < 0 ? v : below);
    }

    /** The part of this range from version v on: its else-branch. */
    GradleRange from(GradleVersionNumber v) {
        return new GradleRange(v.compareTo(lowest) > 0 ? v : lowest, below);
    }

    @Override
    public String toString() {
        return "Gradle " + lowest + (below == null ? " and newer" : " to below " + below);
    }
}

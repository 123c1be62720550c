package simpview.compare;

/**
 * A connected patch of panel pixels that differ, as a rectangle in panel
 * coordinates as the course counts them: origin at the panel's bottom-left
 * pixel, x right, y up; bounds inclusive.
 */
public record DiffRegion(int left, int bottom, int right, int top, int pixels) {

    /** E.g. "x 120-180, y 300-342 (61x43): 1,234 pixels". */
    public String describe() {
        return String.format("x %d-%d, y %d-%d (%dx%d): %s",
                left, right, bottom, top, right - left + 1, top - bottom + 1, Count.of(pixels, "pixel"));
    }
}

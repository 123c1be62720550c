package simpview.pages;

/**
 * Where the user is among the window's pages, and how they move: first the
 * scenes named at start, if any (positions 1 to {@code scenes}), then the
 * eight pages (the positions after them). Wraps around. Without scenes a
 * position is a page number.
 */
public final class PageStepper {

    private final int scenes;
    private int current = 1;

    /** The eight pages only. */
    public PageStepper() {
        this(0);
    }

    /** {@code scenes} scene pages, then the eight pages. */
    public PageStepper(int scenes) {
        if (scenes < 0) {
            throw new IllegalArgumentException("scenes " + scenes);
        }
        this.scenes = scenes;
    }

    /** How many positions there are: the scenes and the eight pages. */
    public int count() {
        return scenes + Assignment2.COUNT;
    }

    /** The position showing, 1 to {@link #count()}. */
    public int current() {
        return current;
    }

    /** The scene at a position (0-based among the scenes), or -1 when the position is one of the eight pages. */
    public int sceneAt(int position) {
        return position <= scenes ? position - 1 : -1;
    }

    /** The page (1 to 8) at a position, or -1 when the position is a scene. */
    public int pageAt(int position) {
        return position > scenes ? position - scenes : -1;
    }

    public int next() {
        current = current % count() + 1;
        return current;
    }

    public int previous() {
        current = (current + count() - 2) % count() + 1;
        return current;
    }

    public int first() {
        current = 1;
        return current;
    }

    public int last() {
        current = count();
        return current;
    }

    /** Goes to page n (1 to 8) of the eight; anything else leaves the position as it is. */
    public int jump(int n) {
        if (n >= 1 && n <= Assignment2.COUNT) {
            current = scenes + n;
        }
        return current;
    }

    /** Goes to a position (1 to {@link #count()}); anything else leaves it as it is. */
    public int moveTo(int position) {
        if (position >= 1 && position <= count()) {
            current = position;
        }
        return current;
    }
}

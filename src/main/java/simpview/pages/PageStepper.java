package simpview.pages;

/** Which of the eight pages is showing, and how the user moves between them. Wraps around. */
public final class PageStepper {

    private int current = 1;

    /** The page showing, 1 to 8. */
    public int current() {
        return current;
    }

    public int next() {
        current = current % Pages.COUNT + 1;
        return current;
    }

    public int previous() {
        current = (current + Pages.COUNT - 2) % Pages.COUNT + 1;
        return current;
    }

    public int first() {
        current = 1;
        return current;
    }

    public int last() {
        current = Pages.COUNT;
        return current;
    }

    /** Goes to page n (1 to 8); anything else leaves the page as it is. */
    public int jump(int n) {
        if (n >= 1 && n <= Pages.COUNT) {
            current = n;
        }
        return current;
    }
}

package simpview.compare;

import java.util.Locale;

/** A count as the reports print it, with its noun: "1 picture", "1,234 pixels". */
public final class Count {

    private Count() {
    }

    /** n with thousands separated, then {@code one}, or {@code one + "s"} unless n is 1. */
    public static String of(long n, String one) {
        return of(n, one, one + "s");
    }

    /** The same for a noun whose plural is not one + "s": {@code of(3, "patch", "patches")}. */
    public static String of(long n, String one, String many) {
        return String.format(Locale.ROOT, "%,d %s", n, n == 1 ? one : many);
    }

    /** "1 pixel fails", "3 pixels fail": the count, its noun and a verb that agrees with it. */
    public static String with(long n, String noun, String verbOfOne, String verbOfMany) {
        return of(n, noun) + " " + (n == 1 ? verbOfOne : verbOfMany);
    }
}

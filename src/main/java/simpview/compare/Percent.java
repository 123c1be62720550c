package simpview.compare;

import java.util.Locale;

/** Shares as the reports print them: "99.87 %", never rounded up to 100 unless all pixels count. */
public final class Percent {

    private Percent() {
    }

    /** A share from 0 to 1 as a percentage with two decimals, rounded down. */
    public static String of(double share) {
        return number(share) + " %";
    }

    /** The same without the sign, for tables: "99.87". */
    public static String number(double share) {
        double hundredths = Math.floor(share * 10_000 + 1e-9);
        return String.format(Locale.ROOT, "%.2f", hundredths / 100);
    }
}

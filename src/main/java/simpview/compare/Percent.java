package simpview.compare;

import java.math.BigDecimal;
import java.util.Locale;

/** Shares as the reports print them: "99.87 %", never rounded up to 100 unless all pixels count. */
public final class Percent {

    private Percent() {
    }

    /** A share from 0 to 1 as a percentage with two decimals, rounded down. */
    public static String of(double share) {
        return number(share) + " %";
    }

    /**
     * Why a share in percent strictly between 0 and 1, as {@code written}, is refused: it is a fraction written
     * where a percentage goes (0.99 for 99 %, as --flip-threshold and most programs write a share), and as a
     * percentage it passes, or scores, nearly any picture: "0.99 is a fraction, not a share in percent (0 to
     * 100): for 99 %, write 99". Null for any other share, 0 and 1 among them.
     */
    public static String fractionInstead(double percent, String written) {
        if (!(percent > 0 && percent < 1)) {
            return null;
        }
        String meant = BigDecimal.valueOf(percent).movePointRight(2).stripTrailingZeros().toPlainString();
        return written + " is a fraction, not a share in percent (0 to 100): for " + meant + " %, write " + meant;
    }

    /** The same without the sign, for tables: "99.87". */
    public static String number(double share) {
        double hundredths = Math.floor(share * 10_000 + 1e-9);
        return String.format(Locale.ROOT, "%.2f", hundredths / 100);
    }
}
